// Reading a tuning: the scenario's `tune:` section, the command line over it, every bound
// checked against the parameter's documented range.
#include "tune/tune_spec.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>

#include "util/c_number.h"
#include "util/data_dir.h"
#include "worlds/decimal_number.h"
#include "worlds/known_keys.h"
#include "worlds/world_error.h"
#include "worlds/yaml_input.h"

namespace plantsim::tune {

using worlds::WorldError;

namespace {

constexpr int kMaxBudget = 100000;

struct MethodName {
  Method method;
  const char* name;
};
constexpr MethodName kMethods[] = {
    {Method::kSbplx, "sbplx"},   {Method::kSbplxStarts, "sbplx-starts"},
    {Method::kBobyqa, "bobyqa"}, {Method::kNelderMead, "neldermead"},
    {Method::kCrs2, "crs2"},     {Method::kIsres, "isres"}};

Method parse_method(const std::string& text, const std::string& where) {
  std::string choices;
  for (const MethodName& m : kMethods) {
    if (text == m.name) return m.method;
    choices += std::string(choices.empty() ? "" : ", ") + m.name;
  }
  throw std::invalid_argument(where + ": unknown method '" + text + "' (expected one of " +
                              choices + ")");
}

std::string number_text(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

/// A search bound must lie in the parameter's documented range; a whole number's bounds are whole.
TunedParameter checked_parameter(const std::string& key, double lo, double hi,
                                 const std::string& where) {
  TunedParameter p;
  p.info = episode::number_parameter(key);  // throws naming an unknown key
  p.lo = lo, p.hi = hi;
  const std::string range =
      (p.info.above ? "(" : "[") + number_text(p.info.lo) + ", " + number_text(p.info.hi) + "]";
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi))
    throw std::invalid_argument(where + ": '" + key + "' needs finite bounds LOW < HIGH");
  if (lo < p.info.lo || hi > p.info.hi || (p.info.above && lo <= p.info.lo))
    throw std::invalid_argument(where + ": '" + key + "' bounds " + number_text(lo) + ":" +
                                number_text(hi) + " leave its documented range " + range +
                                " (docs/config.md)");
  if (p.info.whole && (lo != std::floor(lo) || hi != std::floor(hi)))
    throw std::invalid_argument(where + ": '" + key + "' is a whole number: whole bounds");
  return p;
}

// By the decimal rule of every YAML number (worlds/decimal_number.h), on the command line as in
// the scenario: std::stod took `0x10` as 16.
double parse_bound(const std::string& text, const std::string& where) {
  const auto v = worlds::decimal_number(text);
  if (!v) throw std::invalid_argument(where + ": '" + text + "' is not a number");
  return *v;
}

/// "KEY=LOW:HIGH" from the command line.
TunedParameter parameter_from_option(const std::string& text) {
  const std::string where = "--param " + text;
  const std::size_t eq = text.find('='), colon = text.rfind(':');
  if (eq == std::string::npos || colon == std::string::npos || colon < eq)
    throw std::invalid_argument(where +
                                ": expected KEY=LOW:HIGH, e.g. "
                                "tracking.max_linear_speed_mps=0.3:0.8");
  return checked_parameter(text.substr(0, eq),
                           parse_bound(text.substr(eq + 1, colon - eq - 1), where),
                           parse_bound(text.substr(colon + 1), where), where);
}

std::vector<std::uint64_t> read_seeds(const YAML::Node& n, const std::string& path) {
  const std::string field = "tune.validation_seeds";
  std::vector<std::uint64_t> seeds;
  auto whole = [&](const YAML::Node& v) {
    const std::string s = v.IsScalar() ? v.Scalar() : "";
    if (s.empty() || s.size() > 9 || s.find_first_not_of("0123456789") != std::string::npos)
      throw WorldError(path, field, "expected whole numbers from 1 to 999999999, got '" + s + "'");
    return static_cast<std::uint64_t>(std::stoull(s));
  };
  if (n.IsScalar()) {
    const std::uint64_t count = whole(n);
    if (count < 1 || count > 1000000) throw WorldError(path, field, "count must be 1 to 1000000");
    for (std::uint64_t k = 1; k <= count; ++k) seeds.push_back(k);
  } else if (n.IsSequence() && n.size() > 0 && n.size() <= 1000000) {
    std::set<std::uint64_t> seen;
    for (const auto& v : n)
      if (!seen.insert(seeds.emplace_back(whole(v))).second)
        throw WorldError(path, field, "seed " + v.Scalar() + " is listed twice");
  } else {
    throw WorldError(path, field, "expected a count or a non-empty list of seeds");
  }
  return seeds;
}

std::vector<std::string> read_worlds(const YAML::Node& n, const std::string& path) {
  if (!n.IsSequence() || n.size() == 0 || n.size() > 1000)
    throw WorldError(path, "tune.validation_worlds", "expected a list of 1 to 1000 world files");
  const std::string base = std::filesystem::path(path).parent_path().string();
  std::vector<std::string> files;
  for (std::size_t i = 0; i < n.size(); ++i) {
    const std::string field = "tune.validation_worlds[" + std::to_string(i) + "]";
    if (!n[i].IsScalar()) throw WorldError(path, field, "expected a file name");
    const std::string resolved = util::resolve_input_path(n[i].Scalar(), base);
    std::error_code ec;
    if (!std::filesystem::exists(resolved, ec))
      throw WorldError(path, field,
                       "'" + n[i].Scalar() + "' not found (looked for " + resolved + ")");
    files.push_back(resolved);
  }
  return files;
}

void check_section_keys(const YAML::Node& t, const std::string& path) {
  const std::vector<std::string> known = {"validation_worlds", "validation_seeds", "parameters",
                                          "objective",         "budget",           "method",
                                          "min_wilson"};
  for (const auto& kv : t) {
    const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : "?";
    if (std::find(known.begin(), known.end(), key) == known.end())
      throw WorldError(path, "tune." + key, worlds::unknown_key_problem(key, known));
  }
}

std::vector<TunedParameter> scenario_parameters(const YAML::Node& n, const std::string& path) {
  if (!n.IsMap() || n.size() == 0)
    throw WorldError(path, "tune.parameters", "expected a mapping KEY: [LOW, HIGH]");
  std::vector<TunedParameter> out;
  for (const auto& kv : n) {
    const std::string key = kv.first.Scalar(), field = "tune.parameters." + key;
    if (!kv.second.IsSequence() || kv.second.size() != 2)
      throw WorldError(path, field, "expected [LOW, HIGH]");
    double b[2] = {0, 0};
    for (int i = 0; i < 2; ++i)
      b[i] = parse_bound(kv.second[i].IsScalar() ? kv.second[i].Scalar() : "", path + ": " + field);
    try {
      out.push_back(checked_parameter(key, b[0], b[1], field));
    } catch (const std::invalid_argument& e) {
      throw WorldError(path, field, e.what());
    }
  }
  return out;
}

/// The validation part: the tuning part's settings on the held-out worlds or seeds. Gate rules
/// naming a tuning world do not apply there.
batch::BatchSpec validation_part(const batch::BatchSpec& tuning, const YAML::Node& t,
                                 const std::string& path) {
  if (!t["validation_worlds"] && !t["validation_seeds"])
    throw WorldError(path, "tune.validation_worlds",
                     "missing: a tuning is proven on worlds (or seeds) it was not tuned on; "
                     "name them in tune.validation_worlds or tune.validation_seeds");
  batch::BatchSpec v = tuning;
  v.name = tuning.name + " (validation)";
  if (t["validation_worlds"]) v.world_files = read_worlds(t["validation_worlds"], path);
  if (t["validation_seeds"]) v.seeds = read_seeds(t["validation_seeds"], path);
  // Whether the parts overlap is judged by the worlds' content once they are loaded
  // (tune/held_out.h), not by the names written here.
  std::erase_if(v.gate.rules, [](const batch::GateRule& r) { return !r.world.empty(); });
  return v;
}

}  // namespace

