// The navigation chart's layout (see the header).
#include "render/navigation_chart.h"

#include <algorithm>

#include "render/method_strips.h"
#include "render/palette.h"

namespace plantsim::render {

Image draw_navigation_chart(const std::vector<EpisodeOutcome>& episodes, int width_px,
                            FigureLayout* layout_out) {
  constexpr double kNear_m = 0.3;  // episode/navigation_metrics.h's kNearObstacle_m
  const std::vector<std::string> methods = methods_of(episodes);
  std::vector<std::vector<double>> clearance(methods.size()), jerk(methods.size()),
      compute(methods.size());
  std::vector<std::vector<bool>> failed(methods.size());
  std::vector<std::size_t> counts(methods.size(), 0);
  bool any_failed = false, any_succeeded = false;
  for (const auto& e : episodes) {
    if (e.min_clearance_m < 0) continue;  // it never travelled
    const std::size_t m = method_index(methods, e.method);
    clearance[m].push_back(e.min_clearance_m);
    failed[m].push_back(!e.docked);
    any_failed = any_failed || !e.docked;
    any_succeeded = any_succeeded || e.docked;
    if (e.rms_jerk_mps3 >= 0) jerk[m].push_back(e.rms_jerk_mps3);
    if (e.controller_ms_median >= 0) compute[m].push_back(e.controller_ms_median);
    ++counts[m];
  }
  const double row_h = 60;
  const int height = static_cast<int>(130 + row_h * std::max<std::size_t>(methods.size(), 1) + 60);
  Figure fig(width_px, height);
  fig.text("Navigation: clearance, smoothness, the controller's compute time", 20, 28, 18,
           palette::kAxis, Anchor::kLeft, true);
  fig.text(
      "one mark per episode over its travel to the staging pose: a dot if it succeeded, a cross "
      "if it failed (clearance); compute time is wall time on this machine",
      20, 48, 13, palette::kAxis);
  const double label_w = 260, gap = 50;
  const double panel_w = (width_px - label_w - 2 * gap - 40) / 3.0;
  const PixelBox first{label_w, 110, label_w + panel_w,
                       110 + row_h * std::max<std::size_t>(methods.size(), 1)};
  const PixelBox second{first.right + gap, first.top, first.right + gap + panel_w, first.bottom};
  const PixelBox third{second.right + gap, first.top, second.right + gap + panel_w, first.bottom};
  method_labels(fig, first, methods, counts);
  strip_panel(fig, first, methods, clearance, kNear_m, "Min clearance (red line: 0.3 m)", "m", 1.0,
              &failed);
  strip_panel(fig, second, methods, jerk, -1, "RMS jerk", "m/s^3", 1.0);
  strip_panel(fig, third, methods, compute, -1, "Controller median per cycle", "ms", 1.0);
  std::vector<LegendEntry> legend = {{palette::kCollisionMark, "0.3 m"}};
  if (any_succeeded)
    legend.push_back({method_colour(0), "succeeded (dot, its method's colour)", Swatch::kDot});
  if (any_failed) legend.push_back({kFailedMark, "failed (black cross)", Swatch::kDot});
  fig.legend(20, 76, legend, static_cast<int>(legend.size()), 330);
  Image img = fig.finish();
  if (layout_out) *layout_out = fig.layout();
  return img;
}

}  // namespace plantsim::render
