// Grid map to world.
#include "worlds/movingai_world.h"

#include <cmath>

#include "worlds/charger_placement.h"
#include "worlds/known_keys.h"
#include "worlds/names.h"
#include "worlds/world_error.h"
#include "worlds/world_loader.h"

namespace plantsim::worlds {

World world_from_movingai(const std::string& map_path, const std::string& scen_path, int query,
                          std::optional<Pose2> start, std::optional<Pose2> charger) {
  const GridMap map = load_movingai_map(map_path);
  World w;
  w.name = name_from_file(map_path, "rename the map file");
  w.source = map_path;
  w.floor = {0.0, 0.0, static_cast<double>(map.width), static_cast<double>(map.height)};
  w.obstacles = merge_blocked_cells(map, blocked_for_anyangle);
  w.inflation_margin_m = kBenchmarkInflation_m - w.robot.radius_m;
  auto cell_centre = [&](int x, int y) { return Vec2{x + 0.5, map.height - y - 0.5}; };
  if (!start || !charger) {
    if (scen_path.empty())
      throw WorldError(
          map_path, "",
          "a MovingAI map needs --scen FILE (with --query K) or both --start and --charger");
    const std::vector<Scenario> queries = load_movingai_scenarios(scen_path);
    if (query < 0 || query >= static_cast<int>(queries.size()))
      throw WorldError(scen_path, "query",
                       "has " + std::to_string(queries.size()) + " queries; --query " +
                           std::to_string(query) + " is not one of them (from 0)");
    const Scenario& q = queries[static_cast<std::size_t>(query)];
    if (q.map_width != map.width || q.map_height != map.height)
      throw WorldError(scen_path, "query",
                       "is for a " + std::to_string(q.map_width) + " x " +
                           std::to_string(q.map_height) + " map, not this " +
                           std::to_string(map.width) + " x " + std::to_string(map.height) + " one");
    const Vec2 s = cell_centre(q.sx, q.sy), g = cell_centre(q.gx, q.gy);
    if (!start) start = Pose2{s.x, s.y, std::atan2(g.y - s.y, g.x - s.x)};
    if (!charger) {
      w.start = *start;
      check_pose_free(w, {g.x, g.y, 0.0}, "goal");
      const auto heading = choose_docking_heading(w, g);
      if (!heading)
        throw WorldError(scen_path, "query",
                         "no heading leaves room for a charger at the goal cell");
      charger = Pose2{g.x, g.y, *heading};
    }
  }
  w.start = *start;
  w.charger = *charger;
  validate_world(w);
  return w;
}

}  // namespace plantsim::worlds
