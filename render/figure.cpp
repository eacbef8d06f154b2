// Panels, axes, legends, colour bars and plots.
#include "render/figure.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>

#include "render/colormap.h"
#include "render/palette.h"

namespace plantsim::render {

PanelGrid panel_grid(std::size_t panels, int max_columns, int width_px, int panel_height_px) {
  PanelGrid g;
  g.columns = std::max(1, std::min(max_columns, static_cast<int>(panels)));
  g.rows = std::max(1, static_cast<int>((panels + g.columns - 1) / g.columns));
  g.panel_width_px = static_cast<double>(width_px) / g.columns;
  g.panel_height_px = panel_height_px;
  return g;
}

TextRenderer& shared_text_renderer() {
  static TextRenderer renderer;
  return renderer;
}

Figure::Figure(int width, int height, int supersample) : canvas_(width, height, supersample) {
  canvas_.clear(palette::kBackground);
}

bool overlaps(const TextBox& a, const TextBox& b) {
  return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

void Figure::text(const std::string& s, double x, double baseline_y, int size_px, Rgb colour,
                  Anchor anchor, bool bold) {
  texts_.push_back({s, x, baseline_y, size_px, colour, anchor, bold});
}

std::string Figure::fit(const std::string& s, int size_px, double max_width_px, bool bold) const {
  TextRenderer& tr = shared_text_renderer();
  auto width = [&](const std::string& t) {
    const TextBox b = tr.measure(t, 0, 0, size_px, Anchor::kLeft, bold);
    return b.x1 - b.x0;
  };
  if (width(s) <= max_width_px) return s;
  std::string fitted = s;
  while (!fitted.empty() && width(fitted + "...") > max_width_px) {
    fitted.pop_back();
    while (!fitted.empty() && (static_cast<unsigned char>(fitted.back()) & 0xC0) == 0x80)
      fitted.pop_back();  // whole characters
    if (!fitted.empty() && static_cast<unsigned char>(fitted.back()) >= 0xC0) fitted.pop_back();
  }
  return fitted + "...";
}

void Figure::text_fitted(const std::string& s, double x, double baseline_y, int size_px, Rgb colour,
                         double max_width_px, bool bold) {
  text(fit(s, size_px, max_width_px, bold), x, baseline_y, size_px, colour, Anchor::kLeft, bold);
}

bool Figure::text_if_free(const std::string& s, double x, double baseline_y, int size_px,
                          Rgb colour, Anchor anchor) {
  TextRenderer& tr = shared_text_renderer();
  const TextBox box = tr.measure(s, static_cast<int>(std::lround(x)),
                                 static_cast<int>(std::lround(baseline_y)), size_px, anchor);
  if (box.x0 < 0 || box.y0 < 0 || box.x1 > width() || box.y1 > height()) return false;
  for (const QueuedText& q : texts_) {
    const TextBox other = tr.measure(q.s, static_cast<int>(std::lround(q.x)),
                                     static_cast<int>(std::lround(q.y)), q.size, q.anchor, q.bold);
    if (overlaps(box, other)) return false;
  }
  text(s, x, baseline_y, size_px, colour, anchor);
  return true;
}

PixelTransform Figure::world_panel(const geom::Rect& view, const PixelBox& box) {
  const PixelTransform t = PixelTransform::fit(view, box.left, height() - box.bottom, box.right,
                                               height() - box.top, height());
  canvas_.set_transform(t);
  return t;
}

void Figure::clip_to_world(const geom::Rect& view, const PixelTransform& t, double margin_px) {
  const Vec2 lo = t.to_pixel({view.xmin, view.ymin}), hi = t.to_pixel({view.xmax, view.ymax});
  canvas_.set_clip(lo.x - margin_px, hi.y - margin_px, hi.x + margin_px, lo.y + margin_px);
}

void Figure::world_axes(const geom::Rect& view, const PixelTransform& t) {
  canvas_.clear_clip();
  const Vec2 lo = t.to_pixel({view.xmin, view.ymin}), hi = t.to_pixel({view.xmax, view.ymax});
  const int target_x = std::max(2, static_cast<int>((hi.x - lo.x) / 90));
  const int target_y = std::max(2, static_cast<int>((lo.y - hi.y) / 70));
  const auto xs = nice_ticks(view.xmin, view.xmax, target_x),
             ys = nice_ticks(view.ymin, view.ymax, target_y);
  const double xstep = xs.size() > 1 ? xs[1] - xs[0] : 1.0,
               ystep = ys.size() > 1 ? ys[1] - ys[0] : 1.0;
  canvas_.pixel_line({lo.x, lo.y}, {hi.x, lo.y}, 1.0, palette::kAxis);
  canvas_.pixel_line({lo.x, lo.y}, {lo.x, hi.y}, 1.0, palette::kAxis);
  for (double x : xs) {
    const double px = t.to_pixel({x, view.ymin}).x;
    canvas_.pixel_line({px, lo.y}, {px, lo.y + 5}, 1.0, palette::kAxis);
    text(tick_label(x, xstep), px, lo.y + 18, 12, palette::kAxis, Anchor::kCenter);
  }
  for (double y : ys) {
    const double py = t.to_pixel({view.xmin, y}).y;
    canvas_.pixel_line({lo.x - 5, py}, {lo.x, py}, 1.0, palette::kAxis);
    text(tick_label(y, ystep), lo.x - 8, py + 4, 12, palette::kAxis, Anchor::kRight);
  }
  text("x (m)", 0.5 * (lo.x + hi.x), lo.y + 34, 13, palette::kAxis, Anchor::kCenter);
  text("y (m)", lo.x - 8, hi.y - 8, 13, palette::kAxis, Anchor::kRight);
}

void Figure::colour_bar(const PixelBox& box, double lo, double hi, const std::string& label) {
  const int steps = 64;
  for (int i = 0; i < steps; ++i) {
    const double x0 = box.left + box.width() * i / steps,
                 x1 = box.left + box.width() * (i + 1) / steps;
    canvas_.pixel_line({x0, 0.5 * (box.top + box.bottom)}, {x1, 0.5 * (box.top + box.bottom)},
                       box.height(), cividis((i + 0.5) / steps));
  }
  const auto ticks = nice_ticks(lo, hi, 4);
  const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : 1.0;
  for (double v : ticks) {
    const double x = box.left + box.width() * (v - lo) / (hi - lo);
    canvas_.pixel_line({x, box.bottom}, {x, box.bottom + 4}, 1.0, palette::kAxis);
    text(tick_label(v, step), x, box.bottom + 17, 12, palette::kAxis, Anchor::kCenter);
  }
  text(label, box.left, box.top - 7, 13, palette::kAxis);
  layout_.legend_boxes.push_back({box.left, box.top - 20, box.right, box.bottom + 20});
}

void Figure::draw_swatch(double x, double y, const LegendEntry& e) {
  const Rgb c = e.colour;
  switch (e.swatch) {
    case Swatch::kBar:
      canvas_.pixel_line({x, y}, {x + 22, y}, 5.0, c);
      break;
    case Swatch::kDashed:
      for (double a = x; a < x + 22; a += 8)
        canvas_.pixel_line({a, y}, {std::min(a + 5, x + 22), y}, 2.5, c);
      break;
    case Swatch::kRing: {
      std::vector<Vec2> circle;
      for (int k = 0; k <= 16; ++k)
        circle.push_back({x + 11 + 6 * std::cos(k * M_PI / 8), y + 6 * std::sin(k * M_PI / 8)});
      canvas_.pixel_polyline(circle, 2.0, c);
      break;
    }
    case Swatch::kDot:
      canvas_.pixel_line({x + 7, y}, {x + 15, y}, 8.0, c);
      break;
    case Swatch::kOutline:
      canvas_.pixel_polyline(
          {{x + 3, y - 6}, {x + 19, y - 6}, {x + 19, y + 6}, {x + 3, y + 6}, {x + 3, y - 6}}, 1.8,
          c);
      break;
  }
}

PixelBox Figure::legend(double x, double y, const std::vector<LegendEntry>& entries, int columns,
                        double column_width_px) {
  columns = std::max(1, columns);
  const std::size_t rows = (entries.size() + columns - 1) / columns;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const double cx = x + column_width_px * static_cast<double>(i / std::max<std::size_t>(rows, 1));
    const double row = y + 19.0 * static_cast<double>(i % std::max<std::size_t>(rows, 1));
    draw_swatch(cx, row - 4, entries[i]);
    text(fit(entries[i].label, 13, column_width_px - 34), cx + 28, row + 1, 13, palette::kAxis);
    layout_.legend.push_back(entries[i]);
  }
  const PixelBox box{x, y - 12, x + column_width_px * columns,
                     y + 19.0 * static_cast<double>(rows)};
  layout_.legend_boxes.push_back(box);
  return box;
}

namespace {

// The data range a plot shows: every finite x (even where y is undefined), y from zero or below,
// never less than the options' minimum span, padded at the top.
struct PlotScale {
  double xmin, xmax, ymin, ymax;
  bool empty;  // no finite y at all
  Vec2 to_pixel(const PixelBox& box, double x, double y) const {
    return Vec2{box.left + box.width() * (x - xmin) / (xmax - xmin),
                box.bottom - box.height() * (y - ymin) / (ymax - ymin)};
  }
};

PlotScale plot_scale(const std::vector<Figure::Series>& series, double min_y_span) {
  double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin, ymin = xmin, ymax = -xmin;
  for (const Figure::Series& s : series)
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!std::isfinite(s.x[i])) continue;
      xmin = std::min(xmin, s.x[i]);
      xmax = std::max(xmax, s.x[i]);
      if (!std::isfinite(s.y[i])) continue;
      ymin = std::min(ymin, s.y[i]);
      ymax = std::max(ymax, s.y[i]);
    }
  if (!(xmax > xmin)) xmin = 0, xmax = 1;
  const bool empty = !std::isfinite(ymin);
  if (!(ymax > ymin)) ymin = std::isfinite(ymin) ? ymin - 1 : 0, ymax = ymin + 2;
  ymin = std::min(ymin, 0.0);
  // Rounding noise around zero must not be blown up into a full-height signal.
  if (ymax - ymin < min_y_span) ymax = ymin + min_y_span;
  ymax += 0.05 * (ymax - ymin);
  return {xmin, xmax, ymin, ymax, empty};
}

}  // namespace

