// Seed 004's figure: one panel per coverage method on the same work area, cells filled by how
// often the path visits them (once: green; more: orange to red), blocked cells dark, the
// sub-regions outlined with their visiting order numbered, where each sweep starts, the path, and
// the document's metrics. A method without a plan says why in its panel.
#pragma once

#include <string>
#include <vector>

#include "planner/coverage/coverage_plan.h"
#include "render/figure.h"
#include "worlds/world.h"

namespace plantsim::render {

struct CoveragePanel {
  std::string label;
  const planner::CoverageGrid* grid = nullptr;
  planner::CoveragePlan plan;
  std::vector<Vec2> driven;  ///< the robot's trajectory, when the plan was driven
  std::string extra;         ///< one more line of text (e.g. driven coverage)
};

/// How a plan's order was found, in a line: sub-regions, order cost and the greedy one, the
/// network's share of settled restarts, the search's proof (or the failure of a plan).
std::string describe_order(const planner::CoveragePlan& plan);

/// `subtitle`: a line under the title (the document's numbers beside these).
Image draw_coverage(const worlds::World& world, const std::vector<CoveragePanel>& panels,
                    const std::string& title, const std::string& subtitle, int width_px = 1600,
                    int panel_height_px = 560, FigureLayout* layout = nullptr);

}  // namespace plantsim::render
