// Layout of the tuning charts on the shared chart axes.
#include "render/tune_charts.h"

#include <algorithm>
#include <cmath>

#include "render/chart_axes.h"
#include "render/palette.h"

namespace plantsim::render {

namespace {

constexpr Rgb kDefaultLine{120, 120, 130};

/// The score range every counted point and the default fit in, padded.
std::pair<double, double> score_range(const std::vector<SearchScores>& searches,
                                      double default_score) {
  double lo = default_score, hi = default_score;
  for (const SearchScores& s : searches)
    for (std::size_t i = 0; i < s.score.size(); ++i)
      if (s.counted[i]) lo = std::min(lo, s.score[i]), hi = std::max(hi, s.score[i]);
  if (!(hi > lo)) lo -= 0.5, hi += 0.5;
  const double pad = 0.06 * (hi - lo);
  return {lo - pad, hi + pad};
}

int uncounted(const std::vector<SearchScores>& searches) {
  int n = 0;
  for (const SearchScores& s : searches)
    n += static_cast<int>(std::count(s.counted.begin(), s.counted.end(), false));
  return n;
}

void dot(GlCanvas& c, double x, double y, Rgb colour) {
  c.pixel_line({x - 2.5, y}, {x + 2.5, y}, 5.0, colour);
}

void dashed_horizontal(GlCanvas& c, const Axes& a, double y, Rgb colour) {
  for (double x = a.box.left; x < a.box.right; x += 12)
    c.pixel_line({x, a.py(y)}, {std::min(x + 7, a.box.right), a.py(y)}, 2.0, colour);
}

void dashed_vertical(GlCanvas& c, const Axes& a, double x, Rgb colour) {
  for (double y = a.box.top; y < a.box.bottom; y += 10)
    c.pixel_line({a.px(x), y}, {a.px(x), std::min(y + 6, a.box.bottom)}, 2.0, colour);
}

std::string left_out_note(int n) {
  return n == 0 ? ""
                : "; " + std::to_string(n) +
                      " evaluation(s) below the success floor or refused are not drawn";
}

}  // namespace

Image draw_convergence_chart(const std::vector<SearchScores>& searches, double default_score,
                             const std::string& title, const std::string& y_label, int width_px,
                             FigureLayout* layout_out) {
  const int height = 600;
  Figure fig(width_px, height);
  fig.text_fitted(title, 20, 28, 18, palette::kAxis, width_px - 40.0, true);
  fig.text_fitted(
      "best score so far (line) and each evaluation's score (dots), on the tuning episodes" +
          left_out_note(uncounted(searches)),
      20, 48, 13, palette::kAxis, width_px - 40.0);
  std::size_t longest = 1;
  for (const SearchScores& s : searches) longest = std::max(longest, s.score.size());
  const auto [lo, hi] = score_range(searches, default_score);
  const Axes a{{90, 110, width_px - 40.0, height - 70.0}, 0.5, longest + 0.5, lo, hi};
  axis(fig, a, true, "evaluation");
  axis(fig, a, false);
  fig.text(y_label, 20, 100, 13, palette::kAxis);
  GlCanvas& c = fig.canvas();
  dashed_horizontal(c, a, default_score, kDefaultLine);
  std::vector<LegendEntry> legend;
  for (const SearchScores& s : searches) {
    std::vector<Vec2> line;
    double best = -HUGE_VAL;
    for (std::size_t i = 0; i < s.score.size(); ++i) {
      if (!s.counted[i]) continue;
      best = std::max(best, s.score[i]);
      dot(c, a.px(i + 1.0), a.py(s.score[i]), s.colour);
      if (!line.empty()) line.push_back({a.px(i + 1.0), line.back().y});
      line.push_back({a.px(i + 1.0), a.py(best)});
    }
    if (!line.empty()) line.push_back({a.px(static_cast<double>(s.score.size())), line.back().y});
    c.pixel_polyline(line, 2.4, s.colour);
    legend.push_back({s.colour, s.label});
  }
  legend.push_back({kDefaultLine, "default settings", Swatch::kDashed});
  fig.legend(20, 70, legend, static_cast<int>(legend.size()), 300);
  Image img = fig.finish();
  if (layout_out) *layout_out = fig.layout();
  return img;
}

Image draw_parameter_scores(const std::vector<ParameterAxis>& parameters,
                            const std::vector<SearchScores>& searches, const std::string& y_label,
                            int width_px, FigureLayout* layout_out) {
  const PanelGrid grid = panel_grid(parameters.size(), 3, width_px, 320);
  Figure fig(width_px, grid.height_px() + 40);
  fig.text_fitted(
      "Score against each parameter (tuning episodes)" + left_out_note(uncounted(searches)), 20, 28,
      18, palette::kAxis, width_px - 40.0, true);
  double any_score = 0;  // a counted score, to start the range from
  for (const SearchScores& s : searches)
    for (std::size_t i = 0; i < s.score.size(); ++i)
      if (s.counted[i]) any_score = s.score[i];
  const auto [lo, hi] = score_range(searches, any_score);
  GlCanvas& c = fig.canvas();
  for (std::size_t p = 0; p < parameters.size(); ++p) {
    const ParameterAxis& axis_info = parameters[p];
    const Vec2 corner = grid.corner(p);
    const PixelBox box{corner.x + 80, corner.y + 40, corner.x + grid.panel_width_px - 25,
                       corner.y + grid.panel_height_px - 50.0};
    const double pad = 0.03 * (axis_info.hi - axis_info.lo);
    const Axes a{box, axis_info.lo - pad, axis_info.hi + pad, lo, hi};
    fig.text_fitted(axis_info.name, box.left, box.top - 12, 13, palette::kAxis, box.width(), true);
    axis(fig, a, true, "");
    axis(fig, a, false);
    dashed_vertical(c, a, axis_info.default_value, kDefaultLine);
    c.pixel_line({a.px(axis_info.best_value), box.top}, {a.px(axis_info.best_value), box.bottom},
                 2.0, palette::kOkabeVermillion);
    for (const SearchScores& s : searches)
      for (std::size_t i = 0; i < s.score.size(); ++i)
        if (s.counted[i] && p < s.values[i].size())
          dot(c, a.px(s.values[i][p]), a.py(s.score[i]), s.colour);
  }
  std::vector<LegendEntry> legend;
  for (const SearchScores& s : searches) legend.push_back({s.colour, s.label, Swatch::kDot});
  legend.push_back({kDefaultLine, "default value", Swatch::kDashed});
  legend.push_back({palette::kOkabeVermillion, "best value (best.json)"});
  fig.text(y_label + " (vertical axes)", 20, grid.height_px() + 30.0, 13, palette::kAxis);
  fig.legend(width_px * 0.35, grid.height_px() + 14.0, legend, static_cast<int>(legend.size()),
             170);
  Image img = fig.finish();
  if (layout_out) *layout_out = fig.layout();
  return img;
}

}  // namespace plantsim::render
