// Clustering, association and the alpha-beta filter.
#include "robot/obstacle_tracker.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace plantsim::robot {

std::vector<std::span<const geom::Vec2>> cluster_in_order(const std::vector<geom::Vec2>& points,
                                                          double gap_m) {
  std::vector<std::span<const geom::Vec2>> out;
  std::size_t first = 0;
  for (std::size_t k = 1; k <= points.size(); ++k)
    if (k == points.size() || geom::distance(points[k - 1], points[k]) > gap_m) {
      out.emplace_back(points.data() + first, k - first);
      first = k;
    }
  // A 270-degree scan does not wrap; a full circle would join its ends here.
  return out;
}

void ObstacleTracker::update(const std::vector<geom::Vec2>& unexplained, geom::Vec2 sensor,
                             double t_s) {
  const double dt = std::max(t_s - last_t_s_, 0.0);
  last_t_s_ = t_s;
  for (Track& tr : tracks_) tr.position = tr.position + dt * tr.velocity;

  struct Cluster {
    geom::Vec2 center, half;
  };
  std::vector<Cluster> clusters;
  for (const auto& c : cluster_in_order(unexplained, p_.cluster_gap_m)) {
    geom::Rect b{c[0].x, c[0].y, c[0].x, c[0].y};
    for (const geom::Vec2& q : c)
      b = {std::min(b.xmin, q.x), std::min(b.ymin, q.y), std::max(b.xmax, q.x),
           std::max(b.ymax, q.y)};
    // The thing goes on behind the face the lidar sees: grow the box away from the sensor.
    const geom::Vec2 away = b.center() - sensor;
    const double len = geom::norm(away);
    if (len > 0) {
      const geom::Vec2 back = (p_.assumed_depth_m / len) * away;
      b = {std::min(b.xmin, b.xmin + back.x), std::min(b.ymin, b.ymin + back.y),
           std::max(b.xmax, b.xmax + back.x), std::max(b.ymax, b.ymax + back.y)};
    }
    const double h = 0.5 * p_.min_size_m;
    clusters.push_back({b.center(), {std::max(0.5 * b.width(), h), std::max(0.5 * b.height(), h)}});
  }
  // Greedy nearest pairs first: one cluster per track, one track per cluster.
  std::vector<bool> cluster_used(clusters.size(), false), track_used(tracks_.size(), false);
  while (true) {
    double best = p_.association_gate_m;
    std::size_t bi = 0, bj = 0;
    bool found = false;
    for (std::size_t i = 0; i < clusters.size(); ++i) {
      if (cluster_used[i]) continue;
      for (std::size_t j = 0; j < tracks_.size(); ++j) {
        if (track_used[j]) continue;
        const double d = geom::distance(clusters[i].center, tracks_[j].position);
        if (d < best) best = d, bi = i, bj = j, found = true;
      }
    }
    if (!found) break;
    cluster_used[bi] = track_used[bj] = true;
    Track& tr = tracks_[bj];
    const geom::Vec2 innovation = clusters[bi].center - tr.position;
    tr.position = tr.position + p_.alpha * innovation;
    if (dt > 0) tr.velocity = tr.velocity + (p_.beta / dt) * innovation;
    const double speed = geom::norm(tr.velocity);
    if (speed > p_.max_speed_mps) tr.velocity = (p_.max_speed_mps / speed) * tr.velocity;
    tr.half_extent = clusters[bi].half;
    tr.last_seen_s = t_s;
    ++tr.hits;
  }
  for (std::size_t i = 0; i < clusters.size(); ++i)
    if (!cluster_used[i])
      tracks_.push_back({next_id_++, clusters[i].center, {0, 0}, clusters[i].half, t_s, 1});
  std::erase_if(tracks_, [&](const Track& tr) { return t_s - tr.last_seen_s > p_.forget_after_s; });
}

std::vector<controller::MovingBox> ObstacleTracker::boxes(double t_s) const {
  std::vector<controller::MovingBox> out;
  for (const Track& tr : tracks_) {
    // A new track has no velocity yet; jitter of a standing one's seen face is not motion.
    const bool moving = tr.hits >= 3 && geom::norm(tr.velocity) >= p_.still_speed_mps;
    const geom::Vec2 v = moving ? tr.velocity : geom::Vec2{0, 0};
    const geom::Vec2 c = tr.position + std::max(t_s - last_t_s_, 0.0) * v;
    out.push_back({{c.x - tr.half_extent.x, c.y - tr.half_extent.y, c.x + tr.half_extent.x,
                    c.y + tr.half_extent.y},
                   v});
  }
  return out;
}

}  // namespace plantsim::robot
