// From points to cells and back, with the document's metrics in the note.
#include "planner/coverage/coverage_planner.h"

#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "geometry/polyline.h"

namespace plantsim::planner {

CoveragePlanner::CoveragePlanner(const PlannerInput& input, CoverageMethod method)
    : grid_(input.floor, input.coverage_cell_m, input.obstacles, input.inflation_m), method_(method) {}

std::string CoveragePlanner::name() const {
  switch (method_) {
    case CoverageMethod::kChnn: return "coverage";
    case CoverageMethod::kExact: return "coverage-exact";
    case CoverageMethod::kGreedy: return "coverage-greedy";
    case CoverageMethod::kCells: return "coverage-cells";
  }
  return "coverage";
}

bool is_coverage_planner(std::string_view n) {
  return n == "coverage" || n == "coverage-exact" || n == "coverage-greedy" || n == "coverage-cells";
}

CoverageMethod coverage_method(std::string_view n) {
  if (n == "coverage") return CoverageMethod::kChnn;
  if (n == "coverage-exact") return CoverageMethod::kExact;
  if (n == "coverage-greedy") return CoverageMethod::kGreedy;
  if (n == "coverage-cells") return CoverageMethod::kCells;
  throw std::invalid_argument("not a coverage planner: " + std::string(n));
}

PlanResult CoveragePlanner::plan(Vec2 start, Vec2 goal) {
  if (last_query_ && last_query_->first == start && last_query_->second == goal) return last_result_;
  const auto t0 = std::chrono::steady_clock::now();
  PlanResult r;
  const auto first = grid_.nearest_free(start), last = grid_.nearest_free(goal);
  if (!first || !last) {
    r.note = "no free coverage cell";
    return r;
  }
  if (method_ == CoverageMethod::kCells) {
    last_ = plan_cell_coverage(grid_, *first);
  } else {
    const RegionOrdering o = method_ == CoverageMethod::kChnn    ? RegionOrdering::kChnn
                             : method_ == CoverageMethod::kExact ? RegionOrdering::kExact
                                                                 : RegionOrdering::kGreedy;
    last_ = plan_region_coverage(grid_, *first, o);
  }
  std::vector<Cell> cells = last_.cells;
  const std::vector<Cell> home = grid_.travel(cells.back(), *last);
  if (home.empty()) {
    r.note = "the goal's cell cannot be reached from the covered area";
    return r;
  }
  cells.insert(cells.end(), home.begin() + 1, home.end());
  // Cell centres, keeping only where the heading changes.
  std::vector<Vec2> path{start};
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const bool straight = i > 0 && i + 1 < cells.size() &&
                          cells[i].column - cells[i - 1].column == cells[i + 1].column - cells[i].column &&
                          cells[i].row - cells[i - 1].row == cells[i + 1].row - cells[i].row;
    if (!straight) path.push_back(grid_.centre(cells[i]));
  }
  path.push_back(goal);
  r.status = PlanStatus::kOk;
  r.path = path;
  r.length = geom::polyline_length(path);
  const CoverageMetrics& m = last_.metrics;
  char note[400];
  std::snprintf(note, sizeof note,
                "%d regions; coverage %.2f %% of %d reachable cells, repetition %.2f %%, %d turns, %d dead ends, "
                "%.1f m of coverage path; order cost %.2f",
                static_cast<int>(last_.regions.size()), 100 * m.coverage, m.reachable_cells, 100 * m.repetition, m.turns,
                m.dead_ends, m.length_m, last_.order_cost);
  r.note = note;
  if (method_ != CoverageMethod::kCells) {
    if (last_.exact_cost) std::snprintf(note, sizeof note, " (exact %.2f, greedy %.2f)", *last_.exact_cost, last_.greedy_cost);
    else std::snprintf(note, sizeof note, " (too many regions for the exact order; greedy %.2f)", last_.greedy_cost);
    r.note += note;
  }
  r.stats.vertices = m.reachable_cells;
  r.stats.query_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  last_query_ = {start, goal};
  last_result_ = r;
  return r;
}

}  // namespace plantsim::planner
