// A perceptually ordered, colour-blind-safe colour map (cividis: dark blue to yellow, sampled at
// six points and interpolated) for values such as speed, and "nice" tick steps for axes and
// colour bars.
#pragma once

#include <string>
#include <vector>

#include "render/image.h"

namespace plantsim::render {

/// Colour of t in [0, 1] (clamped).
Rgb cividis(double t);

/// Tick positions covering [lo, hi] at a 1, 2 or 5 x 10^k step giving about `target` ticks.
std::vector<double> nice_ticks(double lo, double hi, int target = 6);

/// Shortest label for a tick value at the given step (no trailing zeros).
std::string tick_label(double value, double step);

}  // namespace plantsim::render
