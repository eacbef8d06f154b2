// Pursuit along plans: travel as to a charger, but the path's end follows the target, planned
// again every period from where the beacon says it is; never docks.
#include "robot/travel.h"

namespace plantsim::robot {
namespace {

class PursuitTravel : public Travel {
 public:
  PursuitTravel(const worlds::World& map, std::string planner_name, const TravelSettings& s,
                std::vector<geom::Vec2> path)
      : map_(map),
        planner_(std::move(planner_name)),
        s_(s),
        control_(make_local_controller(s), s.docking, std::move(path), map.charger),
        next_plan_s_(s.pursuit_replan_period_s) {}

  Decision decide(const Perception& p) override {
    bool replanned = false;
    if (p.target && (p.t_s >= next_plan_s_ || control_.phase() != controller::DockPhase::kTravel)) {
      next_plan_s_ = p.t_s + s_.pursuit_replan_period_s;
      if (auto path = plan_around(map_, planner_, s_.docking, p.pose, *p.target, p.obstacles,
                                  s_.map_planner)) {
        if (control_.phase() == controller::DockPhase::kTravel)
          control_.replace_path(*path);
        else
          control_ = controller::DockingController(make_local_controller(s_), s_.docking, *path,
                                                   map_.charger);
        ++replans_;
        replanned = true;
      }
    }
    const controller::DockingCommand cmd = control_.step(docking_input(p));
    Decision d{cmd.twist,    cmd.phase,        cmd.cross_track_error_m,
               false,        TravelEnd::kNone, cmd.blocked,
               std::nullopt, cmd.events};
    d.events.replanned = replanned;
    if (cmd.phase != controller::DockPhase::kTravel)
      d.twist = {};  // at the path's end: wait for the next plan
    return d;
  }
  TravelCounts counts() const override {
    return {control_.retries(), control_.stops(), replans_, 0, 0};
  }

 private:
  const worlds::World& map_;
  std::string planner_;
  TravelSettings s_;
  controller::DockingController control_;
  double next_plan_s_;
  int replans_ = 0;
};

}  // namespace

std::unique_ptr<Travel> make_pursuit_travel(const worlds::World& map,
                                            const std::string& planner_name,
                                            const TravelSettings& s, std::vector<geom::Vec2> path) {
  return std::make_unique<PursuitTravel>(map, planner_name, s, std::move(path));
}

}  // namespace plantsim::robot
