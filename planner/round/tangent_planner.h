// The disk robot's true optimum (`--inflation round`, planner `vg-round`): obstacles grown by the
// clearance with rounded corners (the Minkowski sum with a disk), so a shortest path is made of
// straight segments tangent to circles of that radius around the obstacles' corners and arcs
// along those circles (a tangent visibility graph). The graph is searched lazily with A* and
// the straight-line heuristic: a state is a circle, the sense it is wrapped in and the tangent
// it arrived by; its tangents to every other circle and to the goal are pushed untested, and
// an arc and a segment are checked for clearance only when popped. Lengths are exact up to the
// clearance tolerance; `path` samples each arc every 2 degrees and `length` is the exact length
// of segments and arcs. A controller cannot follow an arc as tight as the clearance without
// cutting into it (pure pursuit starts turning a lookahead early), so `drive_path` replaces each
// arc by the corner where its tangents meet (split in two or more where a neighbour is near):
// the robot turns there in place, as at a square corner, never inside the clearance. No planner of
// the source documents or the anchors offers this; its square- and staircase-inflated counterparts
// are `vg` with
// --corner-steps 1 and more.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "planner/obstacle_map.h"
#include "planner/planner.h"

namespace plantsim::planner {

class RoundTangentPlanner : public Planner {
 public:
  /// Throws std::invalid_argument past kMaxObstacles (the search is quadratic in corners).
  explicit RoundTangentPlanner(const PlannerInput& input);
  std::string name() const override { return "vg-round"; }
  PlanResult plan(Vec2 start, Vec2 goal) override;

  static constexpr std::size_t kMaxObstacles = 2000;

  /// Clearance questions against the raw obstacles and the walls (exposed for tests).
  bool point_clear(Vec2 p) const;
  bool segment_clear(Vec2 p, Vec2 q) const;
  /// The arc of corner circle `circle` from angle `from`, counter-clockwise through `sweep`.
  bool arc_clear(std::int32_t circle, double from, double sweep) const;
  /// Appends the corners the controller turns at for the arc of circle c from angle `from`
  /// in `sense` through `sweep`, entered at `arr` and left at `dep`.
  void append_drive_corners(Vec2 c, double from, int sense, double sweep, Vec2 arr, Vec2 dep,
                            std::vector<Vec2>& out) const;
  const std::vector<Vec2>& circles() const { return circles_; }
  double radius() const { return radius_; }

 private:
  class Search;            // one query's search (tangent_planner.cpp)
  std::vector<Rect> raw_;  // obstacles as given, not inflated
  Rect free_floor_;        // the floor shrunk by the clearance (walls are flat)
  double radius_;
  std::vector<Vec2> circles_;  // distinct corners of the obstacles that are not inside one
  std::vector<unsigned>
      allowed_;  // per circle, the quadrants a tangent may touch it in (bit q: [q, q + 1] pi/2)
  std::optional<ObstacleMap> square_;  // the square inflation, for snapping a blocked end (a subset
                                       // of free space); built only when snapping is on
  double build_ms_ = 0;
  std::int64_t segment_tests_ = 0;  // tangents (with the arc before them) checked, all queries
  std::int64_t tangents_kept_ = 0;  // of those, clear
};

}  // namespace plantsim::planner
