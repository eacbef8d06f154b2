// Grid maps in the MovingAI benchmark format (.map with its .scen scenario files), kept as
// the raw terrain characters so that each use can apply its own passability rule, and the
// merging of blocked cells into few axis-aligned rectangles for the geometric planners.
// Grid frame: (0, 0) is the top-left cell, x is the column, y grows downward. World frame:
// y up, so the lattice point (x, y), the top-left corner of cell (x, y), is (x, height - y).
#pragma once

#include <string>
#include <vector>

#include "worlds/world.h"

namespace plantsim::worlds {

struct GridMap {
  std::string source;
  int width = 0;
  int height = 0;
  std::vector<char> cells;  ///< row-major, row 0 at the top

  char at(int x, int y) const { return cells[static_cast<std::size_t>(y) * width + x]; }
  bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
};

/// MovingAI octile benchmarks: '.', 'G' and 'S' (swamp) passable; '@', 'O', 'T', 'W' blocked.
bool passable_for_octile(char terrain);
/// Any-angle benchmarks: every terrain but '.' and 'G' is a closed blocked square.
bool blocked_for_anyangle(char terrain);

struct Scenario {
  int bucket = 0;
  std::string map;
  int map_width = 0, map_height = 0;
  int sx = 0, sy = 0, gx = 0, gy = 0;
  double optimal = 0;  ///< the file's octile length
};

/// Throw WorldError naming the file and the line or field at fault.
GridMap load_movingai_map(const std::string& path);
std::vector<Scenario> load_movingai_scenarios(const std::string& path);

/// Blocked cells merged into rectangles (world frame, 1 m cells): runs of blocked cells in
/// each row, then identical runs in consecutive rows joined.
std::vector<Rect> merge_blocked_cells(const GridMap& map, bool (*blocked)(char));

/// World point of lattice point (x, y).
inline Vec2 lattice_point(const GridMap& map, double x, double y) { return {x, map.height - y}; }

}  // namespace plantsim::worlds
