// Panels side by side on the same world at the same scale, one planner (or setting) each,
// with its path length, planning time, graph size and docking result in the panel's title:
// the source document's Fig. 5 / Fig. 6 comparison, and every planner plantsim has.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "episode/episode_result.h"
#include "render/figure.h"

namespace plantsim::render {

struct ComparisonPanel {
  std::string label;                               ///< usually the planner's name
  episode::EpisodeResult run;                      ///< its plan (and trajectory, if driven)
  std::vector<std::pair<Vec2, Vec2>> graph_edges;  ///< drawn thin when given
  bool drove = true;                               ///< false: a plan only, no trajectory drawn
};

/// For two graph planners: "vg vs vg-traditional: path 57.83 vs 57.83 m (the same length);
/// vertices ...; edges evaluated ...; segment tests ...; plan time ..."; empty otherwise.
std::string what_differs(const ComparisonPanel& a, const ComparisonPanel& b);

Image draw_comparison(const worlds::World& world, const std::vector<ComparisonPanel>& panels,
                      const std::string& title, int width_px = 1800, int panel_height_px = 640,
                      FigureLayout* layout = nullptr);

}  // namespace plantsim::render
