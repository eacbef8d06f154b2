// A scenario's episodes without listing them: the cross product worlds x planners x controllers
// x faults x seeds, each episode computed from its index and found from its id, so that a run
// (one shard) holds its own episodes only, whatever the scenario's total.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "batch/batch_spec.h"

namespace plantsim::batch {

class EpisodeSpace {
 public:
  /// `spec` must outlive the space.
  EpisodeSpace(const BatchSpec& spec, std::vector<std::string> world_names);

  std::int64_t size() const { return size_; }
  /// The episode at `index` (0 <= index < size()): seeds vary fastest, then faults,
  /// controllers, planners and worlds.
  Episode at(std::int64_t index) const;
  /// The index of the episode whose id is `id`, or none when the scenario has no such episode.
  std::optional<std::int64_t> find(const std::string& id) const;
  /// How many episodes shard i of n runs (those whose index is i modulo n).
  std::int64_t shard_size(int i, int n) const;
  /// Shard i of n; refuses (std::invalid_argument) more than kMaxEpisodes in one run.
  std::vector<Episode> shard(int i, int n) const;

 private:
  const BatchSpec& spec_;
  std::vector<std::string> world_names_;
  std::int64_t size_ = 0;
  std::unordered_map<std::string, std::size_t> world_, planner_, controller_, fault_;
  std::unordered_map<std::uint64_t, std::size_t> seed_;
};

}  // namespace plantsim::batch
