// The exact planner's fast query layer (`interval`): the same shortest paths as `vg` (free
// space, inflation, pinch and slit rules alike), found by interval search over a mesh of the
// free floor instead of A* over the visibility graph. Preprocessing is one sweep (the mesh);
// a query touches only the cells it sweeps, so there is no graph to grow and no per-query
// scan for the start's visible corners. Why both exist: `vg` is the source document's method
// and draws its graph; `interval` answers the same question faster on large maps (docs/seeds.md).
// The mesh is cut along x or along y, whichever gives fewer cells (fewer cells, fewer nodes).
// With `landmarks` in its input, the search also takes the landmarks' (ALT) lower bound.
// `polyanya` is the same planner over convex polygons instead (mesh/convex_mesh.h): a path
// crosses fewer cells, each costs more to expand (docs/seeds.md has the measurements).
#pragma once

#include <chrono>
#include <cstddef>
#include <memory>

#include "planner/mesh/free_space_mesh.h"
#include "planner/mesh/interval_search.h"
#include "planner/mesh/polygon_search.h"
#include "planner/obstacle_map.h"
#include "planner/planner.h"

namespace plantsim::planner {

/// Landmarks times mesh cells: past it a request for landmarks is refused (one landmark over
/// a 50,000-rectangle plant (150,000 cells) is a search of most of a second and 8 MB of table).
inline constexpr std::size_t kLandmarkCellBudget = 2'000'000;

enum class MeshKind { kRectangles, kConvexPolygons };

/// The mesh family's options (interval, polyanya): `landmarks`, 0 to 64, for the ALT heuristic.
std::vector<OptionSpec> mesh_planner_options();

class IntervalPlanner : public Planner {
 public:
  explicit IntervalPlanner(const PlannerInput& input, MeshKind kind = MeshKind::kRectangles);
  std::string name() const override { return convex_ ? "polyanya" : "interval"; }
  PlanResult plan(Vec2 start, Vec2 goal) override;
  /// The mesh's portals: where paths may pass from one free cell (or polygon) to the next.
  std::vector<std::pair<Vec2, Vec2>> graph_edges() const override;
  const FreeSpaceMesh& mesh() const { return *mesh_; }

 private:
  void check_landmark_budget(int landmarks, std::size_t cells) const;

  std::chrono::steady_clock::time_point build_start_;  // first member: times the whole build
  ObstacleMap map_;
  std::unique_ptr<FreeSpaceMesh> mesh_;
  std::unique_ptr<IntervalSearch> search_;
  std::unique_ptr<ConvexMesh> convex_;  // polyanya: the rectangles' floor as convex polygons
  std::unique_ptr<PolygonSearch> polygon_search_;
  bool transposed_ = false;  // the mesh is of the world with x and y swapped
  bool snap_ = false;
  std::size_t budget_bytes_;
  double build_ms_ = 0;
};

}  // namespace plantsim::planner
