// The Stanley law on the nearest leg of the plan (see the header).
#include "stanley_controller.h"

#include <algorithm>
#include <cmath>

namespace example {

using plantsim::controller::LocalController;
using plantsim::controller::LocalQuery;
using plantsim::controller::TrackingCommand;
using plantsim::geom::Pose2;
using plantsim::geom::Vec2;

namespace {

struct StanleyParams {
  double gain = 1.5;               ///< cross-track gain k
  double softening_mps = 0.2;      ///< keeps atan(k e / (v + this)) finite when slow
  double heading_rate_gain = 2.0;  ///< yaw rate per radian of steering
  double speed_mps = 0.45;         ///< cruise
  double max_yaw_rate_radps = 1.2;
  double rotate_threshold_rad = 0.6;  ///< turn in place beyond this heading error
  double slowdown_m = 0.8;            ///< slow down over this before the end
  double min_speed_mps = 0.05;
  double corner_switch_m = 0.05;  ///< onto the next leg this close to a vertex
  double goal_tolerance_m = 0.03;
};

double wrap(double a) { return std::atan2(std::sin(a), std::cos(a)); }

class Stanley : public LocalController {
 public:
  explicit Stanley(StanleyParams p) : p_(p) {}

  void set_path(std::vector<Vec2> path) override {
    path_ = std::move(path);
    leg_ = 0;
  }

  TrackingCommand step(const LocalQuery& q) override {
    TrackingCommand out;
    const Vec2 at = q.pose.position();
    if (path_.size() < 2) {
      out.goal_reached = true;
      return out;
    }
    advance(at);
    const Vec2 a = path_[leg_], b = path_[leg_ + 1];
    const Vec2 d = b - a;
    const double len = std::max(1e-9, std::hypot(d.x, d.y));
    const double along = std::clamp(((at.x - a.x) * d.x + (at.y - a.y) * d.y) / len, 0.0, len);
    const double cross = (d.x * (at.y - a.y) - d.y * (at.x - a.x)) / len;  // + left of the leg
    const double leg_yaw = std::atan2(d.y, d.x);
    const double heading_error = wrap(leg_yaw - q.pose.yaw);
    const double to_end = remaining(along, len);
    out.cross_track_error_m = std::fabs(cross);
    out.carrot_bearing_rad = heading_error;
    out.straight_ahead_m = len - along;
    if (leg_ + 2 == path_.size() && to_end <= p_.goal_tolerance_m) {
      out.goal_reached = true;
      return out;
    }
    if (std::fabs(heading_error) > p_.rotate_threshold_rad) {
      out.twist = {0.0, std::clamp(p_.heading_rate_gain * heading_error, -p_.max_yaw_rate_radps,
                                   p_.max_yaw_rate_radps)};
      return out;
    }
    const double speed =
        std::max(p_.min_speed_mps, p_.speed_mps * std::min(1.0, to_end / p_.slowdown_m));
    const double steer =
        heading_error + std::atan2(-p_.gain * cross, std::fabs(q.speed_mps) + p_.softening_mps);
    out.twist = {speed, std::clamp(p_.heading_rate_gain * steer, -p_.max_yaw_rate_radps,
                                   p_.max_yaw_rate_radps)};
    return out;
  }

 private:
  /// Onto the next leg once past the end of this one (or within corner_switch_m of it).
  void advance(Vec2 at) {
    while (leg_ + 2 < path_.size()) {
      const Vec2 b = path_[leg_ + 1];
      if (std::hypot(at.x - b.x, at.y - b.y) > p_.corner_switch_m) {
        const Vec2 d = b - path_[leg_];
        if ((at.x - b.x) * d.x + (at.y - b.y) * d.y < 0) break;  // not yet past its end
      }
      ++leg_;
    }
  }

  double remaining(double along, double len) const {
    double s = len - along;
    for (std::size_t i = leg_ + 1; i + 1 < path_.size(); ++i)
      s += std::hypot(path_[i + 1].x - path_[i].x, path_[i + 1].y - path_[i].y);
    return s;
  }

  StanleyParams p_;
  std::vector<Vec2> path_;
  std::size_t leg_ = 0;
};

}  // namespace

plantsim::controller::LocalControllerEntry stanley_entry() {
  using plantsim::util::ParamKind;
  const StanleyParams d;
  plantsim::controller::LocalControllerEntry e;
  e.name = "stanley";
  e.summary = "Stanley steering (heading error + atan of the cross-track error), an example plugin";
  e.params = {
      {"stanley", "gain", ParamKind::kReal, d.gain, 0.0, 20.0, false, "cross-track gain k"},
      {"stanley", "softening_mps", ParamKind::kReal, d.softening_mps, 0.0, 5.0, true,
       "speed added under the arctangent (m/s)"},
      {"stanley", "heading_rate_gain", ParamKind::kReal, d.heading_rate_gain, 0.0, 20.0, true,
       "yaw rate per radian of steering (1/s)"},
      {"stanley", "speed_mps", ParamKind::kReal, d.speed_mps, 0.0, 2.0, true, "cruise (m/s)"},
      {"stanley", "max_yaw_rate_radps", ParamKind::kReal, d.max_yaw_rate_radps, 0.0, 5.0, true,
       "yaw-rate limit (rad/s)"},
      {"stanley", "rotate_threshold_rad", ParamKind::kReal, d.rotate_threshold_rad, 0.0, 3.2, true,
       "turn in place beyond this heading error (rad)"},
      {"stanley", "goal_tolerance_m", ParamKind::kReal, d.goal_tolerance_m, 0.0, 1.0, true,
       "the plan's end reached within this (m)"},
  };
  e.make = [](const plantsim::controller::LocalControllerContext&,
              const plantsim::util::ParamValues& v) -> std::unique_ptr<LocalController> {
    StanleyParams p;
    p.gain = v.real("stanley.gain");
    p.softening_mps = v.real("stanley.softening_mps");
    p.heading_rate_gain = v.real("stanley.heading_rate_gain");
    p.speed_mps = v.real("stanley.speed_mps");
    p.max_yaw_rate_radps = v.real("stanley.max_yaw_rate_radps");
    p.rotate_threshold_rad = v.real("stanley.rotate_threshold_rad");
    p.goal_tolerance_m = v.real("stanley.goal_tolerance_m");
    return std::make_unique<Stanley>(p);
  };
  return e;
}

}  // namespace example
