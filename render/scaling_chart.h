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
  bool dashed = false;             ///< a second family of maps, for the same method
  std::string method;              ///< series of one method share a colour (default: the label)
};

Image draw_scaling_chart(const std::vector<ScalingSeries>& series, const std::string& title,
                         const std::string& subtitle, const std::string& x_label,
                         const std::string& y_label, int width_px = 1300, int height_px = 760,
                         FigureLayout* layout = nullptr);

}  // namespace plantsim::render
