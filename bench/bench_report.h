// One line of benchmark output: a JSON object with the measured value and, when there is
// one, the baseline measured in the same run and the ratio value / baseline_value, stamped with
// the build that measured it and when (issue 89: a number without its build compares nothing).
#pragma once

#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "util/build_stamp.h"

namespace plantsim::bench {

struct Measure {
  std::string case_name;
  double value;
  std::string unit;
};

inline void report(const std::string& bench, const Measure& m,
                   const std::optional<Measure>& baseline = {}) {
  nlohmann::ordered_json j;
  j["bench"] = bench;
  j["case"] = m.case_name;
  j["value"] = m.value;
  j["unit"] = m.unit;
  if (baseline) {
    j["baseline"] = baseline->case_name;
    j["baseline_value"] = baseline->value;
    j["ratio"] = baseline->value != 0 ? m.value / baseline->value : 0.0;
  } else {
    j["baseline"] = nullptr;
    j["baseline_value"] = nullptr;
    j["ratio"] = nullptr;
  }
  j["build"] = util::build_stamp().text();
  j["date"] = util::utc_now();
  std::cout << j.dump() << std::endl;
}

}  // namespace plantsim::bench
