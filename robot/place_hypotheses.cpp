// Places carried by odometry and ruled out by scans (see place_hypotheses.h).
#include "robot/place_hypotheses.h"

#include <algorithm>
#include <cmath>

namespace plantsim::robot {

void PlaceHypotheses::reset(const std::vector<geom::Pose2>& places) {
  places_.clear();
  for (const geom::Pose2& p : places) places_.push_back({p, 0, 0.0});
}

void PlaceHypotheses::move(const geom::Pose2& delta) {
  for (Place& p : places_) p.pose = geom::compose(p.pose, delta);
}

void PlaceHypotheses::check(const Judge& judge, int strikes, double margin) {
  double best = -INFINITY;
  for (Place& p : places_) {
    const Verdict v = judge(p.pose);
    p.strikes += v.contradicted;
    p.log_likelihood += v.log_likelihood;
    best = std::max(best, p.log_likelihood);
  }
  // Strikes are not forgiven by agreeing scans: a look-alike agrees wherever the two places
  // look alike, and is told apart only by the few views where they differ.
  places_.erase(std::remove_if(places_.begin(), places_.end(),
                               [&](const Place& p) {
                                 return p.strikes >= strikes || p.log_likelihood < best - margin;
                               }),
                places_.end());
}

bool PlaceHypotheses::holds(const geom::Pose2& estimate, double apart_m, double apart_rad) const {
  return nearest(estimate, apart_m, apart_rad).has_value();
}

std::optional<std::size_t> PlaceHypotheses::nearest_index(const geom::Pose2& estimate,
                                                          double apart_m, double apart_rad) const {
  std::optional<std::size_t> best;
  double best_m = apart_m;
  for (std::size_t i = 0; i < places_.size(); ++i) {
    const geom::Pose2& p = places_[i].pose;
    const double d = geom::distance(p.position(), estimate.position());
    if (d <= best_m && std::fabs(geom::wrap_angle(p.yaw - estimate.yaw)) <= apart_rad) {
      best_m = d;
      best = i;
    }
  }
  return best;
}

std::optional<geom::Pose2> PlaceHypotheses::nearest(const geom::Pose2& estimate, double apart_m,
                                                    double apart_rad) const {
  const std::optional<std::size_t> i = nearest_index(estimate, apart_m, apart_rad);
  return i ? std::optional(places_[*i].pose) : std::nullopt;
}

void PlaceHypotheses::move_nearest(const geom::Pose2& estimate, double apart_m, double apart_rad,
                                   const geom::Pose2& pose) {
  if (const std::optional<std::size_t> i = nearest_index(estimate, apart_m, apart_rad))
    places_[*i].pose = pose;
}

std::vector<geom::Pose2> PlaceHypotheses::rivals(const geom::Pose2& estimate, double apart_m,
                                                 double apart_rad) const {
  std::vector<geom::Pose2> out;
  for (const Place& p : places_)
    if (geom::distance(p.pose.position(), estimate.position()) > apart_m ||
        std::fabs(geom::wrap_angle(p.pose.yaw - estimate.yaw)) > apart_rad)
      out.push_back(p.pose);
  return out;
}

}  // namespace plantsim::robot
