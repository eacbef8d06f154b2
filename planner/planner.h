// The one interface every path planner of plantsim offers: built once for a set of
// obstacles, then asked for paths between points. Results carry a status instead of
// throwing, so a batch can record "no path" as an outcome.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "geometry/vec2.h"
#include "planner/planner_options.h"
#include "planner/search_budget.h"
#include "worlds/world.h"

namespace plantsim::planner {

using geom::Rect;
using geom::Vec2;

/// kSearchLimit: the search outgrew its memory budget (planner/search_budget.h); the note says why.
enum class PlanStatus { kOk, kNoPath, kStartBlocked, kGoalBlocked, kSearchLimit };
std::string_view to_string(PlanStatus s);

struct PlanStats {
  double build_ms = 0;             ///< time to build the planner's structures (graph, grid)
  double query_ms = 0;             ///< time of this query
  std::int64_t vertices = 0;       ///< graph vertices (or free grid cells)
  std::int64_t edges = 0;          ///< edges found so far (lazy graphs) or in total
  std::int64_t expanded = 0;       ///< search nodes expanded by this query
  std::int64_t segment_tests = 0;  ///< exact visibility tests so far
};

/// A label a method puts on the map (seed 003: the letters recorded at a junction, where each
/// walk of the ring search ended).
struct PlanMark {
  enum class Kind { kExplorationLetters, kRouteLetters, kTriedEnd };
  Vec2 at;
  std::string text;
  Kind kind = Kind::kExplorationLetters;
};

/// What a method did on its way to the answer, for figures only (nothing drives on it).
struct PlanTrace {
  std::vector<Vec2> explored;  ///< a walk the method made before its answer (seed 003's
                               ///< exploration, seed 002's raw walk)
  std::string explored_label = "explored";  ///< what figures call it
  std::vector<std::vector<Vec2>>
      tried;                    ///< walks it tried and dropped or kept (seed 003's ring search)
  std::vector<PlanMark> marks;  ///< labels for figures (seed 003's junction letters)
};

struct PlanResult {
  PlanStatus status = PlanStatus::kNoPath;
  std::vector<Vec2> path;  ///< start .. goal, empty unless status is kOk
  std::vector<Vec2>
      drive_path;     ///< what a controller should follow when not `path` itself
                      ///< (vg-round: arcs replaced by their tangents' corners); empty: `path`
  double length = 0;  ///< metres, sum of segment lengths
  PlanStats stats;
  bool start_snapped = false;  ///< the path starts at the nearest free point, not at the start
  bool goal_snapped = false;   ///< the path ends at the nearest free point, not at the goal
  std::string note;            ///< why a baseline failed (trapped, oscillating...) or what it met
  PlanTrace trace;             ///< for figures
};

/// What a planner is built from: the map (raw obstacles, the floor, a maze world's tunnel
/// lattice), how to grow it for the robot, and the options of the chosen family by name.
struct PlannerInput {
  Rect floor;
  std::vector<Rect> obstacles;  ///< raw (not yet inflated)
  double inflation_m = 0.3;     ///< applied to obstacles and walls
  int corner_steps = 1;         ///< 1: square corners (the document); more: tighter staircase
  bool snap_to_free = false;    ///< move a blocked start or goal to the nearest free point
  /// A searching planner (vg, interval, polyanya): a query whose search holds more stops
  /// (kSearchLimit); the others search within their own bounds.
  std::size_t search_budget_bytes = kSearchMemoryBudgetBytes;
  std::optional<worlds::TunnelMaze> maze;  ///< map data: the tunnel lattice of a maze world
  PlannerOptions options;                  ///< the family's own (registry: planner_option_specs)
};

/// The world's obstacles, optionally with the charger body as one more obstacle.
PlannerInput planner_input(const worlds::World& world, bool include_charger_body);

class Planner {
 public:
  virtual ~Planner() = default;
  virtual std::string name() const = 0;
  virtual PlanResult plan(Vec2 start, Vec2 goal) = 0;
  /// The graph the planner has built so far, as segments, for figures (may be empty).
  virtual std::vector<std::pair<Vec2, Vec2>> graph_edges() const { return {}; }
  /// A query with boxes `added_grown` (grown as this planner grows its own) present for this
  /// query only, answered on what the planner has already built; nothing when its family cannot
  /// (the caller then builds a planner with them). The visibility graph can (vg/vg_overlay.h).
  virtual std::optional<PlanResult> plan_around_added(const std::vector<Rect>& added_grown,
                                                      Vec2 start, Vec2 goal) const {
    (void)added_grown, (void)start, (void)goal;
    return std::nullopt;
  }
};

}  // namespace plantsim::planner
