// The strips of per-episode values by method (see the header).
#include "render/method_strips.h"

#include <algorithm>
#include <cmath>

#include "render/chart_axes.h"
#include "render/palette.h"

namespace plantsim::render {

/// The methods in first-met order, each with an Okabe-Ito colour.
std::vector<std::string> methods_of(const std::vector<EpisodeOutcome>& episodes) {
  std::vector<std::string> out;
  for (const auto& e : episodes)
    if (std::find(out.begin(), out.end(), e.method) == out.end()) out.push_back(e.method);
  return out;
}

std::size_t method_index(const std::vector<std::string>& methods, const std::string& method) {
  return static_cast<std::size_t>(std::find(methods.begin(), methods.end(), method) -
                                  methods.begin());
}

Rgb method_colour(std::size_t i) {
  // Not black: black is the failed mark's (kFailedMark), and a seventh method drawn in it hid
  // its failures' crosses among its dots (chart_navigation.png of controllers.yaml).
  static const Rgb kCycle[] = {palette::kOkabeBlue,        palette::kOkabeVermillion,
                               palette::kOkabeBluishGreen, palette::kOkabeReddishPurple,
                               palette::kOkabeOrange,      palette::kOkabeSkyBlue};
  return kCycle[i % (sizeof kCycle / sizeof kCycle[0])];
}

/// A deterministic spread in [-1, 1] for the i-th dot of a strip.
double jitter(std::size_t i) {
  return std::fmod(static_cast<double>(i) * 0.618033988749895, 1.0) * 2.0 - 1.0;
}

void strip_panel(Figure& fig, const PixelBox& box, const std::vector<std::string>& methods,
                 const std::vector<std::vector<double>>& values, double gate,
                 const std::string& title, const std::string& label, double scale,
                 const std::vector<std::vector<bool>>* failed) {
  double hi = std::max(gate * 1.25, 1e-9);  // never an empty range
  for (const auto& v : values)
    for (double x : v) hi = std::max(hi, x * 1.05);
  const Axes a{box, 0, hi, 0, static_cast<double>(methods.size())};
  axis(fig, a, true, label, scale);
  fig.canvas().pixel_line({a.box.left, a.box.bottom}, {a.box.left, a.box.top}, 1.0, palette::kAxis);
  const double row_h = box.height() / std::max<std::size_t>(methods.size(), 1);
  for (std::size_t m = 0; m < methods.size(); ++m) {
    const double centre = box.top + (m + 0.5) * row_h;
    for (std::size_t i = 0; i < values[m].size(); ++i) {
      const double x = a.px(values[m][i]), y = centre + 0.3 * row_h * jitter(i);
      if (failed && i < (*failed)[m].size() && (*failed)[m][i]) {  // a failed episode: a cross
        fig.canvas().pixel_line({x - 4, y - 4}, {x + 4, y + 4}, 2.0, kFailedMark);
        fig.canvas().pixel_line({x - 4, y + 4}, {x + 4, y - 4}, 2.0, kFailedMark);
        continue;
      }
      fig.canvas().pixel_line({x - 2.5, y}, {x + 2.5, y}, 5.0, method_colour(m));
    }
  }
  if (gate >= 0)
    fig.canvas().pixel_line({a.px(gate), box.top}, {a.px(gate), box.bottom}, 2.0,
                            palette::kCollisionMark);
  fig.text(title, box.left, box.top - 10, 14, palette::kAxis, Anchor::kLeft, true);
}

void method_labels(Figure& fig, const PixelBox& box, const std::vector<std::string>& methods,
                   const std::vector<std::size_t>& counts) {
  const double row_h = box.height() / std::max<std::size_t>(methods.size(), 1);
  for (std::size_t m = 0; m < methods.size(); ++m)
    fig.text(fig.fit(methods[m] + " (" + std::to_string(counts[m]) + ")", 12, box.left - 16),
             box.left - 8, box.top + (m + 0.5) * row_h + 4, 12, method_colour(m), Anchor::kRight);
}

}  // namespace plantsim::render
