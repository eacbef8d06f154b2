// Scenario YAML parsing.
#include "batch/batch_spec.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "episode/episode_config_json.h"
#include "planner/planner.h"
#include "planner/registry.h"
#include "plugins/plugin_loader.h"
#include "util/c_number.h"
#include "util/data_dir.h"
#include "util/input_file.h"
#include "worlds/decimal_number.h"
#include "worlds/json_input.h"
#include "worlds/known_keys.h"
#include "worlds/names.h"
#include "worlds/world_error.h"
#include "worlds/yaml_input.h"

namespace plantsim::batch {
namespace {

using worlds::WorldError;

// Every number of a scenario by one rule (worlds/decimal_number.h): decimal, `010` is 10.
using worlds::decimal_number;
using worlds::decimal_whole_number;
using worlds::is_decimal_number;

// A YAML mapping of overrides as JSON text, validated by the episode-config reader.
std::string overrides_json(const YAML::Node& node, const std::string& source,
                           const std::string& field) {
  std::function<nlohmann::json(const YAML::Node&)> convert =
      [&](const YAML::Node& n) -> nlohmann::json {
    if (n.IsMap()) {
      nlohmann::json j = nlohmann::json::object();
      for (const auto& kv : n) j[kv.first.as<std::string>()] = convert(kv.second);
      return j;
    }
    if (n.IsScalar()) {
      const std::string s = n.Scalar();
      if (s == "true" || s == "false") return s == "true";
      // Plain decimal numbers only: std::stod would read "0x10" as 16 and std::stoull as 0, and
      // "inf" or "nan" as numbers; anything else stays text for the config reader to refuse.
      if (is_decimal_number(s)) {
        if (const auto whole = decimal_whole_number(s); whole && s.size() <= 18) return *whole;
        return util::c_strtod(s.c_str(), nullptr);
      }
      return s;
    }
    if (!n.IsDefined() || n.IsNull()) return nlohmann::json::object();
    throw WorldError(source, field, "expected a mapping of parameters");
  };
  std::string text;
  try {
    text = convert(node).dump();
  } catch (const nlohmann::json::type_error&) {
    throw WorldError(source, field, "holds text that is not valid UTF-8");
  }
  episode::parse_episode_config(text, source + " (" + field + ")");  // throws on a bad key or value
  return text;
}

// A list of exactly `count` finite numbers at `where` (`expected` says what it should be).
std::vector<double> read_numbers(const YAML::Node& n, std::size_t count, const std::string& source,
                                 const std::string& where, const char* expected) {
  if (!n || !n.IsSequence() || n.size() != count) throw WorldError(source, where, expected);
  std::vector<double> v(count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::string at = where + "[" + std::to_string(i) + "]";
    const auto number = decimal_number(n[i]);
    if (!number) throw WorldError(source, at, "expected a finite decimal number");
    v[i] = *number;
  }
  return v;
}

// `random_kidnap: {after_s: [a, b], distance_m: [c, d]}` (`where` names it in messages).
FaultSetting::RandomKidnap read_random_kidnap(const YAML::Node& k, const std::string& source,
                                              const std::string& where) {
  if (!k.IsMap()) throw WorldError(source, where, "expected {after_s: [a, b], distance_m: [a, b]}");
  auto number = [](double x) {
    std::ostringstream o;
    o << x;
    return o.str();
  };
  // [low, high] within [lowest, highest].
  auto range = [&](const char* key, double lowest, double highest, double& low, double& high) {
    const std::string at = where + "." + key;
    const std::vector<double> v = read_numbers(k[key], 2, source, at, "expected [low, high]");
    for (int i = 0; i < 2; ++i)
      if (!(v[i] >= lowest && v[i] <= highest))
        throw WorldError(source, at + "[" + std::to_string(i) + "]",
                         "must be from " + number(lowest) + " to " + number(highest));
    if (v[0] > v[1]) throw WorldError(source, at, "low must not exceed high");
    low = v[0], high = v[1];
  };
  FaultSetting::RandomKidnap rk;
  range("after_s", 0.0, 86400.0, rk.after_min_s, rk.after_max_s);
  range("distance_m", 0.0, 1000.0, rk.distance_min_m, rk.distance_max_m);
  if (rk.distance_max_m <= 0)
    throw WorldError(source, where + ".distance_m", "the robot must be moved: high above 0");
  for (const auto& kv : k) {
    const std::string key = kv.first.as<std::string>();
    if (key != "after_s" && key != "distance_m")
      throw WorldError(source, where + "." + key, "unknown parameter");
  }
  return rk;
}

// The keys of a fault that change the plant rather than the episode config; removed from
// `body` as they are read.
void take_plant_keys(YAML::Node& body, FaultSetting& f, const std::string& source,
                     const std::string& field) {
  if (!body.IsMap()) return;
  auto flag = [&](const char* key, bool& out) {
    if (!body[key]) return;
    try {
      out = body[key].as<bool>();
    } catch (const YAML::Exception&) {
      throw WorldError(source, field + "." + key, "expected true or false");
    }
    body.remove(key);
  };
  flag("crossing_obstacle", f.crossing_obstacle);
  flag("crossing_final_approach", f.crossing_final_approach);
  if (body["standing_at_dock_s"]) {
    const double t = decimal_number(body["standing_at_dock_s"]).value_or(-1);
    if (!(t >= 0 && t <= 3600))
      throw WorldError(source, field + ".standing_at_dock_s", "expected seconds from 0 to 3600");
    f.standing_at_dock_s = t;
    body.remove("standing_at_dock_s");
  }
  if (body["unmapped_obstacles"]) {
    const std::uint64_t n = decimal_whole_number(body["unmapped_obstacles"]).value_or(51);
    if (n > 50)
      throw WorldError(source, field + ".unmapped_obstacles",
                       "expected a whole number from 0 to 50");
    f.unmapped_obstacles = static_cast<int>(n);
    body.remove("unmapped_obstacles");
  }
  if (body["charger_map_offset"]) {
    const std::string where = field + ".charger_map_offset";
    const std::vector<double> v = read_numbers(body["charger_map_offset"], 3, source, where,
                                               "expected [dx, dy, dyaw] (m, m, rad)");
    if (std::hypot(v[0], v[1]) > 0.5 || std::fabs(v[2]) > 0.5)
      throw WorldError(source, where,
                       "more than 0.5 m or 0.5 rad: that is a different charger, not a map error");
    f.charger_map_offset = geom::Pose2{v[0], v[1], v[2]};
    body.remove("charger_map_offset");
  }
  if (body["random_kidnap"]) {
    f.random_kidnap = read_random_kidnap(body["random_kidnap"], source, field + ".random_kidnap");
    body.remove("random_kidnap");
  }
}

// A swept value as the fault it makes: plant keys directly, anything else as a dotted
// episode-config key ("drive.tyre_friction").
YAML::Node sweep_override(const std::string& parameter, const YAML::Node& value) {
  YAML::Node body(YAML::NodeType::Map);
  const auto dot = parameter.find('.');
  if (dot == std::string::npos) {
    body[parameter] = value;
  } else {
    YAML::Node section(YAML::NodeType::Map);
    section[parameter.substr(dot + 1)] = value;
    body[parameter.substr(0, dot)] = section;
  }
  return body;
}

std::string value_text(const YAML::Node& v) {
  if (v.IsScalar()) return v.Scalar();
  YAML::Emitter e;
  e << YAML::Flow << v;
  return e.c_str();
}

// Merges two override mappings (b wins).
YAML::Node merged(const YAML::Node& a, const YAML::Node& b) {
  YAML::Node out = a.IsMap() ? YAML::Clone(a) : YAML::Node(YAML::NodeType::Map);
  if (!b.IsMap()) return out;
  for (const auto& kv : b) {
    const std::string key = kv.first.as<std::string>();
    if (kv.second.IsMap() && out[key] && out[key].IsMap())
      out[key] = merged(out[key], kv.second);
    else
      out[key] = YAML::Clone(kv.second);
  }
  return out;
}

std::string scalar_text(const YAML::Node& doc, const char* key, const std::string& path,
                        const std::string& fallback) {
  if (!doc[key]) return fallback;
  if (!doc[key].IsScalar()) throw WorldError(path, key, "expected a single value");
  if (!worlds::valid_utf8(doc[key].Scalar())) throw WorldError(path, key, "is not valid UTF-8");
  return doc[key].Scalar();
}

// A name used in episode ids and records: printable UTF-8, at most 100 bytes.
std::string checked_name(const YAML::Node& key, const std::string& path, const std::string& field) {
  if (!key.IsScalar()) throw WorldError(path, field, "expected names as keys");
  const std::string name = key.Scalar();
  if (const std::string problem = worlds::name_problem(name); !problem.empty())
    throw WorldError(path, field, "a name " + problem + " (docs/batch.md: names)");
  return name;
}

double fraction(const YAML::Node& n, const std::string& path, const std::string& field) {
  const auto v = decimal_number(n);
  if (!v || !(*v >= 0 && *v <= 1)) throw WorldError(path, field, "expected a number from 0 to 1");
  return *v;
}

// gate: {min_success: R, statistic: success_rate | wilson_low, pool: worlds,
//        configurations: [{planner: gcr, min_success: R}, ...]}
Gate read_gate(const YAML::Node& node, const std::string& path) {
  Gate g;
  if (!node) return g;
  if (!node.IsMap())
    throw WorldError(path, "gate", "expected {min_success, statistic, pool, configurations}");
  for (const auto& kv : node) {
    const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : "?";
    const std::vector<std::string> known = {"min_success", "statistic", "pool", "configurations"};
    if (std::find(known.begin(), known.end(), key) == known.end())
      throw WorldError(path, "gate." + key, worlds::unknown_key_problem(key, known));
  }
  if (node["min_success"]) g.min_success = fraction(node["min_success"], path, "gate.min_success");
  if (node["statistic"])
    g.statistic =
        parse_gate_statistic(scalar_text(node, "statistic", path, ""), path + ": gate.statistic");
  if (node["pool"]) {
    const std::string pool = scalar_text(node, "pool", path, "");
    if (pool != "worlds" && pool != "none")
      throw WorldError(path, "gate.pool", "expected 'worlds' or 'none', got '" + pool + "'");
    g.pool_worlds = pool == "worlds";
  }
  if (const YAML::Node list = node["configurations"]) {
    if (!list.IsSequence())
      throw WorldError(path, "gate.configurations",
                       "expected a list of {world, planner, controller, fault, min_success}");
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string field = "gate.configurations[" + std::to_string(i) + "]";
      const YAML::Node item = list[i];
      if (!item.IsMap() || !item["min_success"])
        throw WorldError(
            path, field,
            "expected {planner: ..., min_success: R} (any of world, planner, controller, fault)");
      GateRule rule;
      for (const auto& kv : item) {
        const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : "?";
        if (key == "min_success") continue;
        if (!kv.second.IsScalar()) throw WorldError(path, field + "." + key, "expected a name");
        if (key == "world")
          rule.world = kv.second.Scalar();
        else if (key == "planner")
          rule.planner = kv.second.Scalar();
        else if (key == "controller")
          rule.controller = kv.second.Scalar();
        else if (key == "fault")
          rule.fault = kv.second.Scalar();
        else
          throw WorldError(path, field + "." + key,
                           worlds::unknown_key_problem(
                               key, {"world", "planner", "controller", "fault", "min_success"}));
      }
      rule.min_success = fraction(item["min_success"], path, field + ".min_success");
      g.rules.push_back(rule);
    }
  }
  return g;
}

BatchSpec read_batch_spec(const std::string& path);

}  // namespace

