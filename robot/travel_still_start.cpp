// A travel that first holds still: the robot calibrates its gyro at rest before it sets off.
#include "robot/travel.h"

namespace plantsim::robot {
namespace {

class StillStart : public Travel {
 public:
  StillStart(std::unique_ptr<Travel> travel, double still_s)
      : travel_(std::move(travel)), still_s_(still_s) {}
  Decision decide(const Perception& p) override {
    if (p.t_s < still_s_) return {};  // zero twist, travelling phase
    return travel_->decide(p);
  }
  TravelCounts counts() const override { return travel_->counts(); }
  std::optional<std::vector<geom::Vec2>> final_plan() const override {
    return travel_->final_plan();
  }

 private:
  std::unique_ptr<Travel> travel_;
  double still_s_;
};

}  // namespace

std::unique_ptr<Travel> hold_still_first(std::unique_ptr<Travel> travel, double still_s) {
  if (!(still_s > 0)) return travel;
  return std::make_unique<StillStart>(std::move(travel), still_s);
}

}  // namespace plantsim::robot
