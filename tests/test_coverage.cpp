// Seed 004: the decomposition partitions the work area, sweeps are complete, every method
// covers all reachable cells on generated maps of three obstacle densities (the document's
// 20 x 10 cells), Held-Karp is exact, the CHNN order is a valid permutation and never beats
// the exact order (the gap is printed), and the robot sweeps a pit and docks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <random>

#include "planner/coverage/coverage_planner.h"
#include "planner/planner.h"
#include "sim/episode.h"
#include "test_paths.h"
#include "worlds/world_loader.h"

namespace plantsim::planner {
namespace {

// The document's 20 x 10 grid with obstacle blocks (1-3 by 1-2 cells) until `density` of the
// cells are blocked; the start corner stays free.
CoverageGrid generated_map(double density, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<std::string> rows(10, std::string(20, '.'));
  int blocked = 0;
  while (blocked < density * 200) {
    const int w = 1 + static_cast<int>(rng() % 3), h = 1 + static_cast<int>(rng() % 2);
    const int c = static_cast<int>(rng() % (21 - w)), r = static_cast<int>(rng() % (11 - h));
    for (int y = r; y < r + h; ++y)
      for (int x = c; x < c + w; ++x)
        if ((x > 1 || y < 8) && rows[y][x] == '.') rows[y][x] = '#', ++blocked;  // row 9 is the bottom
  }
  return CoverageGrid::from_rows(rows);
}

bool adjacent(Cell a, Cell b) { return std::abs(a.column - b.column) + std::abs(a.row - b.row) == 1; }

TEST(Coverage, SweepVisitsEveryCellOfItsRectangleOnceFromEachCorner) {
  for (CellRect r : {CellRect{2, 3, 5, 2}, CellRect{0, 0, 2, 6}, CellRect{1, 1, 1, 1}, CellRect{0, 0, 4, 4}})
    for (int corner = 0; corner < 4; ++corner) {
      const std::vector<Cell> s = sweep(r, corner);
      ASSERT_EQ(static_cast<int>(s.size()), r.cells());
      for (std::size_t i = 1; i < s.size(); ++i) ASSERT_TRUE(adjacent(s[i - 1], s[i]));
      for (const Cell& c : s) ASSERT_TRUE(r.contains(c));
      for (std::size_t i = 0; i < s.size(); ++i)
        for (std::size_t j = i + 1; j < s.size(); ++j) ASSERT_FALSE(s[i] == s[j]);
    }
}

TEST(Coverage, DecompositionPartitionsTheReachableCells) {
  const CoverageGrid g = generated_map(0.2, 7);
  const std::vector<bool> reach = g.reachable({0, 0});
  std::vector<int> owners(reach.size(), 0);
  for (const CellRect& r : g.decompose(reach))
    for (int y = r.row; y < r.row + r.height; ++y)
      for (int x = r.column; x < r.column + r.width; ++x) {
        ASSERT_TRUE(g.free({x, y}));
        ++owners[g.index({x, y})];
      }
  for (std::size_t i = 0; i < reach.size(); ++i) EXPECT_EQ(owners[i], reach[i] ? 1 : 0) << i;
}

TEST(Coverage, AnEmptyRectangleIsOneSweepWithoutRepetition) {
  const CoverageGrid g = CoverageGrid::from_rows({"......", "......", "......"});
  const CoveragePlan p = plan_region_coverage(g, {0, 0}, RegionOrdering::kChnn);
  EXPECT_EQ(p.regions.size(), 1u);
  EXPECT_DOUBLE_EQ(p.metrics.coverage, 1.0);
  EXPECT_EQ(p.metrics.repeated_visits, 0);
  EXPECT_EQ(p.metrics.turns, 4);  // three lanes of six: two U-bends of two turns each
  EXPECT_EQ(p.metrics.dead_ends, 0);
  EXPECT_DOUBLE_EQ(p.metrics.length_m, 17 * 2.0);
}

class Densities : public ::testing::TestWithParam<double> {};

TEST_P(Densities, EveryMethodCoversAllReachableCells) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const CoverageGrid g = generated_map(GetParam(), seed);
    std::vector<CoveragePlan> plans;
    for (RegionOrdering o : {RegionOrdering::kChnn, RegionOrdering::kExact, RegionOrdering::kGreedy})
      plans.push_back(plan_region_coverage(g, {0, 0}, o));
    plans.push_back(plan_cell_coverage(g, {0, 0}));
    for (const CoveragePlan& p : plans) {
      EXPECT_EQ(p.metrics.covered_cells, p.metrics.reachable_cells) << "density " << GetParam() << " seed " << seed;
      EXPECT_DOUBLE_EQ(p.metrics.coverage, 1.0);
      ASSERT_FALSE(p.cells.empty());
      EXPECT_TRUE(p.cells.front() == (Cell{0, 0}));
      for (std::size_t i = 1; i < p.cells.size(); ++i) {
        ASSERT_TRUE(adjacent(p.cells[i - 1], p.cells[i])) << i;
        ASSERT_TRUE(g.free(p.cells[i]));
      }
    }
    // The CHNN's order: a permutation from the start's region, never better than the exact one.
    const CoveragePlan& chnn = plans[0];
    std::vector<int> sorted = chnn.order;
    std::sort(sorted.begin(), sorted.end());
    std::vector<int> expected(chnn.regions.size());
    std::iota(expected.begin(), expected.end(), 0);
    EXPECT_EQ(sorted, expected);
    EXPECT_TRUE(chnn.regions[chnn.order[0]].contains({0, 0}));
    if (chnn.exact_cost) {
      EXPECT_GE(chnn.order_cost, *chnn.exact_cost - 1e-9);
      EXPECT_LE(*chnn.exact_cost, chnn.greedy_cost + 1e-9);
      std::printf("density %.1f seed %llu: %zu regions, order cost CHNN %.2f, exact %.2f (CHNN +%.1f %%), greedy %.2f; "
                  "network settled on a permutation in %d of %d restarts\n",
                  GetParam(), static_cast<unsigned long long>(seed), chnn.regions.size(), chnn.order_cost,
                  *chnn.exact_cost, 100 * (chnn.order_cost / std::max(1e-9, *chnn.exact_cost) - 1), chnn.greedy_cost,
                  chnn.chnn_settled, chnn.chnn_restarts);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(ThreeDensities, Densities, ::testing::Values(0.1, 0.2, 0.3));

TEST(RegionOrder, HeldKarpMatchesBruteForce) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(1, 10);
  for (int n = 2; n <= 7; ++n) {
    DistanceMatrix d(n, std::vector<double>(n, 0));
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        if (i != j) d[i][j] = u(rng);
    std::vector<int> rest;
    for (int i = 1; i < n; ++i) rest.push_back(i);
    double best = INFINITY;
    do {
      std::vector<int> order{0};
      order.insert(order.end(), rest.begin(), rest.end());
      best = std::min(best, order_cost(d, order));
    } while (std::next_permutation(rest.begin(), rest.end()));
    const auto hk = held_karp_order(d, 0);
    ASSERT_TRUE(hk.has_value());
    EXPECT_NEAR(order_cost(d, *hk), best, 1e-9) << n;
    EXPECT_EQ(hk->front(), 0);
    const ChnnResult chnn = chnn_order(d, 0);
    EXPECT_GE(order_cost(d, chnn.order), best - 1e-9);
  }
}

TEST(Coverage, TheRobotSweepsThePitAndDocks) {
  const auto w = worlds::load_world(test::source_file("worlds/scenarios/depot_pit_coverage.json"));
  auto p = make_planner("coverage-cells", planner_input(w, true));
  sim::EpisodeConfig config;
  config.timeout_s = 3600;
  const sim::EpisodeResult e = sim::run_episode(w, *p, config);
  EXPECT_TRUE(e.docked) << e.status;
  EXPECT_EQ(e.collisions, 0);
  // Cells the robot's centre passed: nearly all (it turns inside corner cells).
  auto& cp = dynamic_cast<CoveragePlanner&>(*p);
  const std::vector<bool> reach = cp.grid().reachable(*cp.grid().nearest_free(w.start.position()));
  std::vector<bool> seen(reach.size(), false);
  for (const auto& s : e.trajectory)
    if (const auto c = cp.grid().cell_at(s.truth.position())) seen[cp.grid().index(*c)] = true;
  int reachable = 0, passed = 0;
  for (std::size_t i = 0; i < reach.size(); ++i) reachable += reach[i], passed += reach[i] && seen[i];
  EXPECT_GE(passed, 0.9 * reachable);
}

}  // namespace
}  // namespace plantsim::planner
