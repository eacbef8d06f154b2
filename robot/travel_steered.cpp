// An outside controller in the loop; plantsim's travel decides the plan, the phase and the end.
#include "robot/travel_steered.h"

namespace plantsim::robot {
namespace {

class SteeredTravel : public Travel {
 public:
  SteeredTravel(std::unique_ptr<Travel> builtin, const worlds::World& map,
                std::vector<geom::Vec2> first_plan, Steering travel, Steering docking)
      : builtin_(std::move(builtin)),
        staging_(worlds::staging_pose(map)),
        first_plan_(std::move(first_plan)),
        travel_(std::move(travel)),
        docking_(std::move(docking)) {}

  Decision decide(const Perception& p) override {
    Decision d = builtin_->decide(p);
    if (d.finished != TravelEnd::kNone) return d;  // docked or failed: the referee has spoken
    const Steering& steer = d.phase == controller::DockPhase::kTravel ? travel_ : docking_;
    if (!steer) return d;
    const std::optional<std::vector<geom::Vec2>> replanned = builtin_->final_plan();
    if (const std::optional<controller::Twist> twist =
            steer({p, replanned ? *replanned : first_plan_, d.phase, d, staging_}))
      d.twist = *twist;
    return d;
  }
  TravelCounts counts() const override { return builtin_->counts(); }
  std::optional<std::vector<geom::Vec2>> final_plan() const override {
    return builtin_->final_plan();
  }

 private:
  std::unique_ptr<Travel> builtin_;
  geom::Pose2 staging_;
  std::vector<geom::Vec2> first_plan_;
  Steering travel_, docking_;
};

}  // namespace

std::unique_ptr<Travel> steered_by(std::unique_ptr<Travel> builtin, const worlds::World& map,
                                   std::vector<geom::Vec2> first_plan, Steering travel,
                                   Steering docking) {
  return std::make_unique<SteeredTravel>(std::move(builtin), map, std::move(first_plan),
                                         std::move(travel), std::move(docking));
}

}  // namespace plantsim::robot
