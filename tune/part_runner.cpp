// Running a part's episodes for one candidate on every core.
#include "tune/part_runner.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <nlohmann/json.hpp>
#include <thread>

#include "batch/episode_runner.h"
#include "batch/episode_space.h"
#include "episode/episode_config_json.h"
#include "episode/episode_work.h"
#include "util/thread_team.h"

namespace plantsim::tune {

std::string overrides_json(const std::vector<TunedParameter>& parameters,
                           const std::vector<double>& values) {
  nlohmann::json j = nlohmann::json::object();
  for (std::size_t i = 0; i < parameters.size() && i < values.size(); ++i) {
    const std::string& path = parameters[i].info.path;
    const std::size_t dot = path.find('.');
    nlohmann::json& slot =
        dot == std::string::npos ? j[path] : j[path.substr(0, dot)][path.substr(dot + 1)];
    if (parameters[i].info.whole)
      slot = static_cast<long long>(std::llround(values[i]));
    else
      slot = values[i];
  }
  return j.dump();
}

PartRunner::PartRunner(const batch::BatchSpec& spec, int threads)
    : spec_(spec),
      loaded_(batch::load_scenario_worlds(spec_)),
      threads_(threads > 0 ? threads
                           : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()))) {
  batch::check_charger_offsets(spec_, loaded_.worlds);
  const batch::EpisodeSpace space(spec_, loaded_.names);
  identity_ = batch::scenario_identity(spec_, loaded_.contents, loaded_.names, space.size());
  if (space.size() > 1000000)
    throw std::invalid_argument(spec_.source + ": a tuning part of more than 1000000 episodes");
  episodes_ = space.shard(0, 1);
  for (const batch::Episode& e : episodes_) ids_.push_back(e.id);
  for (const episode::EpisodeConfig& c : batch::episode_configs(spec_)) {
    timeout_s_ = std::max(timeout_s_, c.timeout_s);
    for (const worlds::World& w : loaded_.worlds) episode::check_episode_work(w, c);
  }
}

std::vector<EpisodeOutcome> PartRunner::run(const std::string& overrides,
                                            const std::function<bool()>& interrupted) const {
  batch::BatchSpec spec = spec_;
  const nlohmann::json patch = nlohmann::json::parse(overrides);
  for (batch::NamedConfig& c : spec.controllers) {
    nlohmann::json merged = nlohmann::json::parse(c.json);
    merged.merge_patch(patch);
    c.json = merged.dump();
  }
  std::vector<episode::EpisodeConfig> configs;
  try {
    configs = batch::episode_configs(spec);
  } catch (const std::exception& e) {
    throw std::invalid_argument(e.what());
  }
  std::vector<EpisodeOutcome> out(episodes_.size());
  std::atomic<std::size_t> next{0};
  std::mutex failure_mutex;
  std::exception_ptr failure;
  auto worker = [&]() {
    try {
      batch::EpisodeRunner runner(spec, loaded_.worlds, loaded_.contents, configs);
      for (std::size_t k = next++; k < episodes_.size(); k = next++) {
        if (interrupted && interrupted())
          throw TuneInterrupted("the tuning was interrupted; its finished evaluations are kept");
        const episode::EpisodeResult r = runner.run(episodes_[k]).result;
        EpisodeOutcome& o = out[k];
        o.id = ids_[k];
        o.succeeded = r.succeeded();
        o.time_s = r.time_s;
        o.position_error_m = r.docked ? r.position_error_m : 0.0;
        o.contacts = r.collisions;
      }
    } catch (...) {
      std::lock_guard lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      next = episodes_.size();
    }
  };
  util::run_on_threads(threads_, worker);
  if (failure) std::rethrow_exception(failure);
  return out;
}

}  // namespace plantsim::tune
