// From points to cells and back, with the document's metrics in the note.
#include "planner/coverage/coverage_planner.h"

#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "geometry/polyline.h"
#include "planner/coverage/cell_coverage.h"
#include "util/stopwatch.h"

namespace plantsim::planner {

CoveragePlanner::CoveragePlanner(const PlannerInput& input, std::string_view name,
                                 const CoverageParams& params)
    : grid_(input.floor, params.cell_m, input.obstacles, input.inflation_m),
      name_(name),
      method_(coverage_method(name)),
      params_(params) {}

bool is_coverage_planner(std::string_view n) {
  return n == "coverage" || n == "coverage-chnn" || n == "coverage-potts" ||
         n == "coverage-exact" || n == "coverage-greedy" || n == "coverage-cells";
}

CoverageMethod coverage_method(std::string_view n) {
  if (n == "coverage" || n == "coverage-chnn") return CoverageMethod::kChnn;
  if (n == "coverage-potts") return CoverageMethod::kPotts;
  if (n == "coverage-exact") return CoverageMethod::kExact;
  if (n == "coverage-greedy") return CoverageMethod::kGreedy;
  if (n == "coverage-cells") return CoverageMethod::kCells;
  throw std::invalid_argument("not a coverage planner: " + std::string(n));
}

PlanResult CoveragePlanner::plan(Vec2 start, Vec2 goal) {
  if (last_query_ && last_query_->first == start && last_query_->second == goal)
    return last_result_;
  const auto t0 = std::chrono::steady_clock::now();
  PlanResult r;
  const auto first = grid_.nearest_free(start), last = grid_.nearest_free(goal);
  if (!first || !last) {
    r.note = "no free coverage cell";
    return r;
  }
  if (!grid_.reachable(*first)[grid_.index(*last)]) {
    r.note = "the goal's cell cannot be reached from the covered area";
    return r;
  }
  if (method_ == CoverageMethod::kCells) {
    last_ = plan_cell_coverage(grid_, *first, *last, params_);
  } else {
    const RegionOrdering o = method_ == CoverageMethod::kChnn    ? RegionOrdering::kChnn
                             : method_ == CoverageMethod::kPotts ? RegionOrdering::kPotts
                             : method_ == CoverageMethod::kExact ? RegionOrdering::kExact
                                                                 : RegionOrdering::kGreedy;
    try {
      last_ = plan_region_coverage(grid_, *first, *last, o, params_);
    } catch (const std::invalid_argument& e) {  // too many sub-regions
      r.note = e.what();
      return r;
    }
  }
  if (!last_.ok) {
    r.note = last_.failure;
    return r;
  }
  const std::vector<Cell>& cells = last_.cells;
  // Cell centres, keeping only where the heading changes.
  std::vector<Vec2> path{start};
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const bool straight =
        i > 0 && i + 1 < cells.size() &&
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
                "%d regions; coverage %.2f %% of %d reachable cells, repetition %.2f %%, %d turns, "
                "%d dead ends, "
                "%.1f m from start to end cell",
                static_cast<int>(last_.regions.size()), 100 * m.coverage, m.reachable_cells,
                100 * m.repetition, m.turns, m.dead_ends, m.length_m);
  r.note = note;
  if (method_ != CoverageMethod::kCells) {
    std::snprintf(note, sizeof note, "; order cost %.2f (greedy %.2f)", last_.order_cost,
                  last_.greedy_cost);
    r.note += note;
  }
  if (method_ == CoverageMethod::kChnn || method_ == CoverageMethod::kPotts) {
    std::snprintf(note, sizeof note, "; settled on a permutation in %d of %d restarts",
                  last_.network_valid, last_.network_restarts);
    r.note += note;
  }
  if (last_.exact) {
    if (!last_.exact->searched)
      std::snprintf(note, sizeof note,
                    "; NOT searched: %d regions, the search handles at most 63 (greedy order)",
                    static_cast<int>(last_.regions.size()));
    else if (last_.exact->proven)
      std::snprintf(note, sizeof note, "; proven optimal in %.2f s (%llu prefixes)",
                    last_.exact->seconds, static_cast<unsigned long long>(last_.exact->prefixes));
    else
      std::snprintf(note, sizeof note,
                    "; NOT proven optimal: search stopped after %.1f s, lower bound %.2f",
                    last_.exact->seconds, last_.exact->lower_bound);
    r.note += note;
  }
  r.stats.vertices = m.reachable_cells;
  r.stats.query_ms = util::ms_since(t0);
  last_query_ = {start, goal};
  last_result_ = r;
  return r;
}

}  // namespace plantsim::planner
