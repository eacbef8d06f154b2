// Grid maps: the any-angle arena against Polyanya's reference lengths, the grid A* baseline
// against MovingAI's optimal octile lengths, merging of blocked cells, and bad map files.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "planner/grid/grid_astar.h"
#include "planner/planner.h"
#include "planner/registry.h"
#include "test_paths.h"
#include "worlds/grid_map.h"
#include "worlds/world_error.h"

namespace plantsim {
namespace {

std::unique_ptr<planner::Planner> anyangle_planner(const worlds::GridMap& map,
                                                   const char* method = "vg", int landmarks = 0) {
  planner::PlannerInput in;
  in.floor = {0, 0, static_cast<double>(map.width), static_cast<double>(map.height)};
  in.obstacles = worlds::merge_blocked_cells(map, worlds::blocked_for_anyangle);
  in.inflation_m = 0;
  if (landmarks > 0) in.options.set("landmarks", landmarks);
  return planner::make_planner(method, in);
}

// The exact planners: the visibility graph, and interval search over the rectangle mesh (with
// and without landmarks) and over convex polygons (polyanya).
TEST(AnyAngle, ArenaMatchesPolyanyaReferenceOnAll160Queries) {
  const auto map = worlds::load_movingai_map(test::shared_data("anyangle/arena.map"));
  for (const char* method : {"vg", "interval", "interval+landmarks", "polyanya"}) {
    const bool landmarks = std::string(method) == "interval+landmarks";
    auto planner = landmarks ? anyangle_planner(map, "interval", 6) : anyangle_planner(map, method);
    std::ifstream ref(test::shared_data("anyangle/arena_anyangle_ref.tsv"));
    std::string header;
    std::getline(ref, header);
    int sx, sy, gx, gy, checked = 0;
    double expected, octile;
    while (ref >> sx >> sy >> gx >> gy >> expected >> octile) {
      const auto r =
          planner->plan(worlds::lattice_point(map, sx, sy), worlds::lattice_point(map, gx, gy));
      ASSERT_EQ(r.status, planner::PlanStatus::kOk)
          << method << " " << sx << " " << sy << " " << gx << " " << gy;
      EXPECT_LE(std::fabs(r.length - expected), 5e-6 * expected + 1e-5)
          << method << " " << sx << " " << sy << " -> " << gx << " " << gy << ": " << r.length
          << " vs " << expected;
      EXPECT_LE(r.length,
                octile + 5e-6 * octile + 1e-5);  // never longer than octile (printed rounded)
      ++checked;
    }
    EXPECT_EQ(checked, 160) << method;
  }
}

// What the landmarks are for: on a large map (ArcticStation, every 4th reference query), the
// same answers from fewer expanded intervals (measured: 543,641 with 8 landmarks against
// 873,371 without). Not BigGameHunters: there the dead ends already keep the search near the
// way (49,532 without landmarks; landmarks cut only 9 % more).
TEST(AnyAngle, LandmarksKeepTheAnswersAndCutTheWork) {
  const auto map = worlds::load_movingai_map(test::shared_data("anyangle/ArcticStation.map"));
  auto plain = anyangle_planner(map, "interval");
  auto alt = anyangle_planner(map, "interval", 8);
  std::ifstream ref(test::shared_data("anyangle/ArcticStation_anyangle_ref.tsv"));
  std::string header;
  std::getline(ref, header);
  int sx, sy, gx, gy, line = 0;
  double expected, octile;
  std::int64_t expanded_plain = 0, expanded_alt = 0;
  while (ref >> sx >> sy >> gx >> gy >> expected >> octile) {
    if (line++ % 4) continue;
    const geom::Vec2 s = worlds::lattice_point(map, sx, sy), g = worlds::lattice_point(map, gx, gy);
    const auto a = plain->plan(s, g), b = alt->plan(s, g);
    ASSERT_EQ(b.status, planner::PlanStatus::kOk) << sx << " " << sy << " " << gx << " " << gy;
    EXPECT_LE(std::fabs(b.length - expected), 5e-6 * expected + 1e-5)
        << sx << " " << sy << " -> " << gx << " " << gy;
    EXPECT_NEAR(a.length, b.length, 1e-9 * (1 + a.length));
    expanded_plain += a.stats.expanded, expanded_alt += b.stats.expanded;
  }
  EXPECT_GT(line, 400);
  EXPECT_LT(expanded_alt, expanded_plain * 75 / 100)
      << expanded_alt << " with landmarks, " << expanded_plain << " without";
}

// What the convex polygons are for: on BigGameHunters (every 4th reference query) a path
// crosses one polygon where it crossed many rectangles cut at each step of a staircase wall,
// so polyanya reaches the same answers expanding under half the intervals (measured over all
// 447, `test_dead_ends`: 79.6 against 468 per query, a query answered by the funnel counting
// the polygons it walks; 225 against 823 before the dead ends were pruned).
TEST(AnyAngle, ConvexPolygonsKeepTheAnswersAndHalveTheWork) {
  const auto map = worlds::load_movingai_map(test::shared_data("anyangle/BigGameHunters.map"));
  auto rectangles = anyangle_planner(map, "interval");
  auto polygons = anyangle_planner(map, "polyanya");
  std::ifstream ref(test::shared_data("anyangle/BigGameHunters_anyangle_ref.tsv"));
  std::string header;
  std::getline(ref, header);
  int sx, sy, gx, gy, line = 0;
  double expected, octile;
  std::int64_t expanded_rectangles = 0, expanded_polygons = 0;
  while (ref >> sx >> sy >> gx >> gy >> expected >> octile) {
    if (line++ % 4) continue;
    const geom::Vec2 s = worlds::lattice_point(map, sx, sy), g = worlds::lattice_point(map, gx, gy);
    const auto a = rectangles->plan(s, g), b = polygons->plan(s, g);
    ASSERT_EQ(b.status, planner::PlanStatus::kOk) << sx << " " << sy << " " << gx << " " << gy;
    EXPECT_LE(std::fabs(b.length - expected), 5e-6 * expected + 1e-5)
        << sx << " " << sy << " -> " << gx << " " << gy;
    expanded_rectangles += a.stats.expanded, expanded_polygons += b.stats.expanded;
  }
  EXPECT_GT(line, 400);
  EXPECT_LT(expanded_polygons, expanded_rectangles / 2)
      << expanded_polygons << " over convex polygons, " << expanded_rectangles
      << " over rectangles";
}

TEST(GridBaseline, ReproducesMovingAIOctileLengthsOnEveryTenthScenario) {
  int checked = 0;
  for (const char* name : {"arena", "den009d", "den101d", "den201d", "den204d"}) {
    const auto map =
        worlds::load_movingai_map(test::shared_data(std::string("movingai/maps/") + name + ".map"));
    const auto scen = worlds::load_movingai_scenarios(
        test::shared_data(std::string("movingai/scen/") + name + ".map.scen"));
    ASSERT_FALSE(scen.empty()) << name;
    for (std::size_t i = 0; i < scen.size(); i += 10) {
      const auto& s = scen[i];
      ASSERT_EQ(s.map_width, map.width);
      const auto r = planner::grid_astar(
          map.width, map.height,
          [&](int x, int y) { return worlds::passable_for_octile(map.at(x, y)); }, s.sx, s.sy, s.gx,
          s.gy);
      ASSERT_TRUE(r.found) << name << " line " << i;
      // The scenario files print lengths rounded to 5 or 6 significant digits.
      EXPECT_NEAR(r.length, s.optimal, 1e-4 * std::max(1.0, s.optimal / 100))
          << name << " line " << i;
      ++checked;
    }
  }
  EXPECT_GT(checked, 80);
}

TEST(GridBaseline, NoCornerCutting) {
  // . #      From (0,0) to (1,1) the diagonal squeezes past the blocked corner: refused,
  // # .      and with both orthogonal cells blocked there is no path at all.
  const std::vector<char> cells = {'.', '@', '@', '.'};
  auto free = [&](int x, int y) { return cells[y * 2 + x] == '.'; };
  EXPECT_FALSE(planner::grid_astar(2, 2, free, 0, 0, 1, 1).found);
  const std::vector<char> open = {'.', '.', '@', '.'};
  auto free2 = [&](int x, int y) { return open[y * 2 + x] == '.'; };
  const auto r = planner::grid_astar(2, 2, free2, 0, 0, 1, 1);
  ASSERT_TRUE(r.found);
  EXPECT_DOUBLE_EQ(r.length, 2.0);
}

TEST(GridMaps, MergedRectanglesCoverExactlyTheBlockedCells) {
  const auto map = worlds::load_movingai_map(test::shared_data("movingai/maps/den101d.map"));
  const auto rects = worlds::merge_blocked_cells(map, worlds::blocked_for_anyangle);
  int blocked = 0;
  for (char c : map.cells) blocked += worlds::blocked_for_anyangle(c);
  double area = 0;
  for (const auto& r : rects) area += r.width() * r.height();
  EXPECT_DOUBLE_EQ(area, blocked);  // disjoint by construction, so areas add up
  EXPECT_LT(rects.size() * 3, static_cast<std::size_t>(blocked));  // real merging happened
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) {
      const geom::Vec2 centre{x + 0.5, map.height - y - 0.5};
      bool covered = false;
      for (const auto& r : rects)
        covered |= r.xmin < centre.x && centre.x < r.xmax && r.ymin < centre.y && centre.y < r.ymax;
      ASSERT_EQ(covered, worlds::blocked_for_anyangle(map.at(x, y))) << x << "," << y;
    }
}

TEST(GridMaps, BadFilesNameTheFileAndTheField) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("plantsim_maps_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  auto write = [&](const std::string& name, const std::string& text) {
    const auto p = (dir / name).string();
    std::ofstream(p) << text;
    return p;
  };
  auto expect = [](const std::string& path, const std::string& needle) {
    try {
      worlds::load_movingai_map(path);
      FAIL() << path;
    } catch (const worlds::WorldError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
  };
  expect(write("short.map", "type octile\nheight 3\nwidth 2\nmap\n..\n..\n"), "row 2");
  expect(write("wide.map", "type octile\nheight 1\nwidth 2\nmap\n...\n"), "has 3 cells");
  expect(write("nohead.map", "height 1\n"), "type");
  // A byte that is no terrain letter is refused where it is, not read as a wall.
  expect(write("nul.map", std::string("type octile\nheight 2\nwidth 3\nmap\n...\n.") +
                              std::string(1, '\0') + ".\n"),
         "field 'row 1': column 1 holds a character that is not MovingAI terrain");
  expect(write("lower.map", "type octile\nheight 1\nwidth 3\nmap\n.t.\n"), "column 1");
  expect(dir.string(), "is a directory");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace plantsim
