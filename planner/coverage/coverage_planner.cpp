// From points to cells and back, with the document's metrics in the note.
#include "planner/coverage/coverage_planner.h"

#include <chrono>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "geometry/polyline.h"
#include "planner/coverage/cell_coverage.h"
#include "util/c_number.h"
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

namespace {

// Cell centres between the two points, keeping only where the heading changes.
std::vector<Vec2> cell_path(const CoverageGrid& grid, const std::vector<Cell>& cells, Vec2 start,
                            Vec2 goal) {
  std::vector<Vec2> path{start};
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const bool straight =
        i > 0 && i + 1 < cells.size() &&
        cells[i].column - cells[i - 1].column == cells[i + 1].column - cells[i].column &&
        cells[i].row - cells[i - 1].row == cells[i + 1].row - cells[i].row;
    if (!straight) path.push_back(grid.centre(cells[i]));
  }
  path.push_back(goal);
  return path;
}

// The document's metrics, the order's cost, and what the network or the exact search did.
std::string coverage_note(const CoveragePlan& plan, CoverageMethod method) {
  const CoverageMetrics& m = plan.metrics;
  char note[400];
  util::c_snprintf(
      note, sizeof note,
      "%d regions; coverage %.2f %% of %d reachable cells, repetition %.2f %%, %d turns, "
      "%d dead ends, "
      "%.1f m from start to end cell",
      static_cast<int>(plan.regions.size()), 100 * m.coverage, m.reachable_cells,
      100 * m.repetition, m.turns, m.dead_ends, m.length_m);
  std::string text = note;
  if (method != CoverageMethod::kCells) {
    util::c_snprintf(note, sizeof note, "; order cost %.2f (greedy %.2f)", plan.order_cost,
                     plan.greedy_cost);
    text += note;
  }
  if (method == CoverageMethod::kChnn || method == CoverageMethod::kPotts) {
    util::c_snprintf(note, sizeof note, "; settled on a permutation in %d of %d restarts",
                     plan.network_valid, plan.network_restarts);
    text += note;
  }
  if (plan.exact) {
    if (!plan.exact->searched)
      util::c_snprintf(note, sizeof note,
                       "; NOT searched: %d regions, the search handles at most 63 (greedy order)",
                       static_cast<int>(plan.regions.size()));
    else if (plan.exact->proven)
      util::c_snprintf(note, sizeof note, "; proven optimal in %.2f s (%llu prefixes)",
                       plan.exact->seconds, static_cast<unsigned long long>(plan.exact->prefixes));
    else
      util::c_snprintf(note, sizeof note,
                       "; NOT proven optimal: search stopped after %.1f s, lower bound %.2f",
                       plan.exact->seconds, plan.exact->lower_bound);
    text += note;
  }
  return text;
}

}  // namespace

// Covers from the start's cell to the goal's by the planner's method into last_; the reason when
// it cannot.
std::optional<std::string> CoveragePlanner::cover(const Cell& first, const Cell& last) {
  if (!grid_.reachable(first)[grid_.index(last)])
    return "the goal's cell cannot be reached from the covered area";
  if (method_ == CoverageMethod::kCells) {
    last_ = plan_cell_coverage(grid_, first, last, params_);
  } else {
    const RegionOrdering o = method_ == CoverageMethod::kChnn    ? RegionOrdering::kChnn
                             : method_ == CoverageMethod::kPotts ? RegionOrdering::kPotts
                             : method_ == CoverageMethod::kExact ? RegionOrdering::kExact
                                                                 : RegionOrdering::kGreedy;
    try {
      last_ = plan_region_coverage(grid_, first, last, o, params_);
    } catch (const std::invalid_argument& e) {  // too many sub-regions
      return e.what();
    }
  }
  if (!last_.ok) return last_.failure;
  return std::nullopt;
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
  if (const auto failure = cover(*first, *last)) {
    r.note = *failure;
    return r;
  }
  r.status = PlanStatus::kOk;
  r.path = cell_path(grid_, last_.cells, start, goal);
  r.length = geom::polyline_length(r.path);
  r.note = coverage_note(last_, method_);
  r.stats.vertices = last_.metrics.reachable_cells;
  r.stats.query_ms = util::ms_since(t0);
  last_query_ = {start, goal};
  last_result_ = r;
  return r;
}

}  // namespace plantsim::planner
