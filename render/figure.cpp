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

void Figure::text(const std::string& s, double x, double baseline_y, int size_px, Rgb colour, Anchor anchor, bool bold) {
  texts_.push_back({s, x, baseline_y, size_px, colour, anchor, bold});
}

PixelTransform Figure::world_panel(const geom::Rect& view, const PixelBox& box) {
  const PixelTransform t =
      PixelTransform::fit(view, box.left, height() - box.bottom, box.right, height() - box.top, height());
  canvas_.set_transform(t);
  return t;
}

void Figure::world_axes(const geom::Rect& view, const PixelTransform& t) {
  const Vec2 lo = t.to_pixel({view.xmin, view.ymin}), hi = t.to_pixel({view.xmax, view.ymax});
  const int target_x = std::max(2, static_cast<int>((hi.x - lo.x) / 90));
  const int target_y = std::max(2, static_cast<int>((lo.y - hi.y) / 70));
  const auto xs = nice_ticks(view.xmin, view.xmax, target_x), ys = nice_ticks(view.ymin, view.ymax, target_y);
  const double xstep = xs.size() > 1 ? xs[1] - xs[0] : 1.0, ystep = ys.size() > 1 ? ys[1] - ys[0] : 1.0;
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
    const double y0 = box.bottom - box.height() * i / steps, y1 = box.bottom - box.height() * (i + 1) / steps;
    canvas_.pixel_line({0.5 * (box.left + box.right), y0}, {0.5 * (box.left + box.right), y1}, box.width(),
                       viridis((i + 0.5) / steps));
  }
  const auto ticks = nice_ticks(lo, hi, 5);
  const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : 1.0;
  for (double v : ticks) {
    const double y = box.bottom - box.height() * (v - lo) / (hi - lo);
    canvas_.pixel_line({box.right, y}, {box.right + 4, y}, 1.0, palette::kAxis);
    text(tick_label(v, step), box.right + 7, y + 4, 12, palette::kAxis);
  }
  text(label, 0.5 * (box.left + box.right), box.top - 10, 13, palette::kAxis, Anchor::kCenter);
}

void Figure::legend(double x, double y, const std::vector<LegendEntry>& entries) {
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const double row = y + 20.0 * i;
    canvas_.pixel_line({x, row - 4}, {x + 22, row - 4}, 5.0, entries[i].colour);
    text(entries[i].label, x + 30, row + 1, 13, palette::kAxis);
  }
}

void Figure::plot(const PixelBox& box, const std::vector<Series>& series, const std::string& title,
                  const std::string& x_label, const std::string& y_label) {
  double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin, ymin = xmin, ymax = -xmin;
  for (const Series& s : series)
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!std::isfinite(s.x[i])) continue;
      xmin = std::min(xmin, s.x[i]);  // the whole time range, even where y is undefined
      xmax = std::max(xmax, s.x[i]);
      if (!std::isfinite(s.y[i])) continue;
      ymin = std::min(ymin, s.y[i]);
      ymax = std::max(ymax, s.y[i]);
    }
  if (!(xmax > xmin)) xmin = 0, xmax = 1;
  if (!(ymax > ymin)) ymin = std::isfinite(ymin) ? ymin - 1 : 0, ymax = ymin + 2;
  ymin = std::min(ymin, 0.0);
  const double pad = 0.05 * (ymax - ymin);
  ymax += pad;
  auto px = [&](double x, double y) {
    return Vec2{box.left + box.width() * (x - xmin) / (xmax - xmin), box.bottom - box.height() * (y - ymin) / (ymax - ymin)};
  };
  canvas_.pixel_line({box.left, box.top}, {box.right, box.top}, 1.0, palette::kGrid);
  for (double y : nice_ticks(ymin, ymax, 4)) {
    const double py = px(xmin, y).y;
    canvas_.pixel_line({box.left, py}, {box.right, py}, 1.0, palette::kGrid);
  }
  for (const Series& s : series) {
    std::vector<Vec2> pts;
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
      if (std::isfinite(s.y[i])) pts.push_back(px(s.x[i], s.y[i]));
    canvas_.pixel_polyline(pts, 1.6, s.colour);
  }
  canvas_.pixel_line({box.left, box.bottom}, {box.right, box.bottom}, 1.0, palette::kAxis);
  canvas_.pixel_line({box.left, box.bottom}, {box.left, box.top}, 1.0, palette::kAxis);
  const auto xs = nice_ticks(xmin, xmax, 8), ys = nice_ticks(ymin, ymax, 4);
  const double xstep = xs.size() > 1 ? xs[1] - xs[0] : 1.0, ystep = ys.size() > 1 ? ys[1] - ys[0] : 1.0;
  for (double x : xs) {
    const Vec2 p = px(x, ymin);
    canvas_.pixel_line({p.x, box.bottom}, {p.x, box.bottom + 4}, 1.0, palette::kAxis);
    text(tick_label(x, xstep), p.x, box.bottom + 17, 12, palette::kAxis, Anchor::kCenter);
  }
  for (double y : ys) {
    const Vec2 p = px(xmin, y);
    canvas_.pixel_line({box.left - 4, p.y}, {box.left, p.y}, 1.0, palette::kAxis);
    text(tick_label(y, ystep), box.left - 7, p.y + 4, 12, palette::kAxis, Anchor::kRight);
  }
  text(title, box.left, box.top - 8, 14, palette::kAxis, Anchor::kLeft, true);
  text(x_label, 0.5 * (box.left + box.right), box.bottom + 32, 12, palette::kAxis, Anchor::kCenter);
  text(y_label, box.right, box.top - 8, 12, palette::kAxis, Anchor::kRight);
}

Image Figure::finish() {
  Image img = canvas_.read();
  TextRenderer& tr = shared_text_renderer();
  for (const QueuedText& q : texts_)
    tr.draw(img, q.s, static_cast<int>(std::lround(q.x)), static_cast<int>(std::lround(q.y)), q.size, q.colour, q.anchor,
            q.bold);
  texts_.clear();
  return img;
}

}  // namespace plantsim::render