void Figure::plot(const PixelBox& box, const std::vector<Series>& series, const std::string& title,
                  const std::string& y_label, const PlotOptions& options) {
  const PlotScale scale = plot_scale(series, options.min_y_span);
  auto px = [&](double x, double y) { return scale.to_pixel(box, x, y); };
  for (const Band& b : options.bands) {
    const double x0 = px(std::clamp(b.x0, scale.xmin, scale.xmax), scale.ymin).x,
                 x1 = px(std::clamp(b.x1, scale.xmin, scale.xmax), scale.ymin).x;
    if (x1 > x0)
      canvas_.pixel_line({0.5 * (x0 + x1), box.top}, {0.5 * (x0 + x1), box.bottom}, x1 - x0,
                         b.colour);
  }
  canvas_.pixel_line({box.left, box.top}, {box.right, box.top}, 1.0, palette::kGrid);
  for (double y : nice_ticks(scale.ymin, scale.ymax, 4)) {
    const double py = px(scale.xmin, y).y;
    canvas_.pixel_line({box.left, py}, {box.right, py}, 1.0, palette::kGrid);
  }
  for (const Series& s : series) {
    std::vector<Vec2> pts;
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
      if (std::isfinite(s.y[i])) pts.push_back(px(s.x[i], s.y[i]));
    canvas_.pixel_polyline(pts, 1.6, s.colour);
  }
  for (const PlotOptions::Marker& m : options.markers) {
    if (m.x < scale.xmin || m.x > scale.xmax) continue;
    const double x = px(m.x, scale.ymin).x;
    canvas_.pixel_line({x, box.top}, {x, box.bottom}, 2.0, m.colour);
  }
  plot_axes(box, scale.xmin, scale.xmax, scale.ymin, scale.ymax);
  text(title + (y_label.empty() ? "" : " (" + y_label + ")"), box.left, box.top - 8, 14,
       palette::kAxis, Anchor::kLeft, true);
  if (!options.x_label.empty())
    text(options.x_label, 0.5 * (box.left + box.right), box.bottom + 32, 12, palette::kAxis,
         Anchor::kCenter);
  if (scale.empty && !options.note.empty())
    text(options.note, 0.5 * (box.left + box.right), 0.5 * (box.top + box.bottom), 13,
         palette::kAxis, Anchor::kCenter);
  if (options.legend) plot_legend(box, series, options.bands, options.markers);
}

