// One part of a tuning (its tuning or its validation episodes) run with a candidate's values:
// the same episodes every time (worlds, starts, seeds, faults), so that two candidates differ by
// their parameters and not by their luck (common random numbers).
#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "batch/batch_spec.h"
#include "batch/scenario_setup.h"
#include "tune/objective.h"
#include "tune/tune_spec.h"

namespace plantsim::tune {

/// The candidate's values as episode-config overrides: {"tracking": {"max_linear_speed_mps": 0.9}}
/// (whole-number parameters written as whole numbers).
std::string overrides_json(const std::vector<TunedParameter>& parameters,
                           const std::vector<double>& values);

/// A tuning stopped by its `interrupted` poll: the evaluations finished before it are on disk, the
/// next run reads them back.
class TuneInterrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class PartRunner {
 public:
  /// Loads the part's worlds (throws worlds::WorldError naming a bad one).
  PartRunner(const batch::BatchSpec& spec, int threads);

  /// The part's episodes run with `overrides` over every controller's settings (faults keep
  /// theirs over them), in the part's order. Throws std::invalid_argument when the settings
  /// contradict each other (a look-ahead minimum above its maximum).
  /// `interrupted`, polled between episodes, stops the run (TuneInterrupted).
  std::vector<EpisodeOutcome> run(const std::string& overrides,
                                  const std::function<bool()>& interrupted = {}) const;

  const std::vector<std::string>& ids() const { return ids_; }
  const batch::BatchSpec& spec() const { return spec_; }
  const batch::ScenarioWorlds& worlds() const { return loaded_; }
  /// The longest episode timeout of the part's settings (bounds a mean time).
  double timeout_s() const { return timeout_s_; }
  /// The scenario fingerprint of the part (ties the records to what made them).
  const std::string& fingerprint() const { return identity_.fingerprint; }

 private:
  batch::BatchSpec spec_;
  batch::ScenarioWorlds loaded_;
  std::vector<batch::Episode> episodes_;
  std::vector<std::string> ids_;
  batch::ScenarioIdentity identity_;
  double timeout_s_ = 0;
  int threads_ = 1;
};

}  // namespace plantsim::tune
