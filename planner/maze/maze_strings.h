// Seed 003 (cable-tunnel inspection robot): the turn string a hand-rule exploration records at
// junctions (L left, R right, S straight, U turn back) and its simplification into the route
// without dead ends. Left-hand rule: "SUL" and "LUS" become "R", "LUL" becomes "S"; right-hand
// rule, the mirror: "SUR" and "RUS" become "L", "RUR" becomes "S". As the document specifies,
// the first (leftmost) occurrence of any pattern is replaced and the search starts again from
// the first letter, until no pattern is left.
#pragma once

#include <string>
#include <string_view>

namespace plantsim::planner {

enum class Hand { kLeft, kRight };

/// Throws std::invalid_argument for letters other than L, R, S, U.
std::string simplify_turns(std::string_view turns, Hand hand);

}  // namespace plantsim::planner
