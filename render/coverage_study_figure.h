// The figure of seed 004's experiment repeated on generated work areas: for each obstacle share,
// repetition, turns and dead ends per map, one line per method, under lines that set the
// document's claims beside what was measured.
#pragma once

#include <string>
#include <vector>

#include "render/figure.h"

namespace plantsim::render {

struct StudyMethod {
  std::string name;
  Rgb colour;
  std::vector<double> repetition_percent, turns, dead_ends;  ///< per map; NaN where it had no plan
};

struct StudyShare {
  double blocked_share = 0;
  std::vector<StudyMethod> methods;
};

Image draw_coverage_study(const std::vector<StudyShare>& shares, const std::string& title,
                          const std::vector<std::string>& verdict_lines, int width_px = 1500,
                          FigureLayout* layout = nullptr);

}  // namespace plantsim::render
