// What `plantsim tune` searches and how it judges: the scenario's tuning part (its `worlds` and
// `seeds`, exactly what `plantsim batch` runs of it), its held-out validation part
// (`tune.validation_worlds` and `tune.validation_seeds`), the parameters with their search bounds,
// the objective, the budget and the optimiser. Everything is checked before any episode runs.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "batch/batch_spec.h"
#include "episode/episode_config_json.h"
#include "tune/objective.h"

namespace plantsim::tune {

/// One searched parameter: what docs/config.md says of it and the bounds searched within.
struct TunedParameter {
  episode::NumberParameter info;
  double lo = 0, hi = 0;
};

/// The optimisers: NLopt's local subplex (the default), BOBYQA and Nelder-Mead, and its global
/// CRS2 and ISRES; every one over the parameters scaled to [0, 1].
enum class Method { kSbplx, kSbplxStarts, kBobyqa, kNelderMead, kCrs2, kIsres };
std::string method_name(Method m);

/// What the command line (or plantsim.tune) asks; unset fields come from the scenario's `tune:`.
struct TuneRequest {
  std::string scenario;
  std::vector<std::string> parameters;  ///< "KEY=LOW:HIGH"
  std::optional<int> budget;
  std::optional<std::string> objective, method;
  std::optional<double> min_wilson;
  std::uint64_t seed = 1;
  int threads = 0;  ///< 0: one per core
};

struct TuneSpec {
  std::string scenario;  ///< the YAML file
  batch::BatchSpec tuning, validation;
  std::vector<TunedParameter> parameters;
  Objective objective = Objective::kSuccessThenTime;
  /// The constrained objectives' floor on the tuning episodes' Wilson low; unset: the default
  /// settings' own.
  std::optional<double> min_wilson;
  int budget = 60;  ///< evaluations for the optimiser, and as many for random search
  Method method = Method::kSbplx;
  std::uint64_t seed = 1;
  int threads = 0;
};

/// The searched parameters when neither the command line nor the scenario names any: pure
/// pursuit's speed and look-ahead and the docking approach's speed (docs/tune.md).
std::vector<std::string> default_parameters();

/// Throws std::invalid_argument or worlds::WorldError naming the file, field or option.
TuneSpec load_tune_spec(const TuneRequest& request);

}  // namespace plantsim::tune
