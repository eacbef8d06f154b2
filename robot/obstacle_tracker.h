// Obstacles the map does not know, from the scan: the returns perception found unexplained
// (shorter than the map predicts) are clustered by gaps between neighbouring beams, and each
// cluster is associated with a track by nearest predicted centre; a track keeps its position
// and velocity with an alpha-beta filter and is forgotten when unseen for a while. What the
// arc check, the stops and the replans use.
#pragma once

#include <span>
#include <vector>

#include "controller/collision_check.h"
#include "geometry/vec2.h"

namespace plantsim::robot {

struct TrackerParams {
  double unexplained_margin_m =
      0.15;                    ///< a return this much shorter than the map predicts is not the map
  double range_m = 8.0;        ///< returns beyond this are not tracked
  double cluster_gap_m = 0.3;  ///< neighbouring returns closer than this are one object
  double association_gate_m = 0.8;  ///< a cluster this close to a track's prediction updates it
  double alpha = 0.6;               ///< position gain of the alpha-beta filter
  double beta = 0.2;                ///< velocity gain
  double max_speed_mps = 3.0;       ///< velocities are clamped here
  double still_speed_mps = 0.1;     ///< slower tracks are reported standing (face-centroid jitter)
  double forget_after_s = 1.0;      ///< unseen this long: dropped (kept and predicted until then)
  double min_size_m = 0.2;          ///< boxes are grown to at least this across
  double assumed_depth_m =
      0.5;  ///< ... and this far behind the face seen (the lidar sees one face of a thing)
};

struct Track {
  int id;
  geom::Vec2 position;  ///< centre of the seen part, map frame
  geom::Vec2 velocity;
  geom::Vec2 half_extent;  ///< of the box reported
  double last_seen_s;
  int hits;
};

class ObstacleTracker {
 public:
  explicit ObstacleTracker(TrackerParams params) : p_(params) {}
  /// One scan's unexplained returns, in beam order (map frame), seen from `sensor` at time t.
  void update(const std::vector<geom::Vec2>& unexplained, geom::Vec2 sensor, double t_s);
  /// Tracks as boxes with velocities, moved on to time t.
  std::vector<controller::MovingBox> boxes(double t_s) const;
  const std::vector<Track>& tracks() const { return tracks_; }
  const TrackerParams& params() const { return p_; }

 private:
  TrackerParams p_;
  std::vector<Track> tracks_;
  int next_id_ = 0;
  double last_t_s_ = 0;
};

/// Splits points in beam order into clusters wherever neighbours are more than `gap_m` apart:
/// each cluster a run of `points` (valid while they are).
std::vector<std::span<const geom::Vec2>> cluster_in_order(const std::vector<geom::Vec2>& points,
                                                          double gap_m);

}  // namespace plantsim::robot
