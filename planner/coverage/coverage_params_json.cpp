// The table of coverage parameters, read and written by the shared reader (worlds/param_json.h).
#include "planner/coverage/coverage_params_json.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <vector>

#include "util/input_file.h"
#include "util/param_table.h"
#include "worlds/json_input.h"
#include "worlds/param_json.h"
#include "worlds/world_error.h"

namespace plantsim::planner {
namespace {

using Field = util::Param<CoverageParams>;

const std::vector<Field>& fields() {
  static const std::vector<Field> table = {
      PLANTSIM_PARAM("", cell_m, "cell_m", 0.2, 100.0),
      PLANTSIM_PARAM("", weights.cells, "w1_cells", 0.0, 1.0),
      PLANTSIM_PARAM("", weights.turns, "w2_turns", 0.0, 1.0),
      PLANTSIM_PARAM("", turn_k, "turn_k", 0.0, 100.0),
      PLANTSIM_PARAM("chnn", chnn.alpha, "alpha", 0.0, 1e6),
      PLANTSIM_PARAM("chnn", chnn.beta, "beta", 0.0, 1e6),
      PLANTSIM_PARAM("chnn", chnn.gamma, "gamma", 0.0, 1e6),
      PLANTSIM_PARAM("chnn", chnn.eta, "eta", 0.0, 1e6),
      PLANTSIM_PARAM("chnn", chnn.target_ratio, "target_ratio", 0.5, 3.0),
      PLANTSIM_PARAM("chnn", chnn.u0, "u0", 1e-6, 10.0),
      PLANTSIM_PARAM("chnn", chnn.tau, "tau", 1e-6, 1e6),
      PLANTSIM_PARAM("chnn", chnn.dt, "dt", 1e-9, 1e-2),
      PLANTSIM_PARAM("chnn", chnn.max_steps, "max_steps", 1, 1e7),
      PLANTSIM_PARAM("chnn", chnn.settle_change, "settle_change", 0.0, 1.0),
      PLANTSIM_PARAM("chnn", chnn.restarts, "restarts", 1, 10000),
      PLANTSIM_PARAM("chnn", chnn.init_noise, "init_noise", 0.0, 10.0),
      PLANTSIM_PARAM("chnn", chnn.seed, "seed", 0, 9e15),
      PLANTSIM_PARAM("potts", potts.a, "a", 0.0, 1e6),
      PLANTSIM_PARAM("potts", potts.d, "d", 0.0, 1e6),
      PLANTSIM_PARAM("potts", potts.t0, "t0", 1e-6, 1e6),
      PLANTSIM_PARAM("potts", potts.cooling, "cooling", 0.01, 0.999),
      PLANTSIM_PARAM("potts", potts.t_min, "t_min", 1e-9, 1e6),
      PLANTSIM_PARAM("potts", potts.sweeps, "sweeps", 1, 1000),
      PLANTSIM_PARAM("potts", potts.restarts, "restarts", 1, 10000),
      PLANTSIM_PARAM("potts", potts.seed, "seed", 0, 9e15),
      PLANTSIM_PARAM("exact", exact.max_prefixes, "max_prefixes", 0, 1e12),
      PLANTSIM_PARAM("exact", exact.time_limit_s, "time_limit_s", 0.0, 3600.0),
      PLANTSIM_PARAM("exact", exact.max_table_states, "max_table_states", 0, 1e8),
  };
  return table;
}

}  // namespace

CoverageParams parse_coverage_params(const std::string& text, const std::string& source) {
  const nlohmann::json j = worlds::parse_json_input(text, source);  // syntax, repeated keys
  worlds::ParamDocument doc(j, source);
  CoverageParams p;
  doc.read(fields(), p);
  doc.refuse_unknown();
  if (std::abs(p.weights.cells + p.weights.turns - 1.0) > 1e-9)
    throw worlds::WorldError(source, "w1_cells",
                             "w1_cells + w2_turns must be 1 (the document's weights sum to 1)");
  return p;
}

CoverageParams load_coverage_params(const std::string& path) {
  std::string text;
  try {
    text = util::read_input_file(path, 1u << 20);
  } catch (const util::InputFileError& e) {
    throw worlds::WorldError(path, "", e.what());
  }
  return parse_coverage_params(text, path);
}

std::string coverage_params_json(const CoverageParams& p) {
  nlohmann::ordered_json j;
  worlds::write_param_rows(j, fields(), p);
  return j.dump(2) + "\n";
}

}  // namespace plantsim::planner
