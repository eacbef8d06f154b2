// Seed 001's potential field with wall following, fed what perception senses; at the staging
// area the docking manoeuvre takes over (to a moving target it never docks).
#include "robot/travel.h"

namespace plantsim::robot {
namespace {

class FieldTravel : public Travel {
 public:
  FieldTravel(const worlds::World& map, std::string planner_name, const TravelSettings& s,
              bool pursuit, double robot_radius_m)
      : map_(map),
        planner_(std::move(planner_name)),
        s_(s),
        pursuit_(pursuit),
        field_(std::in_place, s.field, robot_radius_m),
        staging_(worlds::staging_pose(map)) {}

  Decision decide(const Perception& p) override {
    if (docking_) return docking_->decide(p);
    const geom::Vec2 velocity = p.speed_mps * p.pose.heading();
    const geom::Vec2 goal = pursuit_ && p.target ? *p.target : staging_.position();
    const geom::Vec2 goal_velocity = pursuit_ && p.target ? p.target_velocity : geom::Vec2{0, 0};
    const controller::FieldCommand fc =
        field_->step({p.pose, velocity, goal, goal_velocity, p.dt_s, p.field});
    minima_ = field_->local_minima();
    follows_ = field_->wall_follow_episodes();
    Decision d;
    d.wall_following = fc.state == controller::FieldState::kWallFollowing;
    if (fc.trapped) {
      d.finished = TravelEnd::kTrapped;
      d.give_up = GiveUp{FailureReason::kTrapped,
                         "the potential field met " + std::to_string(minima_) + " local minima"};
      return d;
    }
    if (fc.arrived && !pursuit_) {
      // At the staging area: the docking manoeuvre takes over from here.
      docking_ = make_path_travel(map_, planner_, s_, {p.pose.position(), staging_.position()});
      return docking_->decide(p);
    }
    d.twist = fc.twist;
    return d;
  }
  TravelCounts counts() const override {
    TravelCounts c = docking_ ? docking_->counts() : TravelCounts{};
    c.local_minima = minima_;  // recoveries: the docking's
    c.wall_follows = follows_;
    return c;
  }

 private:
  const worlds::World& map_;
  std::string planner_;
  TravelSettings s_;
  bool pursuit_;
  std::optional<controller::PotentialFieldController> field_;
  geom::Pose2 staging_;
  std::unique_ptr<Travel> docking_;
  int minima_ = 0, follows_ = 0;
};

}  // namespace

std::unique_ptr<Travel> make_field_travel(const worlds::World& map, const std::string& planner_name,
                                          const TravelSettings& s, bool pursuit,
                                          double robot_radius_m) {
  return std::make_unique<FieldTravel>(map, planner_name, s, pursuit, robot_radius_m);
}

}  // namespace plantsim::robot
