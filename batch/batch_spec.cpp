// Scenario YAML parsing.
#include "batch/batch_spec.h"

#include <yaml-cpp/yaml.h>

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
  if (doc["faults"]) {
    if (!doc["faults"].IsMap()) throw WorldError(path, "faults", "expected a mapping name: {overrides}");
    for (const auto& kv : doc["faults"]) {
      const std::string name = kv.first.as<std::string>();
      YAML::Node body = YAML::Clone(kv.second);
      FaultSetting f{name, "{}", false};
      if (body.IsMap() && body["crossing_obstacle"]) {
        f.crossing_obstacle = body["crossing_obstacle"].as<bool>();
        body.remove("crossing_obstacle");
      }
      f.json = overrides_json(body, path, "faults." + name);
      s.faults.push_back(f);
    }
  } else {
    s.faults = {{"none", "{}", false}};
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
