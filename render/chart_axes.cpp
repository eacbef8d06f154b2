// Drawing a chart axis.
#include "render/chart_axes.h"

#include "render/colormap.h"
#include "render/palette.h"

namespace plantsim::render {

void axis(Figure& fig, const Axes& a, bool horizontal, const std::string& label, double scale,
          const std::string& suffix) {
  GlCanvas& c = fig.canvas();
  const PixelBox& b = a.box;
  const double lo = horizontal ? a.x0 : a.y0, hi = horizontal ? a.x1 : a.y1;
  c.pixel_line({b.left, b.bottom}, horizontal ? Vec2{b.right, b.bottom} : Vec2{b.left, b.top}, 1.0,
               palette::kAxis);
  const auto ticks = nice_ticks(lo, hi, horizontal ? 6 : 5);
  const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : 1.0;
  for (double v : ticks) {
    if (v < lo - 1e-9 || v > hi + 1e-9) continue;
    const std::string number = tick_label(v * scale, step * scale) + suffix;
    if (horizontal) {
      c.pixel_line({a.px(v), b.top}, {a.px(v), b.bottom}, 1.0, palette::kGrid);
      c.pixel_line({a.px(v), b.bottom}, {a.px(v), b.bottom + 4}, 1.0, palette::kAxis);
      fig.text(number, a.px(v), b.bottom + 17, 12, palette::kAxis, Anchor::kCenter);
    } else {
      c.pixel_line({b.left, a.py(v)}, {b.right, a.py(v)}, 1.0, palette::kGrid);
      fig.text(number, b.left - 7, a.py(v) + 4, 12, palette::kAxis, Anchor::kRight);
    }
  }
  if (horizontal)
    fig.text(label, 0.5 * (b.left + b.right), b.bottom + 34, 13, palette::kAxis, Anchor::kCenter);
}

}  // namespace plantsim::render
