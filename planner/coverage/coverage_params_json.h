// Seed 004's coverage parameters from JSON (`plantsim coverage --params FILE`): one table of
// every parameter with its range, read and written by the same entries, so that the defaults
// file (configs/coverage_params.json) and the code cannot drift apart. Unknown keys, values out
// of range and non-numbers are errors naming the file and the field.
#pragma once

#include <string>

#include "planner/coverage/coverage_params.h"

namespace plantsim::planner {

CoverageParams load_coverage_params(const std::string& path);
CoverageParams parse_coverage_params(const std::string& text, const std::string& source);
std::string coverage_params_json(const CoverageParams& params = {});

}  // namespace plantsim::planner
