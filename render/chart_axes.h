// Linear chart axes shared by the batch and tuning charts: a data range mapped into a pixel box,
// and an axis drawn along its bottom or left side with a grid, ticks and numbers.
#pragma once

#include <string>

#include "render/figure.h"

namespace plantsim::render {

/// A data range mapped into a pixel box (row 0 at the top).
struct Axes {
  PixelBox box;
  double x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  double px(double x) const { return box.left + box.width() * (x - x0) / (x1 - x0); }
  double py(double y) const { return box.bottom - box.height() * (y - y0) / (y1 - y0); }
};

/// The bottom (horizontal) or left axis of `a`: line, grid, ticks and numbers (value x scale,
/// with a suffix such as " %"), and the label under a horizontal one.
void axis(Figure& fig, const Axes& a, bool horizontal, const std::string& label = "",
          double scale = 1.0, const std::string& suffix = "");

}  // namespace plantsim::render
