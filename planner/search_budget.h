// The memory one query's search may hold before it stops with PlanStatus::kSearchLimit, and the
// message that says so. Exact planners on some maps need far more than the map: where many
// corners see each other across a long open area (rows of small obstacles along a corridor),
// the visibility graph has edges, and the interval searches nodes, quadratic in the corners. A
// query past the budget is refused clearly instead of exhausting the machine.
#pragma once

#include <cstddef>
#include <cstdio>
#include <string>

#include "util/c_number.h"

namespace plantsim::planner {

/// 2 GiB, the default (PlannerInput::search_budget_bytes): what the largest plants (200,000
/// rectangles) were allowed.
inline constexpr std::size_t kSearchMemoryBudgetBytes = std::size_t{2} << 30;

/// Why a search stopped: what it held, in what, for the plan's note.
inline std::string search_limit_note(const std::string& planner, std::size_t budget,
                                     std::size_t bytes, const std::string& what) {
  const auto mib = [](std::size_t b) {
    char text[32];
    util::c_snprintf(text, sizeof text, "%.1f MiB", static_cast<double>(b) / (1 << 20));
    return std::string(text);
  };
  return planner + ": the search passed its memory budget of " + mib(budget) + " (" + mib(bytes) +
         " in " + what +
         "): too many corners of this map see each other for an exact search; coarsen the map "
         "(merge small obstacles) or try another planner";
}

}  // namespace plantsim::planner