GateStatistic parse_gate_statistic(const std::string& text, const std::string& where) {
  if (text == "success_rate") return GateStatistic::kSuccessRate;
  if (text == "wilson_low") return GateStatistic::kWilsonLow;
  throw std::invalid_argument(where + ": expected success_rate or wilson_low, got '" + text + "'");
}

BatchSpec load_batch_spec(const std::string& path) {
  try {
    return read_batch_spec(path);
  } catch (const YAML::Exception& e) {
    // A node of the wrong kind somewhere not checked field by field.
    throw WorldError(path, "", std::string("unexpected YAML structure: ") + e.what());
  }
}

namespace {

void check_top_keys(const YAML::Node& doc, const std::string& path) {
  for (const auto& kv : doc) {
    const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : "?";
    // `tune` is `plantsim tune`'s (tune/tune_spec.h): a batch runs the scenario's `worlds`.
    const std::vector<std::string> known = {"name",   "worlds", "planners", "controllers",
                                            "faults", "sweep",  "seeds",    "starts",
                                            "gate",   "tune",   "plugins"};
    if (std::find(known.begin(), known.end(), key) == known.end())
      throw WorldError(path, key, worlds::unknown_key_problem(key, known));
  }
}

void read_worlds(const YAML::Node& doc, const std::string& path, const std::string& base,
                 BatchSpec& s) {
  if (!doc["worlds"] || !doc["worlds"].IsSequence() || doc["worlds"].size() == 0)
    throw WorldError(path, "worlds", "expected a non-empty list of world files");
  if (doc["worlds"].size() > 1000) throw WorldError(path, "worlds", "more than 1000 worlds");
  for (std::size_t i = 0; i < doc["worlds"].size(); ++i) {
    const YAML::Node w = doc["worlds"][i];
    const std::string field = "worlds[" + std::to_string(i) + "]";
    if (!w.IsScalar()) throw WorldError(path, field, "expected a file name");
    // Relative to the scenario file ("$data/..." under the shared data folder), so that a
    // scenario runs the same from any current folder.
    const std::string resolved = util::resolve_input_path(w.Scalar(), base);
    std::error_code ec;
    if (!std::filesystem::exists(resolved, ec))
      throw WorldError(path, field, "'" + w.Scalar() + "' not found (looked for " + resolved + ")");
    s.world_files.push_back(resolved);
  }
}

/// The plugins the scenario's components come from, loaded before anything names them.
void read_plugins(const YAML::Node& doc, const std::string& path, const std::string& base,
                  BatchSpec& s) {
  if (!doc["plugins"]) return;
  if (!doc["plugins"].IsSequence())
    throw WorldError(path, "plugins", "expected a list of plugin files (.so)");
  for (std::size_t i = 0; i < doc["plugins"].size(); ++i) {
    const YAML::Node p = doc["plugins"][i];
    const std::string field = "plugins[" + std::to_string(i) + "]";
    if (!p.IsScalar()) throw WorldError(path, field, "expected a file name");
    const std::string resolved = util::resolve_input_path(p.Scalar(), base);
    try {
      plugins::load_plugin(resolved);
    } catch (const plugins::PluginError& e) {
      throw WorldError(path, field, e.what());
    }
    s.plugin_files.push_back(resolved);
  }
}

void read_planners(const YAML::Node& doc, const std::string& path, BatchSpec& s) {
  if (doc["planners"]) {
    if (!doc["planners"].IsSequence())
      throw WorldError(path, "planners", "expected a list of planner names");
    for (const auto& p : doc["planners"]) {
      if (!p.IsScalar()) throw WorldError(path, "planners", "expected a list of planner names");
      s.planners.push_back(p.Scalar());
    }
  } else {
    s.planners = {"vg"};
  }
  const auto known = planner::planner_names();
  for (const auto& p : s.planners)
    if (std::find(known.begin(), known.end(), p) == known.end())
      throw WorldError(path, "planners", "unknown planner '" + p + "'");
  for (std::size_t i = 0; i < s.planners.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (s.planners[i] == s.planners[j])
        throw WorldError(path, "planners", "'" + s.planners[i] + "' is listed twice");
  if (s.planners.empty())
    throw WorldError(path, "planners",
                     "an empty list: no episode would run (leave the key out for vg)");
}

/// A controller given as a config file (`tuned: ../results/tune_speed/best.json`, what `plantsim
/// tune` writes), relative to the scenario, read and checked as `run --config` reads it.
std::string config_file_json(const std::string& file, const std::string& path,
                             const std::string& name) {
  const std::string field = "controllers." + name;
  const std::string resolved =
      util::resolve_input_path(file, std::filesystem::path(path).parent_path().string());
  std::string text;
  try {
    text = util::read_input_file(resolved);
  } catch (const std::exception& e) {
    throw WorldError(path, field, "'" + file + "': " + e.what());
  }
  nlohmann::json j;
  try {
    j = worlds::parse_json_input(text, resolved);  // bounded: depth, keys given twice
  } catch (const WorldError& e) {
    throw WorldError(
        path, field,
        "'" + file + "' is not JSON (expected a config file, docs/config.md): " + e.what());
  }
  episode::parse_episode_config(text, resolved);  // throws on a bad key or value, naming the file
  return j.dump();
}

void read_controllers(const YAML::Node& doc, const std::string& path, BatchSpec& s) {
  if (doc["controllers"]) {
    if (!doc["controllers"].IsMap())
      throw WorldError(path, "controllers", "expected a mapping name: {overrides}");
    if (doc["controllers"].size() == 0)
      throw WorldError(path, "controllers",
                       "empty: no episode would run (leave the key out for the default settings)");
    for (const auto& kv : doc["controllers"]) {
      const std::string name = checked_name(kv.first, path, "controllers");
      s.controllers.push_back({name, kv.second.IsScalar()
                                         ? config_file_json(kv.second.Scalar(), path, name)
                                         : overrides_json(kv.second, path, "controllers." + name)});
    }
  } else {
    s.controllers = {{"default", "{}"}};
  }
}

/// Each fault's overrides as written, by name.
using FaultBodies = std::vector<std::pair<std::string, YAML::Node>>;

FaultBodies read_fault_bodies(const YAML::Node& doc, const std::string& path) {
  FaultBodies bodies;
  if (doc["faults"]) {
    if (!doc["faults"].IsMap())
      throw WorldError(path, "faults", "expected a mapping name: {overrides}");
    if (doc["faults"].size() == 0)
      throw WorldError(path, "faults",
                       "empty: no episode would run (leave the key out for no fault)");
    for (const auto& kv : doc["faults"])
      bodies.emplace_back(checked_name(kv.first, path, "faults"), YAML::Clone(kv.second));
  }
  return bodies;
}

/// One fault per value of the swept parameter (per fault, when faults are given too): the
/// success-rate curves.
void apply_sweep(const YAML::Node& doc, const std::string& path, BatchSpec& s,
                 FaultBodies& bodies) {
  if (!doc["sweep"]) return;
  const YAML::Node sw = doc["sweep"];
  if (!sw.IsMap() || !sw["parameter"] || !sw["parameter"].IsScalar())
    throw WorldError(path, "sweep", "expected {parameter: <name>, values: [...]}");
  const std::string parameter = sw["parameter"].Scalar();
  if (!worlds::valid_utf8(parameter) || parameter.size() > 100)
    throw WorldError(path, "sweep.parameter", "expected a parameter name");
  if (!sw["values"] || !sw["values"].IsSequence() || sw["values"].size() == 0)
    throw WorldError(path, "sweep.values", "expected a non-empty list of values");
  if (sw["values"].size() > 100) throw WorldError(path, "sweep.values", "more than 100 values");
  s.sweep_parameter = parameter;
  if (bodies.empty()) bodies.emplace_back("", YAML::Node(YAML::NodeType::Map));
  std::vector<std::pair<std::string, YAML::Node>> swept;
  std::vector<std::string> values;
  for (const auto& v : sw["values"]) {
    values.push_back(value_text(v));
    if (!worlds::valid_utf8(values.back()) || values.back().size() > 100)
      throw WorldError(path, "sweep.values", "values must be at most 100 characters of UTF-8");
    // Each value names its configuration (and its episodes' ids): a value twice, or 1 and 1.0,
    // would run one setting as two that share ids.
    const std::string& value = values.back();
    for (std::size_t i = 0; i + 1 < values.size(); ++i)
      if (values[i] == value ||
          (is_decimal_number(values[i]) && is_decimal_number(value) &&
           util::c_strtod(values[i].c_str(), nullptr) == util::c_strtod(value.c_str(), nullptr)))
        throw WorldError(path, "sweep.values",
                         "'" + value + "' is the value '" + values[i] + "' again");
  }
  for (const auto& [name, body] : bodies)
    for (std::size_t i = 0; i < values.size(); ++i) {
      YAML::Node one = merged(body, sweep_override(parameter, sw["values"][i]));
      swept.emplace_back((name.empty() ? "" : name + " ") + parameter + "=" + values[i], one);
    }
  bodies = std::move(swept);
  // The parameter must be a plant key or a config key, and each value one it takes: an unknown
  // key is the parameter's fault, anything else the value's (".nan" and "0x10" were reported as
  // "not a fault parameter").
  for (std::size_t i = 0; i < values.size(); ++i) {
    const std::string field = "sweep.values[" + std::to_string(i) + "]";
    try {
      YAML::Node probe = YAML::Clone(sweep_override(parameter, sw["values"][i]));
      FaultSetting f;
      take_plant_keys(probe, f, path, field);
      overrides_json(probe, path, "sweep");
    } catch (const WorldError& e) {
      if (const std::string what = e.what(); what.find("unknown key") != std::string::npos ||
                                             what.find("unknown parameter") != std::string::npos)
        throw WorldError(path, "sweep.parameter",
                         "'" + parameter + "' is not a fault parameter (" + e.what() + ")");
      throw WorldError(
          path, field,
          "'" + values[i] + "' is not a value of " + parameter + " (" + e.what() + ")");
    }
  }
}

void make_faults(FaultBodies& bodies, const std::string& path, BatchSpec& s) {
  for (auto& [name, body] : bodies) {
    FaultSetting f;
    f.name = name;
    f.json = "{}";
    take_plant_keys(body, f, path, "faults." + name);
    f.json = overrides_json(body, path, "faults." + name);
    if (!s.sweep_parameter.empty()) {
      f.sweep_parameter = s.sweep_parameter;
      f.sweep_value = name.substr(name.rfind('=') + 1);
    }
    s.faults.push_back(f);
  }
  if (s.faults.empty()) {
    FaultSetting none;
    none.name = "none";
    none.json = "{}";
    s.faults.push_back(none);
  }
}

void read_seeds(const YAML::Node& doc, const std::string& path, BatchSpec& s) {
  const YAML::Node seeds = doc["seeds"];
  if (!seeds) throw WorldError(path, "seeds", "missing (a count, or a list of seeds)");
  try {
    if (seeds.IsScalar()) {
      // Decimal: yaml-cpp's as<long>() read `seeds: 010` as 8 seeds.
      const auto n = decimal_whole_number(seeds);
      if (!n) throw WorldError(path, "seeds", "expected a count or a list of whole numbers");
      if (*n == 0 || *n > 1000000)
        throw WorldError(path, "seeds", "count must be from 1 to 1000000");
      for (std::uint64_t k = 1; k <= *n; ++k) s.seeds.push_back(k);
    } else if (seeds.IsSequence()) {
      if (seeds.size() > 1000000) throw WorldError(path, "seeds", "more than 1000000 seeds");
      std::set<std::uint64_t> seen;
      for (const auto& v : seeds) {
        const auto seed = decimal_whole_number(v);
        if (!seed)
          throw WorldError(
              path, "seeds",
              "expected whole numbers, got '" + (v.IsScalar() ? v.Scalar() : "a list") + "'");
        s.seeds.push_back(*seed);
        if (!seen.insert(s.seeds.back()).second)
          throw WorldError(path, "seeds",
                           "seed " + v.Scalar() + " is listed twice (one episode id each)");
      }
      if (s.seeds.empty()) throw WorldError(path, "seeds", "expected a count or a non-empty list");
    } else {
      throw WorldError(path, "seeds", "expected a count or a list of whole numbers");
    }
  } catch (const YAML::Exception&) {
    throw WorldError(path, "seeds", "expected a count or a list of whole numbers");
  }
}

void read_starts(const YAML::Node& doc, const std::string& path, BatchSpec& s) {
  if (doc["starts"]) {
    const std::string v = scalar_text(doc, "starts", path, "");
    if (v != "random" && v != "world")
      throw WorldError(path, "starts", "must be 'random' or 'world'");
    s.random_starts = v == "random";
  }
}

/// A gate rule that matches no configuration judges nothing: a typo, refused (worlds are named by
/// their files' contents: checked once they are loaded, scenario_setup.cpp).
void check_gate_rules(const std::string& path, const BatchSpec& s) {
  for (std::size_t i = 0; i < s.gate.rules.size(); ++i) {
    const GateRule& r = s.gate.rules[i];
    const std::string field = "gate.configurations[" + std::to_string(i) + "]";
    auto listed = [](const std::string& name, const auto& items, auto name_of) {
      return name.empty() || std::any_of(items.begin(), items.end(),
                                         [&](const auto& x) { return name_of(x) == name; });
    };
    if (!listed(r.planner, s.planners, [](const std::string& p) { return p; }))
      throw WorldError(path, field + ".planner",
                       "'" + r.planner +
                           "' is not one of the scenario's planners: the rule would judge nothing");
    if (!listed(r.controller, s.controllers, [](const NamedConfig& c) { return c.name; }))
      throw WorldError(
          path, field + ".controller",
          "'" + r.controller +
              "' is not one of the scenario's controllers: the rule would judge nothing");
    if (!listed(r.fault, s.faults, [](const FaultSetting& f) { return f.name; }))
      throw WorldError(
          path, field + ".fault",
          "'" + r.fault + "' is not one of the scenario's faults: the rule would judge nothing");
  }
}

void check_episode_count(const std::string& path, const BatchSpec& s, double faults) {
  // Episodes are counted before any is made, or any fault of a sweep: a cross product of 1e13
  // is a typo, not a batch.
  const double total = static_cast<double>(s.world_files.size()) * s.planners.size() *
                       s.controllers.size() * faults * s.seeds.size();
  if (total > kMaxScenarioEpisodes)
    throw WorldError(path, "seeds",
                     "the scenario makes " + std::to_string(static_cast<long long>(total)) +
                         " episodes, more than the limit of 1e12");
}

BatchSpec read_batch_spec(const std::string& path) {
  const YAML::Node doc = worlds::load_yaml_input(path);
  if (!doc.IsMap())
    throw WorldError(path, "", "expected a mapping with worlds, planners, seeds ...");
  check_top_keys(doc, path);
  BatchSpec s;
  s.source = path;
  s.name = doc["name"] ? scalar_text(doc, "name", path, "")
                       : worlds::name_from_file(path, "rename the scenario file or give it a name");
  if (const std::string problem = worlds::name_problem(s.name); !problem.empty())
    throw WorldError(path, "name", "the name " + problem);
  read_plugins(doc, path, std::filesystem::path(path).parent_path().string(), s);
  read_worlds(doc, path, std::filesystem::path(path).parent_path().string(), s);
  read_planners(doc, path, s);
  read_controllers(doc, path, s);
  FaultBodies bodies = read_fault_bodies(doc, path);
  read_seeds(doc, path, s);
  const YAML::Node values =
      doc["sweep"] && doc["sweep"].IsMap() ? doc["sweep"]["values"] : YAML::Node();
  check_episode_count(
      path, s,
      std::max<double>(1.0, static_cast<double>(bodies.size())) *
          (values && values.IsSequence() ? std::max<double>(1.0, values.size()) : 1.0));
  apply_sweep(doc, path, s, bodies);
  make_faults(bodies, path, s);
  read_starts(doc, path, s);
  s.gate = read_gate(doc["gate"], path);
  check_gate_rules(path, s);
  return s;
}

}  // namespace

}  // namespace plantsim::batch
