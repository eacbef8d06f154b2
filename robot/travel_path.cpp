// Path travel: the docking controller along the plan; a blocked way asks for a plan around
// what the robot senses.
#include "robot/travel.h"

namespace plantsim::robot {
namespace {

std::vector<geom::Vec2> coastal(const worlds::World& map, const TravelSettings& s,
                                const std::vector<geom::Vec2>& path,
                                const std::vector<geom::Rect>& blocked = {}) {
  return coastal_route(map, path, s.lidar_range_m, s.coastal, blocked);
}

class PathTravel : public Travel {
 public:
  /// `replaced`: the route when it is not the planner's path (the figures draw what it drives).
  PathTravel(const worlds::World& map, std::string planner_name, const TravelSettings& s,
             std::vector<geom::Vec2> path, std::vector<geom::Vec2> replaced)
      : map_(map),
        planner_(std::move(planner_name)),
        s_(s),
        control_(make_local_controller(s), s.docking, path, map.charger),
        search_(s.lost_search, s.docking.guard.footprint_radius_m),
        staging_(worlds::staging_pose(map).position()),
        plan_(std::move(replaced)) {}

  Decision decide(const Perception& p) override {
    controller::DockingCommand cmd = control_.step(docking_input(p));
    search_lost(p, cmd);
    if (cmd.recover_requested) need_plan_ = true;
    if (need_plan_ && p.t_s >= next_try_s_) {
      // After a displacement: a new way to the staging pose from wherever the robot now is.
      next_try_s_ = p.t_s + 1.0;
      if (auto path = plan_around(map_, planner_, s_.docking, p.pose, staging_, p.obstacles,
                                  s_.map_planner)) {
        plan_ = coastal(map_, s_, *path, sensed_blocks(map_, s_.docking, p.obstacles));
        control_.replace_path(plan_);
        need_plan_ = false;
      }
      if (need_plan_) {  // no way yet: wait
        Decision wait = decision_of({{}, cmd.phase, 0, true, false, false, cmd.events});
        wait.blocked = true;
        return wait;
      }
    }
    bool replanned = false;
    if (cmd.replan_requested) {
      // Plan again with what blocks the way as extra obstacles, from the nearest free point
      // if the robot stands inside their margin.
      if (auto path = plan_around(map_, planner_, s_.docking, p.pose, staging_, p.obstacles,
                                  s_.map_planner)) {
        plan_ = coastal(map_, s_, *path, sensed_blocks(map_, s_.docking, p.obstacles));
        control_.replace_path(plan_);
        ++replans_;
        replanned = true;
      }
    }
    Decision d = decision_of(cmd, control_.failure());
    d.events.replanned = replanned;
    return d;
  }
  TravelCounts counts() const override {
    return {control_.retries(), control_.stops(), replans_, 0, 0, control_.recoveries()};
  }
  std::optional<std::vector<geom::Vec2>> final_plan() const override {
    return plan_.empty() ? std::nullopt : std::optional(plan_);
  }

 private:
  /// Lost after a displacement, the docking controller turns on the spot; the search takes
  /// over its command (a full turn, then legs along what the robot sees). It turns only when
  /// the controller's own guard let it turn.
  void search_lost(const Perception& p, controller::DockingCommand& cmd) {
    if (!s_.lost_search.enabled || !control_.recovering() ||
        p.health != LocalizationHealth::kLost || !p.scan || p.bumper.pressed()) {
      search_.reset();
      return;
    }
    const controller::Twist t = search_.step(*p.scan, p.odom_pose);
    const bool turning_allowed = cmd.twist.omega_radps != 0;
    cmd.twist = t.v_mps > 0 || turning_allowed ? t : controller::Twist{};
  }

  const worlds::World& map_;
  std::string planner_;
  TravelSettings s_;
  controller::DockingController control_;
  LostSearch search_;
  geom::Vec2 staging_;
  std::vector<geom::Vec2> plan_;
  int replans_ = 0;
  bool need_plan_ = false;
  double next_try_s_ = 0;
};

}  // namespace

std::unique_ptr<Travel> make_path_travel(const worlds::World& map, const std::string& planner_name,
                                         const TravelSettings& s, std::vector<geom::Vec2> path) {
  std::vector<geom::Vec2> route = coastal(map, s, path);
  std::vector<geom::Vec2> replaced = route != path ? route : std::vector<geom::Vec2>{};
  return std::make_unique<PathTravel>(map, planner_name, s, std::move(route), std::move(replaced));
}

}  // namespace plantsim::robot
