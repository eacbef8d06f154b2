// Seed 003 on tunnel lattices: the exit inside a ring (both hand rules come back to the
// entrance) is solved by the marker search; on a maze without loops the simplified string is
// the shortest route; the solution is driven and docked in the simulation.
#include <gtest/gtest.h>

#include <algorithm>

#include "episode/episode_config.h"
#include "episode/episode_result.h"
#include "episode/run_episode.h"
#include "planner/maze/hand_rule.h"
#include "planner/planner.h"
#include "planner/registry.h"
#include "test_paths.h"
#include "worlds/world_loader.h"

namespace plantsim::planner {
namespace {

worlds::World ring_world() {
  return worlds::load_world(test::source_file("data/worlds/plants/cable_tunnel_ring.json"));
}

// The ring world's entrance (at the start) and exit (at the staging pose) on its lattice.
std::pair<LatticeNode, LatticeNode> ring_ends(const worlds::World& w) {
  const auto entrance = w.maze->nearest_node(w.start.position());
  const auto exit = w.maze->nearest_node(worlds::staging_pose(w).position());
  EXPECT_TRUE(entrance && exit);
  return {entrance.value_or(LatticeNode{}), exit.value_or(LatticeNode{})};
}

// A named maze planner's answer on the ring world, start to staging pose.
PlanResult plan_ring(const worlds::World& w, const std::string& name) {
  auto p = make_planner(name, planner_input(w, true));
  return p->plan(w.start.position(), worlds::staging_pose(w).position());
}

// True when every point along the path (every 5 cm) is off the rock.
bool stays_in_corridors(const std::vector<Vec2>& path, const std::vector<geom::Rect>& rock) {
  for (std::size_t i = 1; i < path.size(); ++i) {
    const double len = geom::distance(path[i - 1], path[i]);
    for (double s = 0; s <= len; s += 0.05) {
      const Vec2 p = path[i - 1] + (len > 0 ? s / len : 0.0) * (path[i] - path[i - 1]);
      for (const auto& r : rock)
        if (p.x > r.xmin && p.x < r.xmax && p.y > r.ymin && p.y < r.ymax) return false;
    }
  }
  return true;
}

class RingMaze : public ::testing::TestWithParam<Hand> {};

TEST_P(RingMaze, TheHandRuleComesBackAndTheMarkerSearchReachesTheExit) {
  const worlds::World w = ring_world();
  ASSERT_TRUE(w.maze.has_value());
  const auto entrance = w.maze->nearest_node(w.start.position());
  const auto exit = w.maze->nearest_node(worlds::staging_pose(w).position());
  ASSERT_TRUE(entrance && exit);
  const MazeSolution s = solve_maze(*w.maze, *entrance, Heading::kEast, *exit, GetParam());
  EXPECT_EQ(s.exploration.end, WalkEnd::kBackAtEntrance);  // the case the document solves
  EXPECT_TRUE(s.ring_search);
  ASSERT_TRUE(s.solved()) << s.search_log;
  EXPECT_TRUE(s.route.nodes.front() == *entrance);
  EXPECT_TRUE(s.route.nodes.back() == *exit);
  // Its route is a real corridor walk, never shorter than the shortest one.
  for (std::size_t i = 1; i < s.route.nodes.size(); ++i) {
    const auto a = s.route.nodes[i - 1], b = s.route.nodes[i];
    bool joined = false;
    for (int h = 0; h < 4; ++h)
      joined = joined || (w.maze->open(a, static_cast<Heading>(h)) &&
                          worlds::TunnelMaze::step(a, static_cast<Heading>(h)) == b);
    ASSERT_TRUE(joined) << i;
  }
  const auto best = shortest_route(*w.maze, *entrance, *exit);
  ASSERT_FALSE(best.empty());
  EXPECT_GE(s.route.nodes.size(), best.size());
}

INSTANTIATE_TEST_SUITE_P(BothHands, RingMaze, ::testing::Values(Hand::kLeft, Hand::kRight));

TEST(TreeMaze, TheSimplifiedStringIsTheShortestRoute) {
  // No loops: a spine with side branches and dead ends; the exit at the far end.
  worlds::TunnelMaze m({0, 0}, 2.0, 1.0, 6, 4);
  m.open_run({0, 1}, {5, 1});
  m.open_run({1, 1}, {1, 3});
  m.open_run({1, 3}, {3, 3});
  m.open_run({2, 1}, {2, 0});
  m.open_run({3, 1}, {3, 2});
  m.open_run({4, 1}, {4, 3});
  m.open_run({4, 0}, {4, 1});
  for (Hand hand : {Hand::kLeft, Hand::kRight}) {
    const MazeSolution s = solve_maze(m, {0, 1}, Heading::kEast, {5, 1}, hand);
    EXPECT_EQ(s.exploration.end, WalkEnd::kExit);
    EXPECT_FALSE(s.ring_search);
    EXPECT_NE(s.exploration.turns.find('U'), std::string::npos);  // it met dead ends
    EXPECT_EQ(s.simplified.find('U'), std::string::npos) << s.simplified;
    ASSERT_TRUE(s.solved());
    EXPECT_EQ(s.route.nodes.size(), shortest_route(m, {0, 1}, {5, 1}).size());
    EXPECT_LT(s.route.nodes.size(), s.exploration.nodes.size());
  }
}

TEST(MazePlanner, PlansInsideTheCorridorsAndTheRobotDocks) {
  const worlds::World w = ring_world();
  for (const char* name : {"maze-left", "maze-right"}) {
    auto p = make_planner(name, planner_input(w, true));
    const PlanResult r = p->plan(w.start.position(), worlds::staging_pose(w).position());
    ASSERT_EQ(r.status, PlanStatus::kOk) << r.note;
    EXPECT_TRUE(stays_in_corridors(r.path, w.obstacles)) << name;
    EXPECT_FALSE(r.trace.explored.empty());
    EXPECT_NE(r.note.find("ring search"), std::string::npos) << r.note;
    const episode::EpisodeResult e = episode::run_episode(w, *p, episode::EpisodeConfig{});
    EXPECT_TRUE(e.docked) << name << ": " << episode::status_name(e);
    EXPECT_EQ(e.collisions, 0) << name;
  }
}

TEST(MazePlanner, TheFirstInspectionIsDrivenDeadEndsAndAll) {
  const worlds::World w = ring_world();
  auto explore = make_planner("maze-left-explore", planner_input(w, true));
  auto route = make_planner("maze-left", planner_input(w, true));
  const Vec2 goal = worlds::staging_pose(w).position();
  const PlanResult first = explore->plan(w.start.position(), goal),
                   next = route->plan(w.start.position(), goal);
  ASSERT_EQ(first.status, PlanStatus::kOk);
  EXPECT_GT(first.length,
            2.0 * next.length);  // the exploration and the search before the route is known
  EXPECT_TRUE(stays_in_corridors(first.path, w.obstacles));
  const episode::EpisodeResult e = episode::run_episode(w, *explore, episode::EpisodeConfig{});
  EXPECT_TRUE(e.docked) << episode::status_name(e);
  EXPECT_EQ(e.collisions, 0);
  EXPECT_GT(e.driven_length_m, 0.95 * first.length);  // it really went into the dead ends
}

// The document drives the third string as recorded (its Fig. 25 keeps "SRRRUSURRRR" with its
// dead end); simplifying it again is plantsim's option, and on this ring it is shorter.
TEST(RingMazeThirdString, DrivenAsRecordedByDefaultAndSimplifiedAgainOnRequest) {
  const worlds::World w = ring_world();
  const auto [entrance, exit] = ring_ends(w);
  const MazeSolution recorded = solve_maze(*w.maze, entrance, Heading::kEast, exit, Hand::kLeft);
  ASSERT_TRUE(recorded.solved());
  EXPECT_EQ(recorded.route.turns, recorded.third);
  EXPECT_NE(recorded.third.find('U'), std::string::npos) << recorded.third;  // a dead end, kept
  // Every walk of the search is kept, the last one the one that reached the exit.
  ASSERT_FALSE(recorded.attempts.empty());
  EXPECT_EQ(recorded.attempts.size(), recorded.attempt_labels.size());
  EXPECT_EQ(recorded.attempts.back().end, WalkEnd::kExit);
  for (std::size_t i = 0; i + 1 < recorded.attempts.size(); ++i)
    EXPECT_NE(recorded.attempts[i].end, WalkEnd::kExit);

  const MazeSolution again =
      solve_maze(*w.maze, entrance, Heading::kEast, exit, Hand::kLeft, ThirdString::kResimplified);
  ASSERT_TRUE(again.solved());
  EXPECT_EQ(again.third, recorded.third);
  EXPECT_LT(again.route.nodes.size(), recorded.route.nodes.size());
  EXPECT_EQ(again.route.turns.find('U'), std::string::npos) << again.route.turns;
}

// Each letter is recorded where the walk had a choice (a junction) or none (a dead end, U).
TEST(RingMazeThirdString, LettersSitAtJunctionsAndDeadEnds) {
  const worlds::World w = ring_world();
  const auto [entrance, exit] = ring_ends(w);
  const MazeSolution s = solve_maze(*w.maze, entrance, Heading::kEast, exit, Hand::kRight);
  for (const MazeWalk* walk : {&s.exploration, &s.route}) {
    ASSERT_EQ(walk->turn_at.size(), walk->turns.size());
    for (std::size_t i = 0; i < walk->turns.size(); ++i) {
      int open = 0;
      for (int h = 0; h < 4; ++h)
        open += w.maze->open(walk->nodes[walk->turn_at[i]], static_cast<Heading>(h));
      if (walk->turns[i] == 'U')
        EXPECT_EQ(open, 1) << i;
      else
        EXPECT_GE(open, 3) << i;
    }
  }
}

TEST(MazePlanner, FiguresGetTheSearchWalksAndEveryRecordedLetter) {
  const worlds::World w = ring_world();
  for (const char* name : {"maze-left", "maze-right-resimplified"}) {
    const PlanResult r = plan_ring(w, name);
    ASSERT_EQ(r.status, PlanStatus::kOk) << r.note;
    EXPECT_FALSE(r.trace.tried.empty()) << name;
    std::string explored_letters, tries;
    for (const PlanMark& m : r.trace.marks) {
      if (m.kind == PlanMark::Kind::kExplorationLetters)
        for (char c : m.text)
          if (c != ' ') explored_letters += c;
      if (m.kind == PlanMark::Kind::kTriedEnd) tries += m.text + "; ";
    }
    // The exploration string is in the note; its letters are all on the map, once each.
    const std::size_t at = r.note.find("explored ") + 9;
    std::string first = r.note.substr(at, r.note.find(' ', at) - at);
    std::sort(first.begin(), first.end());
    std::sort(explored_letters.begin(), explored_letters.end());
    EXPECT_EQ(explored_letters, first) << name;
    EXPECT_NE(tries.find(": exit"), std::string::npos) << tries;
    EXPECT_NE(
        r.note.find(std::string(name).find("resimplified") != std::string::npos ? "simplified again"
                                                                                : "as recorded"),
        std::string::npos)
        << r.note;
  }
}

TEST(MazePlanner, AWorldWithoutALatticeGetsNoPathAndTheReason) {
  const auto w = worlds::load_world(test::source_file("data/worlds/examples/small_plant.json"));
  auto p = make_planner("maze-left", planner_input(w, true));
  const PlanResult r = p->plan(w.start.position(), worlds::staging_pose(w).position());
  EXPECT_EQ(r.status, PlanStatus::kNoPath);
  EXPECT_NE(r.note.find("tunnel_maze"), std::string::npos);
}

TEST(TunnelMazeFile, ADiagonalCorridorIsRejectedNamingIt) {
  const std::string text =
      R"({"tunnel_maze": {"origin": [0, 0], "pitch_m": 2, "corridor_m": 1, "columns": 3, "rows": 3,
      "corridors": [[[0, 0], [2, 0]], [[0, 0], [1, 1]]]},
    "robot": {"radius_m": 0.2, "wheel_base_m": 0.34, "wheel_radius_m": 0.06, "max_speed_mps": 0.8, "max_accel_mps2": 1},
    "start": {"x": 0, "y": 0, "yaw": 0}, "charger": {"x": 4.0, "y": 0, "yaw": 0}})";
  try {
    worlds::parse_world_json(text, "m.json");
    FAIL() << "accepted";
  } catch (const worlds::WorldError& e) {
    EXPECT_NE(std::string(e.what()).find("tunnel_maze.corridors[1]"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace plantsim::planner