void Figure::plot_axes(const PixelBox& box, double xmin, double xmax, double ymin, double ymax) {
  const PlotScale scale{xmin, xmax, ymin, ymax, false};
  canvas_.pixel_line({box.left, box.bottom}, {box.right, box.bottom}, 1.0, palette::kAxis);
  canvas_.pixel_line({box.left, box.bottom}, {box.left, box.top}, 1.0, palette::kAxis);
  const auto xs = nice_ticks(xmin, xmax, 8), ys = nice_ticks(ymin, ymax, 4);
  const double xstep = xs.size() > 1 ? xs[1] - xs[0] : 1.0,
               ystep = ys.size() > 1 ? ys[1] - ys[0] : 1.0;
  for (double x : xs) {
    const Vec2 p = scale.to_pixel(box, x, ymin);
    canvas_.pixel_line({p.x, box.bottom}, {p.x, box.bottom + 4}, 1.0, palette::kAxis);
    text(tick_label(x, xstep), p.x, box.bottom + 17, 12, palette::kAxis, Anchor::kCenter);
  }
  for (double y : ys) {
    const Vec2 p = scale.to_pixel(box, xmin, y);
    canvas_.pixel_line({box.left - 4, p.y}, {box.left, p.y}, 1.0, palette::kAxis);
    text(tick_label(y, ystep), box.left - 7, p.y + 4, 12, palette::kAxis, Anchor::kRight);
  }
}

