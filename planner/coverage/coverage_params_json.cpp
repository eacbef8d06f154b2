// The table of coverage parameters.
#include "planner/coverage/coverage_params_json.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <nlohmann/json.hpp>
#include <vector>

#include "util/input_file.h"
#include "util/param_table.h"
#include "worlds/json_input.h"
#include "worlds/known_keys.h"
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
  if (!j.is_object()) throw worlds::WorldError(source, "", "expected a JSON object");
  CoverageParams p;
  std::vector<std::string> top{"comment"}, sections;
  for (const Field& f : fields()) {
    if (std::string(f.section).empty())
      top.push_back(f.name);
    else if (std::find(top.begin(), top.end(), f.section) == top.end())
      top.push_back(f.section), sections.push_back(f.section);
  }
  for (const auto& [key, value] : j.items()) {
    if (std::find(top.begin(), top.end(), key) == top.end())
      throw worlds::WorldError(source, key, worlds::unknown_key_problem(key, top));
    if (std::find(sections.begin(), sections.end(), key) == sections.end()) continue;
    if (!value.is_object()) throw worlds::WorldError(source, key, "expected an object");
    std::vector<std::string> known;
    for (const Field& f : fields())
      if (key == f.section) known.push_back(f.name);
    for (const auto& [name, v] : value.items())
      if (std::find(known.begin(), known.end(), name) == known.end())
        throw worlds::WorldError(source, key + "." + name,
                                 worlds::unknown_key_problem(name, known));
  }
  for (const Field& f : fields()) {
    const std::string section = f.section;
    const nlohmann::json* v = nullptr;
    if (section.empty()) {
      if (j.contains(f.name)) v = &j[f.name];
    } else if (j.contains(section) && j[section].contains(f.name)) {
      v = &j[section][f.name];
    }
    if (!v) continue;
    const std::string field = section.empty() ? f.name : section + "." + f.name;
    if (!v->is_number()) throw worlds::WorldError(source, field, "expected a number");
    const double x = v->get<double>();
    if (!std::isfinite(x) || x < f.lo || x > f.hi)
      throw worlds::WorldError(
          source, field,
          "must be between " + nlohmann::json(f.lo).dump() + " and " + nlohmann::json(f.hi).dump());
    if (f.kind == util::ParamKind::kWhole && x != std::floor(x))
      throw worlds::WorldError(source, field, "expected a whole number");
    f.set(p, x);
  }
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
  for (const Field& f : fields()) {
    const double v = f.get(p);
    nlohmann::ordered_json value = f.kind == util::ParamKind::kWhole
                                       ? nlohmann::ordered_json(static_cast<long long>(v))
                                       : nlohmann::ordered_json(v);
    if (std::string(f.section).empty())
      j[f.name] = value;
    else
      j[f.section][f.name] = value;
  }
  return j.dump(2) + "\n";
}

}  // namespace plantsim::planner
