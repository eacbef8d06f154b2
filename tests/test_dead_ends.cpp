// The dead ends of a mesh: bridges of its dual graph found exactly (against removing each edge
// and looking), the searches that skip the side of a bridge with no goal on it giving the same
// answers as without, for far less work on a map whose mesh is nearly a tree, and the funnel
// that pulls a path taut through a channel of bridges.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <random>
#include <string>

#include "planner/mesh/channel_funnel.h"
#include "planner/mesh/convex_mesh.h"
#include "planner/mesh/dead_ends.h"
#include "planner/mesh/free_space_mesh.h"
#include "planner/mesh/interval_search.h"
#include "planner/mesh/polygon_search.h"
#include "test_paths.h"
#include "worlds/grid_map.h"

namespace plantsim::planner {
namespace {

struct Graph {
  std::vector<std::int32_t> first{0}, neighbour;
};

// Undirected edges (a, b), each listed from both ends; a wall (-1) after every node's edges.
Graph graph_of(int nodes, const std::vector<std::pair<int, int>>& edges) {
  std::vector<std::vector<std::int32_t>> adjacent(nodes);
  for (const auto& [a, b] : edges) adjacent[a].push_back(b), adjacent[b].push_back(a);
  Graph g;
  for (auto& list : adjacent) {
    list.push_back(-1);
    g.neighbour.insert(g.neighbour.end(), list.begin(), list.end());
    g.first.push_back(static_cast<std::int32_t>(g.neighbour.size()));
  }
  return g;
}

// The nodes `from` reaches without crossing the edge skipped (one copy of a -> b).
std::vector<bool> reached_without(const std::vector<std::pair<int, int>>& edges, int nodes,
                                  std::size_t skipped, int from) {
  std::vector<std::vector<int>> adjacent(nodes);
  for (std::size_t e = 0; e < edges.size(); ++e)
    if (e != skipped)
      adjacent[edges[e].first].push_back(edges[e].second),
          adjacent[edges[e].second].push_back(edges[e].first);
  std::vector<bool> seen(nodes, false);
  std::vector<int> todo{from};
  seen[from] = true;
  while (!todo.empty()) {
    const int n = todo.back();
    todo.pop_back();
    for (const int m : adjacent[n])
      if (!seen[m]) seen[m] = true, todo.push_back(m);
  }
  return seen;
}

TEST(DeadEnds, TwoRingsOnAChainAndADoubledEdge) {
  // 0-1-2-0 a ring, 2-3-4 a chain, 4-5-6-4 a ring, 6-7 and then 7=8 joined twice.
  const auto g = graph_of(
      9, {{0, 1}, {1, 2}, {2, 0}, {2, 3}, {3, 4}, {4, 5}, {5, 6}, {6, 4}, {6, 7}, {7, 8}, {7, 8}});
  DeadEnds d(g.first, g.neighbour);
  EXPECT_EQ(d.bridge_count(), 3);  // 2-3, 3-4, 6-7
  const std::int32_t at0[] = {0}, at5[] = {5}, both[] = {0, 5};
  EXPECT_FALSE(d.leads_nowhere(2, 3)) << "no goal set: nothing is pruned";
  d.set_goal(at0, 1);
  EXPECT_TRUE(d.leads_nowhere(2, 3));
  EXPECT_FALSE(d.leads_nowhere(3, 2));
  EXPECT_TRUE(d.leads_nowhere(6, 7));
  EXPECT_FALSE(d.leads_nowhere(0, 1)) << "a ring is never a dead end";
  EXPECT_FALSE(d.leads_nowhere(7, 8)) << "a doubled edge is no bridge";
  d.set_goal(at5, 1);
  EXPECT_FALSE(d.leads_nowhere(2, 3));
  EXPECT_TRUE(d.leads_nowhere(4, 3));
  EXPECT_TRUE(d.leads_nowhere(6, 7));
  d.set_goal(both, 2);
  EXPECT_FALSE(d.leads_nowhere(2, 3));
  EXPECT_FALSE(d.leads_nowhere(4, 3));
}

// Against the definition on random sparse graphs (trees with a few extra edges, parallel edges
// among them, several components): crossing a -> b leads nowhere exactly when a -> b is the
// only edge between a and b's sides and b's side holds no goal.
TEST(DeadEnds, MatchRemovingEachEdgeAndLooking) {
  std::mt19937 random(7);
  for (int trial = 0; trial < 200; ++trial) {
    const int nodes = 2 + static_cast<int>(random() % 30);
    std::vector<std::pair<int, int>> edges;
    for (int n = 1; n < nodes; ++n)
      if (random() % 8)
        edges.push_back({static_cast<int>(random() % n), n});  // else a new component
    for (int extra = static_cast<int>(random() % 4); extra > 0; --extra) {
      const int a = static_cast<int>(random() % nodes), b = static_cast<int>(random() % nodes);
      if (a != b) edges.push_back({a, b});
    }
    const auto g = graph_of(nodes, edges);
    DeadEnds d(g.first, g.neighbour);
    std::vector<std::int32_t> goal{static_cast<std::int32_t>(random() % nodes)};
    if (random() % 3 == 0) goal.push_back(static_cast<std::int32_t>(random() % nodes));
    d.set_goal(goal.data(), goal.size());
    std::int64_t bridges = 0;
    for (std::size_t e = 0; e < edges.size(); ++e) {
      const auto [a, b] = edges[e];
      const auto side = reached_without(edges, nodes, e, b);
      const bool bridge = !side[a];
      bridges += bridge;
      bool goal_beyond_b = false, goal_beyond_a = false;
      const auto side_a = reached_without(edges, nodes, e, a);
      for (const std::int32_t t : goal) goal_beyond_b |= side[t], goal_beyond_a |= side_a[t];
      EXPECT_EQ(d.leads_nowhere(a, b), bridge && !goal_beyond_b)
          << "trial " << trial << " edge " << a << "-" << b;
      EXPECT_EQ(d.leads_nowhere(b, a), bridge && !goal_beyond_a)
          << "trial " << trial << " edge " << b << "-" << a;
    }
    EXPECT_EQ(d.bridge_count(), bridges) << "trial " << trial;
  }
}

TEST(DeadEnds, BridgePathIsTheRowOfBridgesOrNothing) {
  // 0-1-2-3 a chain, 3-4-5-3 a ring, 5-6 a bridge.
  const auto g = graph_of(7, {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 3}, {5, 6}});
  DeadEnds d(g.first, g.neighbour);
  std::vector<std::int32_t> path;
  ASSERT_TRUE(d.bridge_path(0, 3, path));
  EXPECT_EQ(path, (std::vector<std::int32_t>{0, 1, 2, 3}));
  ASSERT_TRUE(d.bridge_path(2, 0, path));
  EXPECT_EQ(path, (std::vector<std::int32_t>{2, 1, 0}));
  EXPECT_FALSE(d.bridge_path(0, 6, path)) << "across the ring: two ways round";
  EXPECT_TRUE(d.beyond(1, 2, 3));
  EXPECT_FALSE(d.beyond(2, 1, 3));
  EXPECT_TRUE(d.beyond(2, 1, 0));
}

double polyline(const std::vector<Vec2>& p) {
  double sum = 0;
  for (std::size_t i = 1; i < p.size(); ++i)
    sum += std::hypot(p[i].x - p[i - 1].x, p[i].y - p[i - 1].y);
  return sum;
}

TEST(ChannelFunnel, StraightWhereItCanBendAtACornerWhereItMust) {
  // Along a corridor: no bend.
  auto path = funnel_path({0, 0}, {{{1, 1}, {1, -1}}, {{2, 1}, {2, -1}}}, {3, 0.5}, 1e-12);
  EXPECT_EQ(path, (std::vector<Vec2>{{0, 0}, {3, 0.5}}));
  // East through x = 1, y in [0, 1], then south through y = 0, x in [1, 2]: round (1, 0).
  path = funnel_path({0, 0.5}, {{{1, 1}, {1, 0}}, {{2, 0}, {1, 0}}}, {2, -3}, 1e-12);
  EXPECT_EQ(path, (std::vector<Vec2>{{0, 0.5}, {1, 0}, {2, -3}}));
  EXPECT_NEAR(polyline(path), std::hypot(1, 0.5) + std::hypot(1, 3), 1e-12);
  // The same mirrored (west then north): round (-1, 0) on the other hand.
  path = funnel_path({0, -0.5}, {{{-1, -1}, {-1, 0}}, {{-2, 0}, {-1, 0}}}, {-2, 3}, 1e-12);
  EXPECT_EQ(path, (std::vector<Vec2>{{0, -0.5}, {-1, 0}, {-2, 3}}));
}

// Found by the random worlds: up a wall whose portals end on one line, the funnel closes to a
// single ray with the right end (1, 4.5) nearer than the left (1, 7); the way then turns right,
// round the nearer end. Bending at once at the left end went up to (1, 7) and back: 2.9 m longer.
TEST(ChannelFunnel, AFunnelClosedToOneRayBendsAtTheEndTheWayTurnsRound) {
  const std::vector<Portal> portals{
      {{1, 7}, {1, 4.5}}, {{1.5, 6.5}, {1, 4.5}}, {{3, 6.5}, {4, 4.5}}};
  const Vec2 goal{3.762164, 5.288768};
  const auto path = funnel_path({1, 1.5}, portals, goal, 1e-12);
  EXPECT_EQ(path, (std::vector<Vec2>{{1, 1.5}, {1, 4.5}, goal}));
}

// BigGameHunters, all 447 reference queries: its mesh is nearly a tree (2,282 polygons, 2,248
// shared edges, 2,209 of them bridges), so most of the map hangs off bridges. Measured:
// polyanya answers 155 queries by the funnel alone and expands 35,567 intervals in all (79.6 a
// query, a funnelled query counting the polygons it walks; 88 a query with the dead ends pruned
// but no funnel), 166,184 with neither (225 a query with only single dead-end polygons pruned,
// as Polyanya's authors do); the rectangle mesh's search 209,174 and 387,657 (823 a query).
TEST(DeadEnds, PruningKeepsEveryAnswerAndCutsTheWork) {
  const auto map = worlds::load_movingai_map(test::shared_data("anyangle/BigGameHunters.map"));
  const FreeSpaceMesh rectangles(
      worlds::merge_blocked_cells(map, worlds::blocked_for_anyangle),
      {0, 0, static_cast<double>(map.width), static_cast<double>(map.height)});
  const ConvexMesh polygons(rectangles);
  Graph dual;
  for (std::int32_t p = 0; p < polygons.polygon_count(); ++p) {
    dual.neighbour.insert(dual.neighbour.end(), polygons.neighbours(p),
                          polygons.neighbours(p) + polygons.size(p));
    dual.first.push_back(static_cast<std::int32_t>(dual.neighbour.size()));
  }
  EXPECT_EQ(polygons.polygon_count(), 2282);
  EXPECT_EQ(polygons.portal_count(), 2248);
  EXPECT_EQ(DeadEnds(dual.first, dual.neighbour).bridge_count(), 2209);
  PolygonSearch pruned(polygons), whole(polygons);
  IntervalSearch pruned_rectangles(rectangles), whole_rectangles(rectangles);
  whole.set_dead_end_pruning(false);
  whole_rectangles.set_dead_end_pruning(false);
  std::ifstream ref(test::shared_data("anyangle/BigGameHunters_anyangle_ref.tsv"));
  std::string header;
  std::getline(ref, header);
  int sx, sy, gx, gy, line = 0;
  double expected, octile;
  std::int64_t expanded[4] = {0, 0, 0, 0};
  int funnelled = 0;
  const auto length = [](const IntervalPath& p) {
    double sum = 0;
    for (std::size_t i = 1; i < p.path.size(); ++i)
      sum += std::hypot(p.path[i].x - p.path[i - 1].x, p.path[i].y - p.path[i - 1].y);
    return sum;
  };
  while (ref >> sx >> sy >> gx >> gy >> expected >> octile) {
    ++line;
    const Vec2 s = worlds::lattice_point(map, sx, sy), g = worlds::lattice_point(map, gx, gy);
    const IntervalPath found[4] = {pruned.find(s, g), whole.find(s, g),
                                   pruned_rectangles.find(s, g), whole_rectangles.find(s, g)};
    for (int i = 0; i < 4; ++i) {
      ASSERT_TRUE(found[i].found) << i << ": " << sx << " " << sy << " -> " << gx << " " << gy;
      EXPECT_LE(std::fabs(length(found[i]) - expected), 5e-6 * expected + 1e-5)
          << i << ": " << sx << " " << sy << " -> " << gx << " " << gy;
      expanded[i] += found[i].expanded;
    }
    funnelled += found[0].through_channel;
    EXPECT_FALSE(found[1].through_channel);
  }
  EXPECT_EQ(line, 447);
  std::cout << "BigGameHunters: " << funnelled << " queries funnelled; intervals expanded "
            << expanded[0] << " (polygons), " << expanded[1] << " (polygons, nothing pruned), "
            << expanded[2] << " (rectangles), " << expanded[3] << " (rectangles, nothing pruned)\n";
  EXPECT_GT(funnelled, 100) << "of " << line << " queries answered by the funnel";
  EXPECT_LT(expanded[0], expanded[1] * 4 / 10)
      << expanded[0] << " pruned, " << expanded[1] << " not (polygons)";
  EXPECT_LT(expanded[2], expanded[3] * 6 / 10)
      << expanded[2] << " pruned, " << expanded[3] << " not (rectangles)";
}

}  // namespace
}  // namespace plantsim::planner
