// Running one episode of a scenario (see the header).
#include "batch/episode_runner.h"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>

#include "batch/batch_gate.h"
#include "batch/episode_space.h"
#include "batch/plant_faults.h"
#include "batch/random_start.h"
#include "batch/shortest_possible.h"
#include "episode/run_episode.h"
#include "util/fingerprint.h"

namespace plantsim::batch {

using nlohmann::json;

EpisodeRunner::Run EpisodeRunner::run(const Episode& e) {
  Run out = prepare(e);
  out.result = episode::run_episode(
      out.plant, planner_for(out.plant, e.world, spec_.planners[e.planner], e.fault), out.config,
      steering_);
  if (out.result.docked)
    out.shortest_possible_m = shortest_possible(out.plant, e.world, out.result);
  return out;
}

std::optional<double> EpisodeRunner::shortest_possible(const worlds::World& plant,
                                                       std::size_t world,
                                                       const episode::EpisodeResult& r) {
  if (r.trajectory.empty()) return std::nullopt;
  std::unique_ptr<planner::Planner> own;
  planner::Planner* bound = nullptr;
  if (plant.unmapped.empty()) {
    auto& kept = bound_planners_[world];
    if (!kept) kept = planner::make_planner("vg", shortest_possible_input(plant));
    bound = kept.get();
  } else {
    own = planner::make_planner("vg", shortest_possible_input(plant));
    bound = own.get();
  }
  return shortest_possible_m(*bound, plant.start, r.carries, r.trajectory.back().truth.position());
}

EpisodeRunner::Run EpisodeRunner::prepare(const Episode& e) {
  Run out{worlds_[e.world], {}, {}, 0, std::nullopt};
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
  if (fault.random_kidnap) {
    // The time from the episode's own stream; where it lands, in the episode from its seed.
    const FaultSetting::RandomKidnap& k = *fault.random_kidnap;
    const std::uint64_t draw =
        util::Fingerprint().add(contents_[e.world]).add(e.seed).add(std::uint64_t{104729}).value();
    const double u = static_cast<double>(draw >> 11) * 0x1.0p-53;
    out.config.kidnap.at_s = k.after_min_s + u * (k.after_max_s - k.after_min_s);
    out.config.kidnap.distance_min_m = k.distance_min_m;
    out.config.kidnap.distance_max_m = k.distance_max_m;
  }
  if (optimal.status == planner::PlanStatus::kOk) {
    if (fault.unmapped_obstacles > 0)
      w.unmapped = unmapped_across_path(
          w, optimal.path, fault.unmapped_obstacles,
          util::Fingerprint().add(contents_[e.world]).add(e.seed).add(std::uint64_t{7919}).value());
    if (fault.crossing_obstacle) w.moving.push_back(crossing_person(w, optimal.path));
    if (fault.crossing_final_approach)
      w.moving.push_back(final_approach_crosser(w, optimal.length));
    if (fault.standing_at_dock_s > 0)
      w.moving.push_back(person_standing_at_dock(w, optimal.length, fault.standing_at_dock_s));
  }
  out.optimal_m = optimal.length;
  return out;
}

std::vector<FailedEpisode> failure_gallery(const std::vector<std::string>& lines,
                                           const BatchSpec& spec, const ScenarioWorlds& loaded,
                                           const std::vector<episode::EpisodeConfig>& configs,
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
  const EpisodeSpace all(spec, loaded.names);
  std::vector<std::int64_t> indices;  // in the scenario's order, as the records
  for (const std::string& id : failed)
    if (const auto index = all.find(id)) indices.push_back(*index);
  std::sort(indices.begin(), indices.end());
  for (const std::int64_t index : indices) {
    const Episode e = all.at(index);
    EpisodeRunner::Run r = runner.run(e);
    out.push_back({e.id, std::move(r.plant), std::move(r.result), r.config});
  }
  return out;
}

ReplayedEpisode replay_batch_episode(const std::string& scenario_path, const std::string& id) {
  const BatchSpec spec = load_batch_spec(scenario_path);
  const ScenarioWorlds loaded = load_scenario_worlds(spec);
  const std::vector<episode::EpisodeConfig> configs = episode_configs(spec);
  const std::optional<std::int64_t> index = EpisodeSpace(spec, loaded.names).find(id);
  if (!index)
    throw std::invalid_argument(scenario_path + ": no episode '" + id +
                                "' (ids are world|planner|controller|fault|seed, "
                                "as episodes.jsonl records them)");
  EpisodeRunner runner(spec, loaded.worlds, loaded.contents, configs);
  EpisodeRunner::Run r = runner.run(EpisodeSpace(spec, loaded.names).at(*index));
  return {id, std::move(r.plant), std::move(r.result), r.config};
}

}  // namespace plantsim::batch
