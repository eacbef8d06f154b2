// The batch engine.
#include "batch/batch_runner.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <thread>

#include "batch/batch_gate.h"
#include "batch/batch_report.h"
#include "batch/episode_records.h"
#include "batch/plant_faults.h"
#include "geometry/predicates.h"
#include "planner/planner.h"
#include "sim/episode_config_json.h"
#include "sim/episode_json.h"
#include "util/atomic_file.h"
#include "util/csv.h"
#include "util/fingerprint.h"
#include "util/folder_lock.h"
#include "util/input_file.h"
#include "worlds/known_keys.h"
#include "worlds/world_error.h"
#include "worlds/world_fingerprint.h"
#include "worlds/world_loader.h"

namespace plantsim::batch {
namespace {

using nlohmann::json;

// A free start for this world and seed: uniform over the floor, outside inflated obstacles,
// with a path to the staging pose, not right at the charger.
std::optional<geom::Pose2> random_start(const worlds::World& w, planner::Planner& vg,
                                        std::uint64_t seed, std::uint64_t world_content) {
  std::mt19937_64 rng(
      util::Fingerprint().add(world_content).add(seed).add(std::uint64_t{17}).value());
  std::uniform_real_distribution<double> ux(w.floor.xmin, w.floor.xmax),
      uy(w.floor.ymin, w.floor.ymax), yaw(-M_PI, M_PI);
  const geom::Vec2 staging = worlds::staging_pose(w).position();
  for (int attempt = 0; attempt < 2000; ++attempt) {
    const geom::Pose2 p{ux(rng), uy(rng), yaw(rng)};
    if (geom::distance(p.position(), w.charger.position()) < 2.0) continue;
    bool too_close = false;  // not starting against an actor's box
    for (const auto& m : w.moving) {
      const geom::Rect b = m.box_at(0.0);
      const double dx = std::max({b.xmin - p.x, 0.0, p.x - b.xmax}),
                   dy = std::max({b.ymin - p.y, 0.0, p.y - b.ymax});
      too_close |= std::hypot(dx, dy) < w.robot.radius_m + 1.0;
    }
    for (const geom::Rect& u : w.unmapped) {  // not inside (or against) a box the map lacks
      const double dx = std::max({u.xmin - p.x, 0.0, p.x - u.xmax}),
                   dy = std::max({u.ymin - p.y, 0.0, p.y - u.ymax});
      too_close |= std::hypot(dx, dy) < w.robot.radius_m + 0.3;
    }
    if (too_close) continue;
    if (vg.plan(p.position(), staging).status == planner::PlanStatus::kOk) return p;
  }
  return std::nullopt;
}

// Which scenario a record belongs to: what makes its episodes (world contents, planners,
// settings, faults, seeds, starts), not the file's name or the order of its lists' worlds.
struct ScenarioIdentity {
  std::string fingerprint;  // 16 hex digits
  std::int64_t episodes = 0;
  std::string file;  // absolute path, to draw a merge's figures again
};

ScenarioIdentity scenario_identity(const BatchSpec& spec,
                                   const std::vector<std::uint64_t>& world_contents,
                                   const std::vector<std::string>& world_names,
                                   std::int64_t episodes) {
  util::Fingerprint f;
  f.add(std::string_view("plantsim scenario v1"));
  std::vector<std::string> worlds;
  for (std::size_t i = 0; i < world_contents.size(); ++i)
    worlds.push_back(world_names[i] + "#" + util::Fingerprint().add(world_contents[i]).hex());
  std::sort(worlds.begin(), worlds.end());
  for (const std::string& w : worlds) f.add(w);
  for (const std::string& p : spec.planners) f.add(p);
  for (const NamedConfig& c : spec.controllers) f.add(c.name).add(c.json);
  for (const FaultSetting& x : spec.faults) {
    f.add(x.name).add(x.json).add(
        static_cast<std::uint64_t>(x.crossing_obstacle * 4 + x.crossing_final_approach * 2));
    f.add(static_cast<std::uint64_t>(x.unmapped_obstacles));
    if (x.standing_at_dock_s > 0)
      f.add(std::string_view("standing_at_dock_s")).add(x.standing_at_dock_s);
    if (x.charger_map_offset)
      f.add(x.charger_map_offset->x).add(x.charger_map_offset->y).add(x.charger_map_offset->yaw);
  }
  for (std::uint64_t seed : spec.seeds) f.add(seed);
  f.add(static_cast<std::uint64_t>(spec.random_starts));
  std::error_code ec;
  return {f.hex(), episodes,
          std::filesystem::absolute(spec.source, ec).lexically_normal().string()};
}

// A scenario's worlds with their names and content fingerprints; two worlds of one name are
// refused (episode ids name the world).
struct ScenarioWorlds {
  std::vector<worlds::World> worlds;
  std::vector<std::string> names;
  std::vector<std::uint64_t> contents;
};

ScenarioWorlds load_scenario_worlds(const BatchSpec& spec) {
  ScenarioWorlds s;
  for (std::size_t i = 0; i < spec.world_files.size(); ++i) {
    s.worlds.push_back(worlds::load_world(spec.world_files[i]));
    s.names.push_back(s.worlds.back().name);
    s.contents.push_back(worlds::world_fingerprint(s.worlds.back()));
    for (std::size_t k = 0; k < i; ++k)
      if (s.names[k] == s.names[i])
        throw worlds::WorldError(
            spec.source, "worlds[" + std::to_string(i) + "]",
            "a second world named '" + s.names[i] + "' (episode ids name the world; rename one)");
    if (s.names[i].find('|') != std::string::npos)
      throw worlds::WorldError(spec.source, "worlds[" + std::to_string(i) + "]",
                               "the world's name '" + s.names[i] +
                                   "' holds '|', which separates the parts of an episode id");
  }
  for (std::size_t i = 0; i < spec.gate.rules.size(); ++i)
    if (const std::string& w = spec.gate.rules[i].world;
        !w.empty() && std::find(s.names.begin(), s.names.end(), w) == s.names.end())
      throw worlds::WorldError(
          spec.source, "gate.configurations[" + std::to_string(i) + "].world",
          "'" + w + "' is not one of the scenario's worlds: the rule would judge nothing");
  return s;
}

std::string record_line(const Episode& e, const BatchSpec& spec, const ScenarioIdentity& scenario,
                        const worlds::World& plant, const sim::EpisodeResult& r, double optimal_m) {
  const std::string& world_name = plant.name;
  const geom::Pose2& start = plant.start;
  nlohmann::ordered_json j;
  j["index"] = e.index;
  j["id"] = e.id;
  j["scenario"] = scenario.fingerprint;
  j["scenario_episodes"] = scenario.episodes;
  j["scenario_file"] = scenario.file;
  j["world"] = world_name;
  j["planner"] = spec.planners[e.planner];
  j["controller"] = spec.controllers[e.controller].name;
  j["fault"] = spec.faults[e.fault].name;
  if (!spec.faults[e.fault].sweep_parameter.empty()) {
    j["sweep_parameter"] = spec.faults[e.fault].sweep_parameter;
    j["sweep_value"] = spec.faults[e.fault].sweep_value;
  }
  j["seed"] = e.seed;
  j["start"] = {start.x, start.y, start.yaw};
  j["goal"] = plant.target ? "catch" : "dock";
  j["succeeded"] = r.succeeded();
  sim::add_episode_metrics(j, r);
  j["optimal_length_m"] = optimal_m;
  // What a perfect robot drives: the optimum to the staging pose and the straight approach from
  // there to the docked pose, so that driven length is compared with like (issue 37: without the
  // approach every docked episode looked 0.8 to 1 m longer than optimal).
  j["optimal_driven_m"] =
      plant.target ? optimal_m : optimal_m + plant.charger_spec.staging_distance_m;
  // The driven path for the report's overlay of every episode, in millimetres, thinned to a
  // point every 0.5 m (further apart on long drives: at most about 400 points, 3 kB a record).
  auto path = json::array();
  geom::Vec2 last{NAN, NAN};
  const double spacing = std::max(0.5, r.driven_length_m / 400.0);
  for (std::size_t i = 0; i < r.trajectory.size(); ++i) {
    const geom::Vec2 p = r.trajectory[i].truth.position();
    if (i + 1 < r.trajectory.size() && i > 0 && geom::distance(p, last) < spacing) continue;
    path.push_back(std::lround(p.x * 1000));
    path.push_back(std::lround(p.y * 1000));
    last = p;
  }
  j["path_mm"] = path;
  if (!plant.unmapped.empty()) {  // the plant as this episode met it, to replay it
    auto boxes = json::array();
    for (const geom::Rect& u : plant.unmapped) boxes.push_back({u.xmin, u.ymin, u.xmax, u.ymax});
    j["unmapped"] = boxes;
  }
  return j.dump();
}

class Progress {
 public:
  Progress(std::int64_t total, bool enabled)
      : total_(total), enabled_(enabled), tty_(::isatty(2)), t0_(Clock::now()) {}
  void tick() {
    const std::int64_t done = ++done_;
    if (!enabled_) return;
    std::lock_guard lock(mutex_);
    const double elapsed = std::chrono::duration<double>(Clock::now() - t0_).count();
    const bool last = done == total_;
    if (tty_ ? (elapsed - last_print_ < 0.2 && !last)
             : (done * 10 / std::max<std::int64_t>(total_, 1) == printed_decile_ && !last))
      return;
    last_print_ = elapsed;
    printed_decile_ = done * 10 / std::max<std::int64_t>(total_, 1);
    const double rate = done / std::max(elapsed, 1e-9);
    const double eta = (total_ - done) / std::max(rate, 1e-9);
    const int width = 30,
              filled = static_cast<int>(width * done / std::max<std::int64_t>(total_, 1));
    std::fprintf(stderr, "%s[%s%s] %lld/%lld  %.1f episodes/s  ETA %.0f s%s", tty_ ? "\r" : "",
                 std::string(filled, '=').c_str(), std::string(width - filled, ' ').c_str(),
                 static_cast<long long>(done), static_cast<long long>(total_), rate, eta,
                 tty_ && !last ? "" : "\n");
  }

