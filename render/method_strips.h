// The batch charts' shared pieces for values per episode grouped by method: the methods in
// first-met order with their Okabe-Ito colours, a strip panel (one row of dots per method, an
// optional gate line) and the rows' labels.
#pragma once

#include <string>
#include <vector>

#include "render/batch_charts.h"
#include "render/figure.h"
#include "render/palette.h"

namespace plantsim::render {

/// Failed episodes among a strip's dots: black, a colour no method takes before the seventh.
inline constexpr Rgb kFailedMark = palette::kOkabeBlack;

/// The methods in first-met order, each with an Okabe-Ito colour.
std::vector<std::string> methods_of(const std::vector<EpisodeOutcome>& episodes);
std::size_t method_index(const std::vector<std::string>& methods, const std::string& method);
Rgb method_colour(std::size_t i);
/// A deterministic spread in [-1, 1] for the i-th dot of a strip.
double jitter(std::size_t i);

/// Dots of one value per episode, a row per method (`values[m]`), from 0; a red line at `gate`
/// when it is not negative; `failed` marks crosses instead of dots.
void strip_panel(Figure& fig, const PixelBox& box, const std::vector<std::string>& methods,
                 const std::vector<std::vector<double>>& values, double gate,
                 const std::string& title, const std::string& label, double scale,
                 const std::vector<std::vector<bool>>* failed = nullptr);
/// Each row's method and episode count, right-aligned left of `box`, in the method's colour.
void method_labels(Figure& fig, const PixelBox& box, const std::vector<std::string>& methods,
                   const std::vector<std::size_t>& counts);

}  // namespace plantsim::render
