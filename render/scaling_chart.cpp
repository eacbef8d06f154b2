// Decades on both axes, 1-2-5 minor ticks, markers at the measured points.
#include "render/scaling_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "render/palette.h"
#include "util/c_number.h"

namespace plantsim::render {
namespace {

std::string decade_label(double v) {
  char buf[32];
  if (v >= 1)
    util::c_snprintf(buf, sizeof buf, "%.0f", v);
  else
    util::c_snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

/// A polyline in dashes of `dash_px` (pixel coordinates).
void dashed_polyline(GlCanvas& c, const std::vector<Vec2>& pts, double width, double dash_px,
                     Rgb colour) {
  bool on = true;
  double left = dash_px;
  for (std::size_t i = 1; i < pts.size(); ++i) {
    Vec2 a = pts[i - 1];
    double len = geom::distance(a, pts[i]);
    const Vec2 u = len > 0 ? (1.0 / len) * (pts[i] - a) : Vec2{0, 0};
    while (len > 0) {
      const double step = std::min(left, len);
      const Vec2 b = a + step * u;
      if (on) c.pixel_line(a, b, width, colour);
      a = b, len -= step, left -= step;
      if (left <= 0) on = !on, left = dash_px;
    }
  }
}

/// A colour per method (Okabe-Ito; series of one method share it), and the legend of the series
/// that have points to draw.
std::vector<Rgb> series_colours(const std::vector<ScalingSeries>& series,
                                std::vector<LegendEntry>& legend) {
  static const Rgb kColours[] = {palette::kOkabeBlue,        palette::kOkabeVermillion,
                                 palette::kOkabeBluishGreen, palette::kOkabeReddishPurple,
                                 palette::kOkabeOrange,      palette::kOkabeSkyBlue,
                                 palette::kOkabeBlack};
  std::vector<std::string> methods;
  std::vector<Rgb> colour_of(series.size());
  for (std::size_t k = 0; k < series.size(); ++k) {
    const std::string& m = series[k].method.empty() ? series[k].label : series[k].method;
    auto it = std::find(methods.begin(), methods.end(), m);
    if (it == methods.end()) it = methods.insert(methods.end(), m);
    colour_of[k] = kColours[static_cast<std::size_t>(it - methods.begin()) % 7];
    const bool drawn =
        std::any_of(series[k].size.begin(), series[k].size.end(), [](double v) { return v > 0; });
    if (drawn)
      legend.push_back(
          {colour_of[k], series[k].label, series[k].dashed ? Swatch::kDashed : Swatch::kBar});
  }
  return colour_of;
}

}  // namespace

Image draw_scaling_chart(const std::vector<ScalingSeries>& series, const std::string& title,
                         const std::string& subtitle, const std::string& x_label,
                         const std::string& y_label, int width_px, int height_px,
                         FigureLayout* layout_out) {
  Figure fig(width_px, height_px);
  fig.text_fitted(title, 20, 28, 18, palette::kAxis, width_px - 40.0, true);
  fig.text_fitted(subtitle, 20, 48, 13, palette::kAxis, width_px - 40.0);
  double xlo = std::numeric_limits<double>::infinity(), xhi = 0, ylo = xlo, yhi = 0;
  for (const auto& s : series)
    for (std::size_t i = 0; i < s.size.size() && i < s.cost.size(); ++i)
      if (s.size[i] > 0 && s.cost[i] > 0) {
        xlo = std::min(xlo, s.size[i]), xhi = std::max(xhi, s.size[i]);
        ylo = std::min(ylo, s.cost[i]), yhi = std::max(yhi, s.cost[i]);
      }
  if (!(xhi > 0)) xlo = 1, xhi = 10, ylo = 1, yhi = 10;
  const double lx0 = std::floor(std::log10(xlo)),
               lx1 = std::max(lx0 + 1, std::ceil(std::log10(xhi)));
  const double ly0 = std::floor(std::log10(ylo)),
               ly1 = std::max(ly0 + 1, std::ceil(std::log10(yhi)));
  // A colour per method, the legend three entries a row above the plot.
  std::vector<LegendEntry> legend;
  const std::vector<Rgb> colour_of = series_colours(series, legend);
  const PixelBox legend_box = fig.legend(20, 74, legend, 3, (width_px - 40.0) / 3);
  const PixelBox box{90, legend_box.bottom + 36, width_px - 40.0, height_px - 70.0};
  auto px = [&](double x, double y) {
    return Vec2{box.left + box.width() * (std::log10(x) - lx0) / (lx1 - lx0),
                box.bottom - box.height() * (std::log10(y) - ly0) / (ly1 - ly0)};
  };
  GlCanvas& c = fig.canvas();
  for (double d = lx0; d <= lx1 + 1e-9; ++d)
    for (double m : {1.0, 2.0, 5.0}) {
      const double v = m * std::pow(10.0, d);
      if (std::log10(v) > lx1 + 1e-9) break;
      const double x = px(v, std::pow(10.0, ly0)).x;
      c.pixel_line({x, box.top}, {x, box.bottom}, 1.0,
                   m == 1.0 ? Rgb{200, 200, 200} : palette::kGrid);
      if (m == 1.0)
        fig.text(decade_label(v), x, box.bottom + 17, 12, palette::kAxis, Anchor::kCenter);
    }
  for (double d = ly0; d <= ly1 + 1e-9; ++d)
    for (double m : {1.0, 2.0, 5.0}) {
      const double v = m * std::pow(10.0, d);
      if (std::log10(v) > ly1 + 1e-9) break;
      const double y = px(std::pow(10.0, lx0), v).y;
      c.pixel_line({box.left, y}, {box.right, y}, 1.0,
                   m == 1.0 ? Rgb{200, 200, 200} : palette::kGrid);
      if (m == 1.0)
        fig.text(decade_label(v), box.left - 7, y + 4, 12, palette::kAxis, Anchor::kRight);
    }
  c.pixel_line({box.left, box.bottom}, {box.right, box.bottom}, 1.0, palette::kAxis);
  c.pixel_line({box.left, box.bottom}, {box.left, box.top}, 1.0, palette::kAxis);
  fig.text(x_label + " (log scale)", 0.5 * (box.left + box.right), box.bottom + 36, 13,
           palette::kAxis, Anchor::kCenter);
  fig.text(y_label + " (log scale)", box.left, box.top - 10, 13, palette::kAxis);
  for (std::size_t k = 0; k < series.size(); ++k) {
    const Rgb colour = colour_of[k];
    std::vector<Vec2> pts;
    for (std::size_t i = 0; i < series[k].size.size() && i < series[k].cost.size(); ++i)
      if (series[k].size[i] > 0 && series[k].cost[i] > 0)
        pts.push_back(px(series[k].size[i], series[k].cost[i]));
    if (pts.empty()) continue;
    if (series[k].dashed)
      dashed_polyline(c, pts, 2.2, 9.0, colour);
    else
      c.pixel_polyline(pts, 2.2, colour);
    for (const Vec2& p : pts) c.pixel_line({p.x - 4, p.y}, {p.x + 4, p.y}, 8.0, colour);
  }
  Image img = fig.finish();
  if (layout_out) *layout_out = fig.layout();
  return img;
}

}  // namespace plantsim::render