std::string method_name(Method m) {
  for (const MethodName& n : kMethods)
    if (n.method == m) return n.name;
  return "?";
}

std::vector<std::string> default_parameters() {
  return {"tracking.max_linear_speed_mps=0.3:0.8",
          "tracking.lookahead_time_s=0.5:2.5",
          "tracking.lookahead_max_m=0.5:2",
          "tracking.regulated_min_radius_m=0.3:2",
          "tracking.approach_slowdown_distance_m=0.3:2.5",
          "docking.approach_speed_mps=0.04:0.2",
          "docking.approach_lookahead_m=0.2:0.8"};
}

TuneSpec load_tune_spec(const TuneRequest& r) {
  TuneSpec spec;
  spec.scenario = r.scenario;
  spec.tuning = batch::load_batch_spec(r.scenario);  // throws naming file and field
  const YAML::Node doc = worlds::load_yaml_input(r.scenario);
  const YAML::Node t = doc["tune"];
  if (!t || !t.IsMap())
    throw WorldError(r.scenario, "tune",
                     "missing: a tuning scenario names its held-out part in a `tune:` section "
                     "(docs/tune.md)");
  check_section_keys(t, r.scenario);
  spec.validation = validation_part(spec.tuning, t, r.scenario);
  try {
    if (!r.parameters.empty()) {
      for (const std::string& p : r.parameters) spec.parameters.push_back(parameter_from_option(p));
    } else if (t["parameters"]) {
      spec.parameters = scenario_parameters(t["parameters"], r.scenario);
    } else {
      for (const std::string& p : default_parameters())
        spec.parameters.push_back(parameter_from_option(p));
    }
    std::set<std::string> seen;
    for (const TunedParameter& p : spec.parameters)
      if (!seen.insert(p.info.path).second)
        throw std::invalid_argument("--param: '" + p.info.path + "' is named twice");
    const std::string objective = r.objective      ? *r.objective
                                  : t["objective"] ? t["objective"].as<std::string>()
                                                   : "";
    if (!objective.empty())
      spec.objective = parse_objective(objective, r.objective ? "--objective" : "tune.objective");
    const std::string method = r.method      ? *r.method
                               : t["method"] ? t["method"].as<std::string>()
                                             : "sbplx";
    spec.method = parse_method(method, r.method ? "--method" : "tune.method");
    long budget = 60;
    if (r.budget) {
      budget = *r.budget;
    } else if (t["budget"]) {
      // Decimal as --budget reads it: yaml-cpp's as<long>() read `budget: 010` as 8.
      const auto v = worlds::decimal_whole_number(t["budget"]);
      if (!v || *v > static_cast<std::uint64_t>(kMaxBudget))
        throw WorldError(r.scenario, "tune.budget",
                         "expected a whole number of evaluations from 1 to 100000");
      budget = static_cast<long>(*v);
    }
    if (budget < 1 || budget > kMaxBudget)
      throw std::invalid_argument(std::string(r.budget ? "--budget" : "tune.budget") +
                                  ": the number of evaluations must be 1 to 100000, got " +
                                  std::to_string(budget));
    spec.budget = static_cast<int>(budget);
    if (r.min_wilson || t["min_wilson"]) {
      const auto floor = r.min_wilson ? r.min_wilson : worlds::decimal_number(t["min_wilson"]);
      if (!floor) throw WorldError(r.scenario, "tune.min_wilson", "expected a decimal number");
      if (!(*floor >= 0 && *floor <= 1))
        throw std::invalid_argument("--min-wilson: a Wilson lower bound from 0 to 1");
      spec.min_wilson = *floor;
    }
  } catch (const YAML::Exception& e) {
    throw WorldError(r.scenario, "tune", std::string("unexpected value: ") + e.what());
  }
  spec.seed = r.seed;
  spec.threads = r.threads;
  return spec;
}

}  // namespace plantsim::tune
