// An output's stamp: the build that made it (util/build_stamp.h), when, in how long, and a hash
// of what it was made from (a config, a scenario), as one JSON object ("made_by" in every
// summary.json) and as one line of text (under every report's title).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "util/build_stamp.h"
#include "util/fixed_text.h"

namespace plantsim::util {

struct MadeBy {
  std::string date = utc_now();
  double duration_s = 0;  ///< wall-clock seconds the work took
  std::string input;      ///< what `input_hash` is of: "config", "scenario"
  std::string input_hash;

  nlohmann::ordered_json json() const {
    const BuildStamp& b = build_stamp();
    nlohmann::ordered_json j;
    j["plantsim"] = b.version, j["commit"] = b.commit, j["dirty"] = b.dirty, j["date"] = date;
    j["duration_s"] = std::round(duration_s * 1000) / 1000;
    if (!input.empty()) j[input] = input_hash;
    return j;
  }
  std::string text() const {
    return "Made by " + build_stamp().text() + " on " + date + " in " + fixed(duration_s, 1) +
           " s" + (input.empty() ? "" : "; " + input + " " + input_hash) + ".";
  }
};

}  // namespace plantsim::util