 private:
  using Clock = std::chrono::steady_clock;
  std::int64_t total_;
  bool enabled_, tty_;
  Clock::time_point t0_;
  std::atomic<std::int64_t> done_{0};
  std::mutex mutex_;
  double last_print_ = -1;
  std::int64_t printed_decile_ = -1;
};

/// Everything one episode needs, made the same way for the batch and for replaying one of its
/// episodes: the plant with the episode's start and faults, the settings, the exact optimum.
class EpisodeRunner {
 public:
  EpisodeRunner(const BatchSpec& spec, const std::vector<worlds::World>& worlds,
                const std::vector<std::uint64_t>& contents,
                const std::vector<sim::EpisodeConfig>& configs,
                const sim::EpisodeSteering& steering = {})
      : spec_(spec), worlds_(worlds), contents_(contents), configs_(configs), steering_(steering) {}

  struct Run {
    worlds::World plant;
    sim::EpisodeConfig config;
    sim::EpisodeResult result;
    double optimal_m = 0;
  };

  Run run(const Episode& e) {
    Run out{worlds_[e.world], {}, {}, 0};
    worlds::World& w = out.plant;
    const FaultSetting& fault = spec_.faults[e.fault];
    if (fault.charger_map_offset) w.charger_map_offset = *fault.charger_map_offset;
    planner::Planner& exact = planner_for(w, e.world, "vg", e.fault);
    if (spec_.random_starts) {
      const auto s = random_start(w, exact, e.seed, contents_[e.world]);
      if (!s) throw std::runtime_error(w.name + ": no free start with a path to the charger");
      w.start = *s;
    }
    const planner::PlanResult optimal =
        exact.plan(w.start.position(), worlds::staging_pose(w).position());
    out.config = configs_[e.controller * spec_.faults.size() + e.fault];
    out.config.seed = e.seed;
    if (optimal.status == planner::PlanStatus::kOk) {
      if (fault.unmapped_obstacles > 0)
        w.unmapped = unmapped_across_path(w, optimal.path, fault.unmapped_obstacles,
                                          util::Fingerprint()
                                              .add(contents_[e.world])
                                              .add(e.seed)
                                              .add(std::uint64_t{7919})
                                              .value());
      if (fault.crossing_obstacle) w.moving.push_back(crossing_person(w, optimal.path));
      if (fault.crossing_final_approach)
        w.moving.push_back(final_approach_crosser(w, optimal.length));
      if (fault.standing_at_dock_s > 0)
        w.moving.push_back(person_standing_at_dock(w, optimal.length, fault.standing_at_dock_s));
    }
    out.optimal_m = optimal.length;
    out.result = sim::run_episode(w, planner_for(w, e.world, spec_.planners[e.planner], e.fault),
                                  out.config, steering_);
    return out;
  }

