// The core planner (seed 000, improved): reduced visibility graph over inflated rectangles,
// searched with A* and the straight-line heuristic f = g + h. Start and goal are joined to
// the graph at query time; the graph and its lazily found edges persist across queries.
#pragma once

#include <chrono>
#include <memory>

#include "planner/astar.h"
#include "planner/obstacle_map.h"
#include "planner/planner.h"
#include "planner/vg/visibility_graph.h"

namespace plantsim::planner {

class VisibilityGraphPlanner : public Planner {
 public:
  explicit VisibilityGraphPlanner(const PlannerInput& input);
  std::string name() const override { return "vg"; }
  /// A planner for this one's world with obstacles `added` and the obstacles at the indices
  /// `removed` (into the input's obstacles) taken away: a parked cart that arrived or left. It
  /// takes over every vertex's edges that the change cannot reach, so the next query searches
  /// mostly a warm graph. Throws std::out_of_range for an index past the obstacles.
  std::unique_ptr<VisibilityGraphPlanner> with_changes(
      const std::vector<Rect>& added, const std::vector<std::size_t>& removed) const;
  const PlannerInput& input() const { return input_; }
  PlanResult plan(Vec2 start, Vec2 goal) override;
  std::vector<std::pair<Vec2, Vec2>> graph_edges() const override;  ///< the whole reduced graph
  /// The overlay of vg/vg_overlay.h: the map's graph kept, the added boxes' corners joined to it.
  std::optional<PlanResult> plan_around_added(const std::vector<Rect>& added_grown, Vec2 start,
                                              Vec2 goal) const override;
  const ObstacleMap& map() const { return map_; }
  const VisibilityGraph& graph() const { return graph_; }

 private:
  VisibilityGraphPlanner(const PlannerInput& input, const VisibilityGraphPlanner& base,
                         const std::vector<Rect>& changed);
  SearchResult lazy_astar(Vec2 start, Vec2 goal) const;

  std::chrono::steady_clock::time_point build_start_;  // first member: times the build
  PlannerInput input_;
  ObstacleMap map_;
  VisibilityGraph graph_;
  mutable std::vector<std::uint16_t> expansions_;  // how often each vertex was expanded (max 2)
  bool snap_ = false;
  double build_ms_ = 0;
};

/// The traditional visibility graph the document compares against: every corner of every
/// inflated rectangle, every visible pair tested up front, Dijkstra's search.
class TraditionalVisibilityPlanner : public Planner {
 public:
  explicit TraditionalVisibilityPlanner(const PlannerInput& input);
  std::string name() const override { return "vg-traditional"; }
  PlanResult plan(Vec2 start, Vec2 goal) override;
  std::vector<std::pair<Vec2, Vec2>> graph_edges() const override;  ///< every visible pair

 private:
  ObstacleMap map_;
  std::vector<Vec2> corners_;
  std::vector<std::vector<GraphEdge>> adjacency_;
  std::int64_t edges_ = 0;
  std::int64_t segment_tests_ = 0;
  bool snap_ = false;
  double build_ms_ = 0;
};

}  // namespace plantsim::planner
