// A log-log chart of a cost against a size, one line per method (planning time against the
// number of obstacles, from `plantsim bench planner --chart`).
#pragma once

#include <string>
#include <vector>

#include "render/figure.h"

namespace plantsim::render {

struct ScalingSeries {
  std::string label;
  std::vector<double> size, cost;  ///< positive; points where either is not are left out
};

Image draw_scaling_chart(const std::vector<ScalingSeries>& series, const std::string& title,
                         const std::string& subtitle, const std::string& x_label,
                         const std::string& y_label, int width_px = 1100, int height_px = 700,
                         FigureLayout* layout = nullptr);

}  // namespace plantsim::render
