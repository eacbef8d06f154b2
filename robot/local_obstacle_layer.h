// The robot's memory of what its map lacks: scan returns the map does not explain mark the
// cells of a sparse grid in the map frame, and a cell is cleared when later scans see through
// it (a beam that reaches past it). Static things the map lacks (a pallet, a parked cart)
// stay remembered when the lidar no longer sees them, where the tracks forget them after a
// second; things that move on are cleared as soon as the robot sees the floor they stood on.
// The occupied cells, merged into rectangles, join the arc check and the replanning.
#pragma once

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "geometry/vec2.h"
#include "robot/readings.h"

namespace plantsim::robot {

struct ObstacleLayerParams {
  bool enabled = true;
  double cell_m = 0.1;        ///< grid cell side
  int mark_evidence = 2;      ///< evidence a return adds to its cell (once per scan)
  int clear_evidence = 1;     ///< evidence a beam reaching past the cell removes
  int occupied_evidence = 3;  ///< a cell counts from this much evidence (two scans agreeing)
  int max_evidence = 6;       ///< cap: a cell seen free in this many scans is gone
  double clear_range_m =
      8.0;  ///< cells farther from the sensor are not cleared (a beam is wider there)
};

class LocalObstacleLayer {
 public:
  explicit LocalObstacleLayer(ObstacleLayerParams params) : p_(params) {}
  /// One scan: `marks` are the returns to remember (map frame), `sensor` the pose the scan was
  /// placed with; every beam of `scan` that reaches past a remembered cell clears it a little.
  void update(const LidarScan& scan, const geom::Pose2& sensor,
              const std::vector<geom::Vec2>& marks);
  /// The occupied cells merged into rectangles (runs along x, stacked along y), map frame; each
  /// is the bounding box of the returns that marked its cells (not the whole cells, which would
  /// grow every obstacle by up to a cell).
  std::vector<geom::Rect> occupied() const;
  /// Number of cells holding any evidence.
  std::size_t cells() const { return evidence_.size(); }
  const ObstacleLayerParams& params() const { return p_; }

 private:
  using Key = std::int64_t;
  Key key(geom::Vec2 p) const;
  geom::Vec2 centre(Key k) const;

  ObstacleLayerParams p_;
  struct Cell {
    int evidence = 0;
    geom::Rect marks{INFINITY, INFINITY, -INFINITY, -INFINITY};  // bounding box of its returns
  };
  std::unordered_map<Key, Cell> evidence_;
};

}  // namespace plantsim::robot
