// Scenario YAML parsing.
#include "batch/batch_spec.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "planner/planner.h"
#include "sim/episode_config_json.h"
#include "worlds/world_error.h"

namespace plantsim::batch {
namespace {

using worlds::WorldError;

// A YAML mapping of overrides as JSON text, validated by the episode-config reader.
std::string overrides_json(const YAML::Node& node, const std::string& source, const std::string& field) {
  std::function<nlohmann::json(const YAML::Node&)> convert = [&](const YAML::Node& n) -> nlohmann::json {
    if (n.IsMap()) {
      nlohmann::json j = nlohmann::json::object();
      for (const auto& kv : n) j[kv.first.as<std::string>()] = convert(kv.second);
      return j;
    }
    if (n.IsScalar()) {
      const std::string s = n.Scalar();
      if (s == "true" || s == "false") return s == "true";
      try {
        std::size_t used = 0;
        const double d = std::stod(s, &used);
        if (used == s.size()) {
          if (s.find_first_of(".eE") == std::string::npos && d >= 0) return static_cast<std::uint64_t>(std::stoull(s));
          return d;
        }
      } catch (...) {
      }
      return s;
    }
    if (!n.IsDefined() || n.IsNull()) return nlohmann::json::object();
    throw WorldError(source, field, "expected a mapping of parameters");
  };
  const std::string text = convert(node).dump();
  sim::parse_episode_config(text, source + " (" + field + ")");  // throws on a bad key or value
  return text;
}

// The keys of a fault that change the plant rather than the episode config; removed from
// `body` as they are read.
void take_plant_keys(YAML::Node& body, FaultSetting& f, const std::string& source, const std::string& field) {
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
  if (body["unmapped_obstacles"]) {
    long n = -1;
    try {
      n = body["unmapped_obstacles"].as<long>();
    } catch (const YAML::Exception&) {
    }
    if (n < 0 || n > 50) throw WorldError(source, field + ".unmapped_obstacles", "expected a whole number from 0 to 50");
    f.unmapped_obstacles = static_cast<int>(n);
    body.remove("unmapped_obstacles");
  }
  if (body["charger_map_offset"]) {
    const YAML::Node o = body["charger_map_offset"];
    const std::string where = field + ".charger_map_offset";
    if (!o.IsSequence() || o.size() != 3) throw WorldError(source, where, "expected [dx, dy, dyaw] (m, m, rad)");
    double v[3];
    for (int i = 0; i < 3; ++i) {
      try {
        v[i] = o[i].as<double>();
      } catch (const YAML::Exception&) {
        throw WorldError(source, where + "[" + std::to_string(i) + "]", "expected a number");
      }
      if (!std::isfinite(v[i])) throw WorldError(source, where + "[" + std::to_string(i) + "]", "must be finite");
    }
    if (std::hypot(v[0], v[1]) > 0.5 || std::fabs(v[2]) > 0.5)
      throw WorldError(source, where, "more than 0.5 m or 0.5 rad: that is a different charger, not a map error");
    f.charger_map_offset = geom::Pose2{v[0], v[1], v[2]};
    body.remove("charger_map_offset");
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
    if (kv.second.IsMap() && out[key] && out[key].IsMap()) out[key] = merged(out[key], kv.second);
    else out[key] = YAML::Clone(kv.second);
  }
  return out;
}

}  // namespace

BatchSpec load_batch_spec(const std::string& path) {
  if (std::filesystem::is_directory(path)) throw WorldError(path, "", "is a directory, expected a scenario YAML");
  YAML::Node doc;
  try {
    doc = YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    throw WorldError(path, "", "cannot be opened for reading");
  } catch (const YAML::Exception& e) {
    throw WorldError(path, "", std::string("malformed YAML: ") + e.what());
  }
  if (!doc.IsMap()) throw WorldError(path, "", "expected a mapping with worlds, planners, seeds ...");
  BatchSpec s;
  s.source = path;
  s.name = doc["name"] ? doc["name"].as<std::string>() : std::filesystem::path(path).stem().string();
  const auto base = std::filesystem::path(path).parent_path();
  if (!doc["worlds"] || !doc["worlds"].IsSequence() || doc["worlds"].size() == 0)
    throw WorldError(path, "worlds", "expected a non-empty list of world files");
  for (const auto& w : doc["worlds"]) {
    const std::filesystem::path p(w.as<std::string>());
    // Relative to the scenario file, or to the current folder when that is where it exists.
    s.world_files.push_back(p.is_absolute() || std::filesystem::exists(p) ? p.string() : (base / p).string());
  }
  if (doc["planners"]) {
    for (const auto& p : doc["planners"]) s.planners.push_back(p.as<std::string>());
  } else {
    s.planners = {"vg"};
  }
  const auto known = planner::planner_names();
  for (const auto& p : s.planners)
    if (std::find(known.begin(), known.end(), p) == known.end()) throw WorldError(path, "planners", "unknown planner '" + p + "'");
  if (doc["controllers"]) {
    if (!doc["controllers"].IsMap()) throw WorldError(path, "controllers", "expected a mapping name: {overrides}");
    for (const auto& kv : doc["controllers"]) {
      const std::string name = kv.first.as<std::string>();
      s.controllers.push_back({name, overrides_json(kv.second, path, "controllers." + name)});
    }
  } else {
    s.controllers = {{"default", "{}"}};
  }
  std::vector<std::pair<std::string, YAML::Node>> bodies;  // each fault's overrides as written
  if (doc["faults"]) {
    if (!doc["faults"].IsMap()) throw WorldError(path, "faults", "expected a mapping name: {overrides}");
    for (const auto& kv : doc["faults"]) bodies.emplace_back(kv.first.as<std::string>(), YAML::Clone(kv.second));
  }
  if (doc["sweep"]) {
    // One fault per value (per fault, when faults are given too): success-rate curves.
    const YAML::Node sw = doc["sweep"];
    if (!sw.IsMap() || !sw["parameter"] || !sw["parameter"].IsScalar())
      throw WorldError(path, "sweep", "expected {parameter: <name>, values: [...]}");
    const std::string parameter = sw["parameter"].Scalar();
    if (!sw["values"] || !sw["values"].IsSequence() || sw["values"].size() == 0)
      throw WorldError(path, "sweep.values", "expected a non-empty list of values");
    if (sw["values"].size() > 100) throw WorldError(path, "sweep.values", "more than 100 values");
    s.sweep_parameter = parameter;
    if (bodies.empty()) bodies.emplace_back("", YAML::Node(YAML::NodeType::Map));
    std::vector<std::pair<std::string, YAML::Node>> swept;
    std::vector<std::string> values;
    for (const auto& v : sw["values"]) values.push_back(value_text(v));
    for (const auto& [name, body] : bodies)
      for (std::size_t i = 0; i < values.size(); ++i) {
        YAML::Node one = merged(body, sweep_override(parameter, sw["values"][i]));
        swept.emplace_back((name.empty() ? "" : name + " ") + parameter + "=" + values[i], one);
      }
    bodies = std::move(swept);
    try {
      // The parameter must be a plant key or a config key: try the first value.
      YAML::Node probe = YAML::Clone(sweep_override(parameter, sw["values"][0]));
      FaultSetting f;
      take_plant_keys(probe, f, path, "sweep.values[0]");
      overrides_json(probe, path, "sweep");
    } catch (const WorldError& e) {
      throw WorldError(path, "sweep.parameter", "'" + parameter + "' is not a fault parameter (" + e.what() + ")");
    }
  }
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
  const YAML::Node seeds = doc["seeds"];
  if (!seeds) throw WorldError(path, "seeds", "missing (a count, or a list of seeds)");
  try {
    if (seeds.IsScalar()) {
      const long n = seeds.as<long>();
      if (n <= 0 || n > 1000000) throw WorldError(path, "seeds", "count must be from 1 to 1000000");
      for (long k = 1; k <= n; ++k) s.seeds.push_back(static_cast<std::uint64_t>(k));
    } else {
      for (const auto& v : seeds) s.seeds.push_back(v.as<std::uint64_t>());
    }
  } catch (const YAML::Exception&) {
    throw WorldError(path, "seeds", "expected a count or a list of whole numbers");
  }
  if (doc["starts"]) {
    const std::string v = doc["starts"].as<std::string>();
    if (v != "random" && v != "world") throw WorldError(path, "starts", "must be 'random' or 'world'");
    s.random_starts = v == "random";
  }
  return s;
}

std::vector<Episode> all_episodes(const BatchSpec& spec, const std::vector<std::string>& world_names) {
  std::vector<Episode> out;
  std::int64_t index = 0;
  for (std::size_t w = 0; w < spec.world_files.size(); ++w)
    for (std::size_t p = 0; p < spec.planners.size(); ++p)
      for (std::size_t c = 0; c < spec.controllers.size(); ++c)
        for (std::size_t f = 0; f < spec.faults.size(); ++f)
          for (std::uint64_t seed : spec.seeds) {
            Episode e{index++, world_names[w] + "|" + spec.planners[p] + "|" + spec.controllers[c].name + "|" +
                                   spec.faults[f].name + "|" + std::to_string(seed),
                      w, p, c, f, seed};
            out.push_back(e);
          }
  return out;
}

std::vector<Episode> shard(const std::vector<Episode>& all, int i, int n) {
  std::vector<Episode> out;
  for (const Episode& e : all)
    if (e.index % n == i) out.push_back(e);
  return out;
}

}  // namespace plantsim::batch