 private:
  // Planners are kept for the runner's life (their caches are not shared between threads). A
  // fault moving the mapped charger has its own (the charger's body is on the map).
  planner::Planner& planner_for(const worlds::World& w, std::size_t world, const std::string& name,
                                std::size_t fault) {
    const std::size_t key = spec_.faults[fault].charger_map_offset ? fault : spec_.faults.size();
    auto& p = planners_[{world, name, key}];
    if (!p) p = planner::make_planner(name, planner::planner_input(w, true));
    return *p;
  }

  const BatchSpec& spec_;
  const std::vector<worlds::World>& worlds_;
  const std::vector<std::uint64_t>& contents_;
  const std::vector<sim::EpisodeConfig>& configs_;
  // A copy: the gallery and the replay pass the default, a temporary that a reference would
  // outlive.
  const sim::EpisodeSteering steering_;
  std::map<std::tuple<std::size_t, std::string, std::size_t>, std::unique_ptr<planner::Planner>>
      planners_;
};

std::vector<sim::EpisodeConfig> episode_configs(const BatchSpec& spec) {
  std::vector<sim::EpisodeConfig> configs;  // controller x fault
  for (const auto& c : spec.controllers)
    for (const auto& f : spec.faults)
      configs.push_back(sim::parse_episode_config(f.json, spec.source,
                                                  sim::parse_episode_config(c.json, spec.source)));
  return configs;
}

/// Replays up to `limit` failed episodes of the records for the report's failure gallery.
std::vector<FailedEpisode> failure_gallery(const std::vector<std::string>& lines,
                                           const BatchSpec& spec, const ScenarioWorlds& loaded,
                                           const std::vector<sim::EpisodeConfig>& configs,
                                           std::size_t limit) {
  // One failure of each reason first, then a second of each, ...: every reason is drawn before
  // any is drawn twice (the report lists every failure).
  std::map<std::string, std::vector<std::string>> by_reason;
  for (const std::string& line : lines) {
    const json j = json::parse(line);
    if (record_succeeded(j)) continue;
    const auto reason = j.find("failure");
    by_reason[reason != j.end() && reason->is_string() ? reason->get<std::string>() : ""].push_back(
        j["id"].get<std::string>());
  }
  std::set<std::string> failed;
  for (std::size_t round = 0; failed.size() < limit; ++round) {
    bool any = false;
    for (const auto& [reason, ids] : by_reason)
      if (round < ids.size() && failed.size() < limit) failed.insert(ids[round]), any = true;
    if (!any) break;
  }
  std::vector<FailedEpisode> out;
  if (failed.empty()) return out;
  EpisodeRunner runner(spec, loaded.worlds, loaded.contents, configs);
  for (const Episode& e : all_episodes(spec, loaded.names))
    if (failed.count(e.id)) {
      EpisodeRunner::Run r = runner.run(e);
      out.push_back({e.id, std::move(r.plant), std::move(r.result), r.config});
    }
  return out;
}

}  // namespace

ReplayedEpisode replay_batch_episode(const std::string& scenario_path, const std::string& id) {
  const BatchSpec spec = load_batch_spec(scenario_path);
  const ScenarioWorlds loaded = load_scenario_worlds(spec);
  const std::vector<sim::EpisodeConfig> configs = episode_configs(spec);
  const std::vector<Episode> all = all_episodes(spec, loaded.names);
  const auto it =
      std::find_if(all.begin(), all.end(), [&](const Episode& e) { return e.id == id; });
  if (it == all.end())
    throw std::invalid_argument(scenario_path + ": no episode '" + id +
                                "' (ids are world|planner|controller|fault|seed, "
                                "as episodes.jsonl records them)");
  EpisodeRunner runner(spec, loaded.worlds, loaded.contents, configs);
  EpisodeRunner::Run r = runner.run(*it);
  return {id, std::move(r.plant), std::move(r.result), r.config};
}

std::pair<double, double> wilson_interval(std::int64_t k, std::int64_t n, double z) {
  if (n <= 0) return {0.0, 1.0};
  const double p = static_cast<double>(k) / n, z2 = z * z;
  const double centre = (p + z2 / (2.0 * n)) / (1 + z2 / n);
  const double half = z * std::sqrt(p * (1 - p) / n + z2 / (4.0 * n * n)) / (1 + z2 / n);
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

std::string summary_csv(const std::vector<std::string>& lines) {
  struct Acc {
    std::int64_t n = 0, succeeded = 0, docked = 0, collisions = 0, retries = 0, trapped = 0,
                 timeouts = 0;
    std::int64_t robot_collisions = 0, localization_not_ok = 0, charging = 0;
    double stops = 0, replans = 0, recoveries = 0;
    double localization_error_max = 0;
    double time = 0, ratio = 0, pos = 0, heading = 0, driven_ratio = 0, local_minima = 0,
           wall_follows = 0;
    std::int64_t ratio_n = 0, driven_n = 0;
    std::array<std::int64_t, robot::kAllFailureReasons.size()>
        failed{};  // per reason, in kAllFailureReasons' order
  };
  std::map<std::tuple<std::string, std::string, std::string, std::string>, Acc> acc;
  for (const std::string& line : lines) {
    const json j = json::parse(line);
    Acc& a = acc[{j["world"], j["planner"], j["controller"], j["fault"]}];
    ++a.n;
    const bool docked = j["docked"].get<bool>();
    a.succeeded += record_succeeded(j);
    a.docked += docked;  // docking errors are means over these
    a.collisions += j["collisions"].get<int>();
    a.retries += j["retries"].get<int>();
    a.time += j["time_s"].get<double>();
    const double opt = j["optimal_length_m"].get<double>(), len = j["path_length_m"].get<double>();
    if (opt > 0 && len > 0) a.ratio += len / opt, ++a.ratio_n;
    if (docked)
      a.pos += j["position_error_m"].get<double>(),
          a.heading += j["heading_error_deg"].get<double>();
    // Driven length over the optimum on success: how far a reactive method wanders.
    const double opt_driven =
        j.value("optimal_driven_m", opt);  // records before it: the plan's optimum
    if (docked && opt_driven > 0)
      a.driven_ratio += j["driven_length_m"].get<double>() / opt_driven, ++a.driven_n;
    a.local_minima += j.value("local_minima", 0);
    a.wall_follows += j.value("wall_follows", 0);
    const std::string status = j["status"].get<std::string>();
    a.trapped += status == "trapped";
    a.timeouts += status == "timeout";
    a.robot_collisions += j.value("collisions_robot_moving", 0);
    a.localization_error_max =
        std::max(a.localization_error_max, j.value("localization_error_max_m", 0.0));
    a.localization_not_ok += j.value("localization_status", std::string("ok")) != "ok";
    a.stops += j.value("stops", 0);
    a.replans += j.value("replans", 0);
    a.recoveries += j.value("recoveries", 0);
    a.charging += j.value("charging", false);
    if (j.contains("failure") && j["failure"].is_string())
      if (const auto reason = robot::failure_reason_from_string(j["failure"].get<std::string>()))
        ++a.failed[static_cast<std::size_t>(*reason)];
  }
  std::string out =
      "world,planner,controller,fault,episodes,succeeded,success_rate,ci95_low,ci95_high,mean_time_"
      "s,"
      "path_over_optimum,mean_position_error_mm,mean_heading_error_deg,collisions,mean_retries,"
      "driven_over_optimum,mean_local_minima,mean_wall_follows,trapped,timeouts,collisions_robot_"
      "moving,"
      "max_localization_error_mm,localization_not_ok,mean_stops,mean_replans,mean_recoveries,"
      "charging";
  for (robot::FailureReason reason : robot::kAllFailureReasons) {
    out += ",failed_";
    out += robot::to_string(reason);
  }
  out += "\n";
  for (const auto& [key, a] : acc) {
    const auto [lo, hi] = wilson_interval(a.succeeded, a.n);
    char row[800];
    std::snprintf(
        row, sizeof row,
        ",%lld,%lld,%.4f,%.4f,%.4f,%.2f,%.4f,%.3f,%.3f,%lld,%.3f,%.4f,%.3f,%.3f,%lld,%lld,%lld,%."
        "2f,%lld,"
        "%.3f,%.3f,%.3f,%lld\n",
        static_cast<long long>(a.n), static_cast<long long>(a.succeeded),
        static_cast<double>(a.succeeded) / a.n, lo, hi, a.time / a.n,
        a.ratio_n ? a.ratio / a.ratio_n : 0.0, a.docked ? 1000 * a.pos / a.docked : 0.0,
        a.docked ? a.heading / a.docked : 0.0, static_cast<long long>(a.collisions),
        static_cast<double>(a.retries) / a.n, a.driven_n ? a.driven_ratio / a.driven_n : 0.0,
        a.local_minima / a.n, a.wall_follows / a.n, static_cast<long long>(a.trapped),
        static_cast<long long>(a.timeouts), static_cast<long long>(a.robot_collisions),
        1000 * a.localization_error_max, static_cast<long long>(a.localization_not_ok),
        a.stops / a.n, a.replans / a.n, a.recoveries / a.n, static_cast<long long>(a.charging));
    std::string failed;
    for (std::int64_t count : a.failed) {
      failed += ',';
      failed += std::to_string(count);
    }
    std::string line(row, std::strlen(row) - 1);  // without its newline
    line += failed + "\n";
    out += util::csv_field(std::get<0>(key)) + "," + util::csv_field(std::get<1>(key)) + "," +
           util::csv_field(std::get<2>(key)) + "," + util::csv_field(std::get<3>(key)) + line;
  }
  return out;
}

std::string sweep_csv(const std::vector<std::string>& lines) {
  struct Acc {
    std::int64_t n = 0, docked = 0, charging = 0, collisions = 0, robot_collisions = 0,
                 failed_with_collision = 0;
    std::int64_t stops = 0, replans = 0;
    double time = 0, pos = 0;
  };
  std::string parameter;
  std::vector<std::string> order;  // values as first met
  std::map<std::string, Acc> acc;
  for (const std::string& line : lines) {
    const json j = json::parse(line);
    if (!j.contains("sweep_parameter")) continue;
    parameter = j["sweep_parameter"].get<std::string>();
    const std::string value = j["sweep_value"].get<std::string>();
    if (!acc.count(value)) order.push_back(value);
    Acc& a = acc[value];
    ++a.n;
    const bool docked = j["docked"].get<bool>();
    const int collisions = j["collisions"].get<int>();
    a.docked += docked;
    a.charging += j.value("charging", false);
    a.collisions += collisions;
    a.robot_collisions += j.value("collisions_robot_moving", 0);
    a.failed_with_collision += !docked && collisions > 0;
    a.stops += j.value("stops", 0);
    a.replans += j.value("replans", 0);
    a.time += j["time_s"].get<double>();
    if (docked) a.pos += j["position_error_m"].get<double>();
  }
  if (order.empty()) return "";
  // Numeric values in increasing order, so that the rows trace a curve.
  auto numeric = [](const std::string& s, double& v) {
    char* end = nullptr;
    v = std::strtod(s.c_str(), &end);
    return end && *end == '\0' && end != s.c_str();
  };
  double x = 0, y = 0;
  if (std::all_of(order.begin(), order.end(), [&](const std::string& s) { return numeric(s, x); }))
    std::stable_sort(order.begin(), order.end(), [&](const std::string& a, const std::string& b) {
      numeric(a, x);
      numeric(b, y);
      return x < y;
    });
  std::string out =
      "parameter,value,episodes,docked,success_rate,ci95_low,ci95_high,charging,collisions,"
      "collisions_robot_moving,"
      "failed_with_collision,mean_stops,mean_replans,mean_time_s,mean_position_error_mm\n";
  for (const std::string& value : order) {
    const Acc& a = acc[value];
    const auto [lo, hi] = wilson_interval(a.docked, a.n);
    char row[600];
    std::snprintf(row, sizeof row,
                  ",%lld,%lld,%.4f,%.4f,%.4f,%lld,%lld,%lld,%lld,%.3f,%.3f,%.2f,%.3f\n",
                  static_cast<long long>(a.n), static_cast<long long>(a.docked),
                  static_cast<double>(a.docked) / a.n, lo, hi, static_cast<long long>(a.charging),
                  static_cast<long long>(a.collisions), static_cast<long long>(a.robot_collisions),
                  static_cast<long long>(a.failed_with_collision),
                  static_cast<double>(a.stops) / a.n, static_cast<double>(a.replans) / a.n,
                  a.time / a.n, a.docked ? 1000 * a.pos / a.docked : 0.0);
    out += util::csv_field(parameter) + "," + util::csv_field(value) + row;
  }
  return out;
}

std::vector<std::string> read_episode_records(const std::string& dir) {
  return read_records(dir + "/episodes.jsonl");
}

BatchOutcome run_batch(const std::string& scenario_path, const RunOptions& o) {
  // Everything that can be wrong is found before the first episode.
  BatchSpec spec = load_batch_spec(scenario_path);
  if (o.steering)
    for (NamedConfig& c : spec.controllers) c.name += "+" + o.steering.name;
  if (o.shard_count < 1 || o.shard_index < 0 || o.shard_index >= o.shard_count)
    throw std::invalid_argument("--shard i/n needs 0 <= i < n");
  const ScenarioWorlds loaded = load_scenario_worlds(spec);
  const std::vector<worlds::World>& worlds = loaded.worlds;
  const std::vector<std::string>& names = loaded.names;
  const std::vector<std::uint64_t>& contents = loaded.contents;
  // A charger offset must leave the mapped charger dockable on every world it is applied to.
  for (const FaultSetting& f : spec.faults) {
    if (!f.charger_map_offset) continue;
    for (worlds::World w : worlds) {
      w.charger_map_offset = *f.charger_map_offset;
      try {
        worlds::validate_world(w);
      } catch (const worlds::WorldError& e) {
        throw worlds::WorldError(spec.source, "faults." + f.name + ".charger_map_offset",
                                 "on " + w.name + ": " + e.what());
      }
    }
  }
  const std::vector<sim::EpisodeConfig> configs = episode_configs(spec);
  const std::vector<Episode> all = all_episodes(spec, names);
  const ScenarioIdentity scenario =
      scenario_identity(spec, contents, names, static_cast<std::int64_t>(all.size()));
  // The work is bounded before it starts: the physics steps this shard may ask for.
  double steps = 0;
  for (const Episode& e : shard(all, o.shard_index, o.shard_count)) {
    const sim::EpisodeConfig& c = configs[e.controller * spec.faults.size() + e.fault];
    steps += std::ceil(c.timeout_s / c.step.dt_s);
  }
  if (steps > kMaxBatchSteps)
    throw std::invalid_argument(
        scenario_path + ": this run asks for " + std::to_string(static_cast<long long>(steps)) +
        " physics steps (timeout_s / step.dt_s summed over its episodes), more than the limit of "
        "1e10 "
        "(docs/batch.md): fewer episodes, shorter timeouts, or shards (--shard i/n)");
  if (o.check_only) {
    BatchOutcome checked;
    checked.episodes = static_cast<std::int64_t>(shard(all, o.shard_index, o.shard_count).size());
    checked.gate = spec.gate;
    checked.scenario_fingerprint = scenario.fingerprint;
    return checked;
  }

  check_batch_output_folder(o.out_dir, o.own_files);
  std::error_code ec;
  std::filesystem::create_directories(o.out_dir, ec);
  if (ec || !std::filesystem::is_directory(o.out_dir))
    throw std::invalid_argument("output folder '" + o.out_dir + "' cannot be created" +
                                (ec ? ": " + ec.message() : ""));
  const util::FolderLock lock(o.out_dir);  // one batch per folder, or both run every episode
  check_batch_output_folder(o.out_dir,
                            o.own_files);  // again, now that no other plantsim writes here
  const std::string jsonl = o.out_dir + "/episodes.jsonl";
  if (o.fresh) std::filesystem::remove(jsonl, ec);
  // Resume keeps the records of this scenario's episodes, once each; the rest run again. Read
  // as a stream: memory grows with the records kept, not with the file.
  // By id: an episode's index depends on the order of the scenario's lists, its id does not.
  std::set<std::string_view> ids;
  for (const Episode& e : all) ids.insert(e.id);
  std::vector<std::string> existing;
  std::set<std::string> done;
  std::int64_t foreign = 0;
  const JsonlScan scan = scan_jsonl(jsonl, [&](std::string&& line) {
    const json j = json::parse(line);
    const std::string theirs = j["scenario"].get<std::string>();
    if (theirs != scenario.fingerprint)
      throw std::invalid_argument("output folder '" + o.out_dir +
                                  "' holds episodes of another scenario (fingerprint " + theirs +
                                  ", this one " + scenario.fingerprint +
                                  "): choose another --out, or --fresh to discard them");
    const std::string id = j["id"].get<std::string>();
    if (!ids.count(id) || !done.insert(id).second) {
      ++foreign;  // not one of this scenario's episodes, or a second copy
      return;
    }
    existing.push_back(std::move(line));
  });
  BatchOutcome outcome;
  outcome.gate = spec.gate;
  outcome.scenario_fingerprint = scenario.fingerprint;
  if (scan.bad_lines > 0 || scan.torn_tail || foreign > 0) {
    // Resume keeps what it can use and reruns the rest; the file is rewritten without them.
    outcome.malformed_lines_cut = scan.bad_lines + scan.torn_tail + foreign;
    std::string kept;
    for (const std::string& line : existing) kept += line + "\n";
    util::write_file_atomically(jsonl, kept);
    std::fprintf(stderr,
                 "batch: warning: cut %lld malformed, unfinished, repeated or foreign line(s) from "
                 "%s; their episodes run again\n",
                 static_cast<long long>(outcome.malformed_lines_cut), jsonl.c_str());
  }

  const std::vector<Episode> mine = shard(all, o.shard_index, o.shard_count);
  std::vector<Episode> todo;
  for (const Episode& e : mine)
    if (!done.count(e.id)) todo.push_back(e);

  outcome.episodes = static_cast<std::int64_t>(mine.size());
  outcome.skipped = outcome.episodes - static_cast<std::int64_t>(todo.size());
  // Appended to, never through a link (the folder was checked; O_NOFOLLOW closes the race).
  const int out_fd =
      ::open(jsonl.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0644);
  std::FILE* out = out_fd >= 0 ? ::fdopen(out_fd, "ab") : nullptr;
  if (!out) {
    if (out_fd >= 0) ::close(out_fd);
    throw std::invalid_argument(util::system_error_text("cannot append to " + jsonl));
  }
  std::mutex write_mutex;
  std::atomic<std::size_t> next{0};
  Progress progress(static_cast<std::int64_t>(todo.size()), o.progress);
  std::exception_ptr failure;
  const int threads = o.threads > 0 ? o.threads : std::max(1u, std::thread::hardware_concurrency());
  auto worker = [&]() {
    EpisodeRunner runner(spec, worlds, contents, configs, o.steering);
    try {
      for (std::size_t k = next++; k < todo.size(); k = next++) {
        const Episode& e = todo[k];
        const EpisodeRunner::Run run = runner.run(e);
        const sim::EpisodeResult& r = run.result;
        const std::string line = record_line(e, spec, scenario, run.plant, r, run.optimal_m) + "\n";
        {
          std::lock_guard lock(write_mutex);
          // A killed batch loses at most the episode being written; a full disk stops the batch
          // at once instead of simulating episodes whose lines are lost.
          if (std::fwrite(line.data(), 1, line.size(), out) != line.size() || std::fflush(out) != 0)
            throw std::runtime_error(util::system_error_text("cannot append to " + jsonl));
          ++outcome.ran;
          outcome.succeeded += r.succeeded();
          outcome.collisions += r.collisions;
        }
        progress.tick();
      }
    } catch (...) {
      std::lock_guard lock(write_mutex);
      if (!failure) failure = std::current_exception();
      next = todo.size();
    }
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  const bool synced = ::fsync(::fileno(out)) == 0 || errno == EINVAL;
  const std::string sync_error = synced ? "" : util::system_error_text("cannot sync " + jsonl);
  if (std::fclose(out) != 0 && !failure)
    throw std::runtime_error(util::system_error_text("cannot close " + jsonl));
  if (failure) std::rethrow_exception(failure);
  if (!synced) throw std::runtime_error(sync_error);

  const std::vector<std::string> records = read_records(jsonl);
  const std::vector<FailedEpisode> failures =
      o.figures ? failure_gallery(records, spec, loaded, configs, kGalleryEpisodes)
                : std::vector<FailedEpisode>{};
  write_batch_report(records, o.out_dir, "plantsim batch: " + spec.name,
                     "plantsim batch " + scenario_path + " --out " + o.out_dir +
                         (o.shard_count > 1 ? " --shard " + std::to_string(o.shard_index) + "/" +
                                                  std::to_string(o.shard_count)
                                            : ""),
                     o.figures ? &worlds : nullptr, spec.planners, o.gate.applied_to(spec.gate),
                     o.figures, failures, scenario_path);
  return outcome;
}

MergeOutcome merge_batches(const std::vector<std::string>& dirs, const std::string& out_dir,
                           const MergeOptions& options) {
  check_batch_output_folder(
      out_dir, options.own_files);  // before any work: never a user's folder, never through a link
  std::map<std::string, std::pair<std::int64_t, std::string>> by_id;  // id -> (index, line)
  std::string fingerprint, first_dir, scenario_file;
  std::int64_t expected = 0;
  for (const std::string& d : dirs) {
    const std::string path = d + "/episodes.jsonl";
    if (!std::filesystem::exists(std::filesystem::symlink_status(path)))
      throw std::invalid_argument(d + ": no episodes.jsonl to merge");
    const JsonlScan scan = scan_jsonl(path, [&](std::string&& line) {
      const json j = json::parse(line);
      const std::string theirs = j["scenario"].get<std::string>();
      if (fingerprint.empty()) {
        fingerprint = theirs, first_dir = d;
        expected = j.value("scenario_episodes", std::int64_t{0});
        scenario_file = j.value("scenario_file", std::string());
      } else if (theirs != fingerprint) {
        throw std::invalid_argument("cannot merge episodes of different scenarios: " + first_dir +
                                    " holds scenario " + fingerprint + ", " + d + " holds " +
                                    theirs);
      }
      const std::string id = j["id"].get<std::string>();
      const std::int64_t index = j["index"].get<std::int64_t>();
      if (index < 0 || index >= expected)
        throw std::invalid_argument("merge: " + path + " holds episode '" + id + "' with index " +
                                    std::to_string(index) + ", outside the scenario's " +
                                    std::to_string(expected) + " episodes");
      const auto [at, fresh] = by_id.try_emplace(id, index, line);
      // The same episode from a run whose lists were ordered otherwise differs in its index and
      // scenario file only; anything else is a different result.
      auto result_of = [](const std::string& record) {
        json r = json::parse(record);
        r.erase("index"), r.erase("scenario_file");
        return r;
      };
      if (!fresh && at->second.second != line && result_of(at->second.second) != result_of(line))
        throw std::invalid_argument("merge: episode '" + id +
                                    "' appears twice with different results (" + path +
                                    " and an earlier folder); shards of one batch never disagree: "
                                    "merge each run's shards apart");
    });
    if (scan.bad_lines > 0)
      std::fprintf(stderr, "merge: warning: %s has %lld malformed line(s), left out\n",
                   path.c_str(), static_cast<long long>(scan.bad_lines));
  }
  if (by_id.empty()) throw std::invalid_argument("nothing to merge: the folders hold no episodes");
  const auto merged = static_cast<std::int64_t>(by_id.size());
  // The figures need the worlds, and the ids are checked against the scenario's own: both from
  // the scenario file when it is still there and unchanged.
  std::vector<worlds::World> worlds;
  std::vector<std::string> planners;
  MergeOutcome outcome;
  std::vector<Episode> scenario_episodes;
  std::error_code ec;
  if (!scenario_file.empty() && std::filesystem::exists(scenario_file, ec)) {
    try {
      const BatchSpec spec = load_batch_spec(scenario_file);
      ScenarioWorlds loaded = load_scenario_worlds(spec);
      if (scenario_identity(spec, loaded.contents, loaded.names, expected).fingerprint ==
          fingerprint) {
        worlds = std::move(loaded.worlds);
        planners = spec.planners;
        outcome.gate = spec.gate;
        scenario_episodes = all_episodes(spec, loaded.names);
      }
    } catch (const std::exception&) {
      worlds.clear();
    }
  }
  // Ids are checked against the scenario's own when its file is there (else only their count).
  std::set<std::string_view> scenario_ids;
  for (const Episode& e : scenario_episodes) scenario_ids.insert(e.id);
  if (!scenario_ids.empty())
    for (const auto& [id, entry] : by_id)
      if (!scenario_ids.count(id))
        throw std::invalid_argument("merge: episode '" + id +
                                    "' is not one of the scenario's episodes (" + scenario_file +
                                    "): a record of another run");
  if (worlds.empty())
    std::fprintf(
        stderr,
        "merge: note: the scenario file %s is gone or changed; the report has no plan figures\n",
        scenario_file.c_str());
  if (merged < expected && !options.allow_partial) {
    std::string missing;
    int named = 0;
    for (const Episode& e : scenario_episodes)
      if (named < 5 && !by_id.count(e.id)) missing += (named++ ? ", " : " (") + e.id;
    if (named > 0) missing += expected - merged > named ? ", ...)" : ")";
    throw IncompleteBatch(
        "merge: " + std::to_string(expected - merged) + " of the scenario's " +
        std::to_string(expected) + " episodes are missing" + missing +
        " (a shard not run or not finished?); rerun them, or pass --allow-partial");
  }
  std::vector<std::pair<std::int64_t, std::string>> ordered;
  for (auto& [id, entry] : by_id) ordered.push_back(entry);
  std::sort(ordered.begin(), ordered.end());
  std::string text;
  std::vector<std::string> lines;
  for (const auto& [index, line] : ordered) {
    text += line + "\n";
    lines.push_back(line);
  }
  outcome.episodes = merged;
  outcome.expected = expected;
  std::filesystem::create_directories(out_dir, ec);
  if (ec || !std::filesystem::is_directory(out_dir))
    throw std::invalid_argument("cannot create output folder '" + out_dir + "'");
  const util::FolderLock lock(out_dir);
  util::write_file_atomically(out_dir + "/episodes.jsonl", text);
  std::string command = "plantsim merge";
  for (const auto& d : dirs) command += " " + d;
  write_batch_report(
      lines, out_dir, "plantsim merge",
      command + " --out " + out_dir + (options.allow_partial ? " --allow-partial" : ""),
      worlds.empty() ? nullptr : &worlds, planners, options.gate.applied_to(outcome.gate), true);
  return outcome;
}

}  // namespace plantsim::batch
