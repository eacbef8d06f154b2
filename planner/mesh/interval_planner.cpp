// The interval planner: the obstacle map for the query's ends, the mesh for the search.
#include "planner/mesh/interval_planner.h"

#include <chrono>
#include <stdexcept>
#include <string>

#include "geometry/polyline.h"
#include "planner/free_point.h"
#include "planner/inflation.h"
#include "util/stopwatch.h"

namespace plantsim::planner {
namespace {

Vec2 swapped(Vec2 p) { return {p.y, p.x}; }
Rect swapped(const Rect& r) { return {r.ymin, r.xmin, r.ymax, r.xmax}; }

}  // namespace

// Each landmark costs one search over the whole mesh at build, and 8 bytes per cell corner (per
// vertex): worth it when the planner answers many queries (bench: ArcticStation). On a huge
// plant that is minutes and gigabytes, so the product is bounded and a request past it refused
// before any search starts.
void IntervalPlanner::check_landmark_budget(int landmarks, std::size_t cells) const {
  if (landmarks > 0 && static_cast<std::size_t>(landmarks) * cells > kLandmarkCellBudget)
    throw std::invalid_argument(name() + ": " + std::to_string(landmarks) +
                                " landmarks over a mesh of " + std::to_string(cells) +
                                " cells: each landmark is a search of the whole mesh at build, and "
                                "landmarks x cells may not pass " +
                                std::to_string(kLandmarkCellBudget) + " (at most " +
                                std::to_string(kLandmarkCellBudget / cells) + " here)");
}

std::vector<OptionSpec> mesh_planner_options() {
  return {{"landmarks", 0, 0, 64, true, "landmarks of the ALT heuristic, 0 for none"}};
}

IntervalPlanner::IntervalPlanner(const PlannerInput& input, MeshKind kind)
    : build_start_(std::chrono::steady_clock::now()),
      map_(inflate(input.obstacles, input.inflation_m, input.corner_steps), input.floor,
           input.inflation_m),
      snap_(input.snap_to_free),
      budget_bytes_(input.search_budget_bytes) {
  const std::vector<OptionSpec> options = mesh_planner_options();
  check_options(kind == MeshKind::kConvexPolygons ? "polyanya" : "interval", input.options,
                options);
  const int landmarks = input.options.get_int(options[0]);
  mesh_ = std::make_unique<FreeSpaceMesh>(map_.rects(), map_.free_floor());
  if (kind == MeshKind::kConvexPolygons) {
    // Both sweeps have the same walls, so the polygons do not depend on which one is cut.
    convex_ = std::make_unique<ConvexMesh>(*mesh_);
    polygon_search_ = std::make_unique<PolygonSearch>(*convex_);
    polygon_search_->set_memory_budget(budget_bytes_);
    check_landmark_budget(landmarks, static_cast<std::size_t>(convex_->polygon_count()));
    polygon_search_->add_landmarks(landmarks);
    build_ms_ = util::ms_since(build_start_);
    return;
  }
  std::vector<Rect> rects;
  rects.reserve(map_.rects().size());
  for (const Rect& r : map_.rects()) rects.push_back(swapped(r));
  auto across = std::make_unique<FreeSpaceMesh>(rects, swapped(map_.free_floor()));
  if (across->cells().size() < mesh_->cells().size()) {
    mesh_ = std::move(across);
    transposed_ = true;
  }
  search_ = std::make_unique<IntervalSearch>(*mesh_);
  search_->set_memory_budget(budget_bytes_);
  check_landmark_budget(landmarks, mesh_->cells().size());
  search_->add_landmarks(landmarks);
  build_ms_ = util::ms_since(build_start_);
}

PlanResult IntervalPlanner::plan(Vec2 start, Vec2 goal) {
  const auto t0 = std::chrono::steady_clock::now();
  PlanResult out;
  if (usable_endpoints(map_, snap_, start, goal, out)) {
    const Vec2 from = transposed_ ? swapped(start) : start, to = transposed_ ? swapped(goal) : goal;
    const IntervalPath found = convex_ ? polygon_search_->find(from, to) : search_->find(from, to);
    out.status = found.found                   ? PlanStatus::kOk
                 : found.over_budget_bytes > 0 ? PlanStatus::kSearchLimit
                                               : PlanStatus::kNoPath;
    if (found.over_budget_bytes > 0)
      out.note = search_limit_note(name(), budget_bytes_, found.over_budget_bytes,
                                   "intervals and their queue");
    out.path = found.path;
    if (transposed_)
      for (Vec2& p : out.path) p = swapped(p);
    out.length = geom::polyline_length(out.path);
    out.stats.expanded = found.expanded;
  }
  out.stats.build_ms = build_ms_;
  out.stats.query_ms = util::ms_since(t0);
  out.stats.vertices =
      convex_ ? convex_->polygon_count() : static_cast<std::int64_t>(mesh_->cells().size());
  out.stats.edges =
      convex_ ? convex_->portal_count() : static_cast<std::int64_t>(mesh_->portals().size());
  return out;
}

std::vector<std::pair<Vec2, Vec2>> IntervalPlanner::graph_edges() const {
  std::vector<std::pair<Vec2, Vec2>> out;
  const auto add = [&](Vec2 a, Vec2 b) {
    out.push_back(transposed_ ? std::make_pair(swapped(a), swapped(b)) : std::make_pair(a, b));
  };
  if (convex_) {
    for (std::int32_t p = 0; p < convex_->polygon_count(); ++p)
      for (std::int32_t k = 0; k < convex_->size(p); ++k)
        if (convex_->neighbour(p, k) > p)  // each shared edge once
          add(convex_->points()[convex_->vertex(p, k)],
              convex_->points()[convex_->vertex(p, k + 1)]);
    return out;
  }
  out.reserve(mesh_->portals().size());
  for (const MeshPortal& p : mesh_->portals()) add({p.x, p.y0}, {p.x, p.y1});
  return out;
}

}  // namespace plantsim::planner
