// MovingAI file parsing and blocked-cell merging.
#include "worlds/grid_map.h"

#include <cmath>
#include <map>
#include <sstream>

#include "util/input_file.h"
#include "worlds/world_error.h"
#include "worlds/world_limits.h"

namespace plantsim::worlds {

bool passable_for_octile(char t) { return t == '.' || t == 'G' || t == 'S'; }
bool blocked_for_anyangle(char t) { return !(t == '.' || t == 'G'); }

namespace {

std::istringstream open_text(const std::string& path) {
  try {
    return std::istringstream(util::read_input_file(path));
  } catch (const util::InputFileError& e) {
    throw WorldError(path, "", e.what());
  }
}

int header_value(std::istream& in, const std::string& path, const std::string& key) {
  std::string word;
  int value = 0;
  if (!(in >> word) || word != key || !(in >> value))
    throw WorldError(path, key, "expected the header line '" + key + " N'");
  return value;
}

}  // namespace

GridMap load_movingai_map(const std::string& path) {
  std::istringstream f = open_text(path);
  GridMap m;
  m.source = path;
  std::string word, type;
  if (!(f >> word >> type) || word != "type")
    throw WorldError(path, "type", "expected 'type octile' first");
  m.height = header_value(f, path, "height");
  m.width = header_value(f, path, "width");
  if (m.width <= 0 || m.height <= 0) throw WorldError(path, "width/height", "must be positive");
  if (static_cast<double>(m.width) * m.height > 64.0e6)
    throw WorldError(path, "width/height", "map too large (more than 64 million cells)");
  if (!(f >> word) || word != "map")
    throw WorldError(path, "map", "expected the line 'map' before the rows");
  m.cells.reserve(static_cast<std::size_t>(m.width) * m.height);
  std::string row;
  std::getline(f, row);  // rest of the 'map' line
  for (int y = 0; y < m.height; ++y) {
    if (!std::getline(f, row))
      throw WorldError(path, "row " + std::to_string(y), "missing (file too short)");
    if (!row.empty() && row.back() == '\r') row.pop_back();
    if (static_cast<int>(row.size()) != m.width)
      throw WorldError(
          path, "row " + std::to_string(y),
          "has " + std::to_string(row.size()) + " cells, expected " + std::to_string(m.width));
    // The benchmark's own terrain letters only: any other byte (a stray NUL, a letter of another
    // format) has no defined meaning, and reading it as a wall would plan round a typo.
    const std::size_t bad = row.find_first_not_of(".G@OTSW");
    if (bad != std::string::npos)
      throw WorldError(path, "row " + std::to_string(y),
                       "column " + std::to_string(bad) +
                           " holds a character that is not MovingAI terrain (. G @ O T S W)");
    m.cells.insert(m.cells.end(), row.begin(), row.end());
  }
  return m;
}

std::vector<Scenario> load_movingai_scenarios(const std::string& path) {
  std::istringstream f = open_text(path);
  std::string line;
  std::vector<Scenario> out;
  int line_no = 0;
  while (std::getline(f, line)) {
    ++line_no;
    if (line.empty() || line.rfind("version", 0) == 0) continue;
    std::istringstream in(line);
    Scenario s;
    if (!(in >> s.bucket >> s.map >> s.map_width >> s.map_height >> s.sx >> s.sy >> s.gx >> s.gy >>
          s.optimal))
      throw WorldError(path, "line " + std::to_string(line_no),
                       "expected 'bucket map width height sx sy gx gy optimal'");
    if (s.map_width <= 0 || s.map_height <= 0 || s.sx < 0 || s.sy < 0 || s.gx < 0 || s.gy < 0 ||
        s.sx >= s.map_width || s.gx >= s.map_width || s.sy >= s.map_height ||
        s.gy >= s.map_height || !std::isfinite(s.optimal))
      throw WorldError(path, "line " + std::to_string(line_no),
                       "start or goal outside the map's width and height");
    if (out.size() >= 1000000)
      throw WorldError(path, "line " + std::to_string(line_no), "more than 1000000 queries");
    out.push_back(s);
  }
  return out;
}

std::vector<Rect> merge_blocked_cells(const GridMap& m, bool (*blocked)(char)) {
  struct Open {
    int y0;  // first row of the rectangle
  };
  std::vector<Rect> out;
  std::map<std::pair<int, int>, Open> open;  // run [x0, x1) -> rows so far
  auto close = [&](std::pair<int, int> run, int y0, int y_end) {
    // The one obstacle limit of every world, checked as the rectangles are made: a 5 kB
    // checkerboard image must not become two million obstacles before anyone counts them.
    if (out.size() >= kMaxObstacles)
      throw WorldError(m.source, "",
                       "its blocked cells make more than " + std::to_string(kMaxObstacles) +
                           " rectangles, the limit for any world (docs/world_format.md)");
    // Rows y0 .. y_end-1 (grid, downward) become world y from height - y_end to height - y0.
    out.push_back({static_cast<double>(run.first), static_cast<double>(m.height - y_end),
                   static_cast<double>(run.second), static_cast<double>(m.height - y0)});
  };
  for (int y = 0; y <= m.height; ++y) {
    std::map<std::pair<int, int>, Open> next;
    if (y < m.height) {
      for (int x = 0; x < m.width;) {
        if (!blocked(m.at(x, y))) {
          ++x;
          continue;
        }
        int x1 = x;
        while (x1 < m.width && blocked(m.at(x1, y))) ++x1;
        const auto run = std::make_pair(x, x1);
        auto it = open.find(run);
        next[run] = it != open.end() ? it->second : Open{y};
        if (it != open.end()) open.erase(it);
        x = x1;
      }
    }
    for (const auto& [run, o] : open) close(run, o.y0, y);
    open = std::move(next);
  }
  return out;
}

}  // namespace plantsim::worlds