// Entries right-aligned along the top edge, above the plot, the last one at the right.
void Figure::plot_legend(const PixelBox& box, const std::vector<Series>& series,
                         const std::vector<Band>& bands,
                         const std::vector<PlotOptions::Marker>& markers) {
  std::vector<LegendEntry> entries;
  for (const Series& s : series) entries.push_back({s.colour, s.label});
  std::vector<std::string> seen;
  for (const Band& b : bands)
    if (std::find(seen.begin(), seen.end(), b.label) == seen.end()) {
      seen.push_back(b.label);
      entries.push_back({b.colour, b.label});
    }
  for (const PlotOptions::Marker& m : markers)
    if (std::find(seen.begin(), seen.end(), m.label) == seen.end()) {
      seen.push_back(m.label);
      entries.push_back({m.colour, m.label});
    }
  TextRenderer& tr = shared_text_renderer();
  double x = box.right;
  for (auto it = entries.rbegin(); it != entries.rend(); ++it) {
    const TextBox m = tr.measure(it->label, 0, 0, 12);
    x -= m.x1 - m.x0;
    text(it->label, x, box.top - 8, 12, palette::kAxis);
    x -= 26;
    canvas_.pixel_line({x, box.top - 12}, {x + 20, box.top - 12}, 8.0, it->colour);
    layout_.legend.push_back(*it);
    x -= 14;
  }
  layout_.legend_boxes.push_back({x, box.top - 22, box.right, box.top - 2});
}

Image Figure::finish() {
  Image img = canvas_.read();
  TextRenderer& tr = shared_text_renderer();
  for (const QueuedText& q : texts_) {
    layout_.texts.push_back(q.s);
    layout_.text_boxes.push_back(tr.draw(img, q.s, static_cast<int>(std::lround(q.x)),
                                         static_cast<int>(std::lround(q.y)), q.size, q.colour,
                                         q.anchor, q.bold));
  }
  texts_.clear();
  return img;
}

}  // namespace plantsim::render
