// The two searches a tuning runs with the same budget: NLopt's optimiser over the parameters
// scaled to [0, 1], started from the current settings, and uniform random search (the baseline).
// Both ask an evaluator for scores; neither knows what an episode is.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "tune/tune_spec.h"

namespace plantsim::tune {

/// Scores the candidate `values` (in the parameters' units) as evaluation `index` of `search`;
/// higher is better.
using Evaluator =
    std::function<double(const char* search, int index, const std::vector<double>& values)>;

/// The parameters' values of a point of the unit cube (whole numbers rounded).
std::vector<double> unscaled(const std::vector<TunedParameter>& parameters,
                             const std::vector<double>& unit);
/// A value's place in its bounds (clamped into [0, 1]).
std::vector<double> scaled(const std::vector<TunedParameter>& parameters,
                           const std::vector<double>& values);

/// NLopt's method from `start` (in the parameters' units, clamped into the bounds) for exactly
/// `spec.budget` evaluations: a local method that converges before the budget is spent starts
/// again from its best point with half the step (docs/tune.md). Evaluations are named "nlopt".
void nlopt_search(const TuneSpec& spec, const std::vector<double>& start,
                  const Evaluator& evaluate);

/// `spec.budget` points drawn uniformly in the bounds from `spec.seed`. Named "random".
void random_search(const TuneSpec& spec, const Evaluator& evaluate);

}  // namespace plantsim::tune
