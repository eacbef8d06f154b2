// A batch scenario (YAML): worlds x planners x controller settings x fault settings x seeds.
// Each combination is one episode with a stable id, so that shards, resumes and merges agree
// on what has been done. Everything is checked before any episode runs.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "episode/episode_config.h"
#include "episode/episode_result.h"
#include "worlds/world.h"

namespace plantsim::batch {

struct NamedConfig {
  std::string name;
  std::string json;  ///< episode-config overrides (docs/config.md), "{}" for none
};

/// A fault: episode-config overrides, and changes to the plant that make it differ from the map.
struct FaultSetting {
  std::string name;
  std::string json;                ///< episode-config overrides (noise, slip, detection noise)
  bool crossing_obstacle = false;  ///< a person crosses the planned path as the robot arrives
  bool crossing_final_approach = false;  ///< a person crosses the final approach as the robot docks
  double standing_at_dock_s = 0;  ///< a person stands on the final approach until this long after
                                  ///< the robot could reach the staging pose (0: nobody)
  int unmapped_obstacles = 0;     ///< boxes the map lacks, placed across the optimal path
  std::optional<geom::Pose2> charger_map_offset;  ///< the charger's mapped pose minus its real one
  /// `random_kidnap`: each episode's robot is lifted at a time drawn from [after_s] and set down
  /// at a distance drawn from [distance_m] on free floor, any heading (sim/kidnap_landing.h).
  struct RandomKidnap {
    double after_min_s = 0, after_max_s = 0;
    double distance_min_m = 0, distance_max_m = 0;
  };
  std::optional<RandomKidnap> random_kidnap;
  std::string sweep_parameter, sweep_value;  ///< when the fault is one value of a sweep
};

/// What a configuration's success is judged by: its success rate, or the lower end of its 95 %
/// Wilson interval (stricter on few episodes: 10 of 10 gives 0.72).
enum class GateStatistic { kSuccessRate, kWilsonLow };

/// A threshold for the configurations matching every name given (empty matches any).
struct GateRule {
  std::string world, planner, controller, fault;
  double min_success = 0;
};

/// The scenario's pass criteria (`gate:`): a default threshold for every configuration and
/// rules for some; the last matching rule wins over the default.
struct Gate {
  std::optional<double> min_success;
  GateStatistic statistic = GateStatistic::kSuccessRate;
  /// `pool: worlds`: judge each planner x controller x fault over all worlds together (a
  /// requirement on a kind of plant, not on each one), as world "all worlds".
  bool pool_worlds = false;
  std::vector<GateRule> rules;
};

/// What the command line changes in a scenario's gate (--min-success, --gate-statistic).
struct GateOverride {
  std::optional<double> min_success;
  std::optional<GateStatistic> statistic;
  Gate applied_to(Gate gate) const {
    if (min_success) gate.min_success = min_success;
    if (statistic) gate.statistic = *statistic;
    return gate;
  }
};

/// Episodes one run (a shard, or a merge) may make: its list and ids are held in memory (about
/// 200 MB at the limit). The scenario's episodes are never listed whole (batch/episode_space.h).
inline constexpr std::int64_t kMaxEpisodes = 1000000;
/// Episodes a scenario may make (worlds x planners x controllers x faults x seeds): more is a
/// typo in a list, not a batch.
inline constexpr double kMaxScenarioEpisodes = 1e12;
/// Physics steps one batch run (a shard) may ask for, the sum over its episodes of timeout_s /
/// step.dt_s: 1e10 is about two days of this 2-core machine; split larger batches into shards.
inline constexpr double kMaxBatchSteps = 1e10;

struct BatchSpec {
  std::string name;
  std::string source;  ///< the YAML file
  std::vector<std::string> world_files;
  std::vector<std::string> planners;
  std::vector<NamedConfig> controllers;
  std::vector<std::string> plugin_files;  ///< `plugins:`, loaded when the scenario was read
  std::vector<FaultSetting>
      faults;                   ///< after expanding the sweep, if any (one per value and fault)
  std::string sweep_parameter;  ///< the swept parameter, or empty
  std::vector<std::uint64_t> seeds;
  bool random_starts = true;  ///< each seed draws a free start; else the world's start
  Gate gate;
};

/// The world name pooled verdicts carry.
inline constexpr const char* kAllWorlds = "all worlds";

/// "success_rate" or "wilson_low"; throws std::invalid_argument naming `where`.
GateStatistic parse_gate_statistic(const std::string& text, const std::string& where);

struct Episode {
  std::int64_t index = 0;  ///< position in the full cross product
  std::string id;          ///< "world|planner|controller|fault|seed"
  std::size_t world = 0, planner = 0, controller = 0, fault = 0;
  std::uint64_t seed = 0;
};

/// Throws worlds::WorldError naming the file and field.
BatchSpec load_batch_spec(const std::string& path);

}  // namespace plantsim::batch
