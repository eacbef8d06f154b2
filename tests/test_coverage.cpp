// Seed 004: the decomposition partitions the work area and sweeps are complete; the cost model
// is the path (D summed along an order is exactly what the assembled cell path travels and
// turns); the exact order matches brute force and beats every other order; the document's
// network settles in a stated share of restarts and says so when it does not; the cell method
// follows the document's values and its ring search; every method covers all reachable cells
// on the document's kind of generated map; the robot sweeps a pit and docks; parameter files
// are checked.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <numeric>
#include <random>

#include "episode/episode_config.h"
#include "episode/episode_result.h"
#include "episode/run_episode.h"
#include "planner/coverage/cell_coverage.h"
#include "planner/coverage/coverage_params_json.h"
#include "planner/coverage/coverage_planner.h"
#include "planner/coverage/order_lp.h"
#include "planner/planner.h"
#include "planner/registry.h"
#include "test_paths.h"
#include "util/input_file.h"
#include "worlds/cell_block_world.h"
#include "worlds/world_error.h"
#include "worlds/world_loader.h"

namespace plantsim::planner {
namespace {

CoverageGrid grid_of(const worlds::World& w, double cell_m = 2.0) {
  const PlannerInput in = planner_input(w, true);
  return CoverageGrid(in.floor, cell_m, in.obstacles, in.inflation_m);
}

// The document's 20 x 10 grid with blocks of cells; the bottom-left cell starts.
CoverageGrid generated_map(double share, std::uint64_t seed) {
  return grid_of(worlds::cell_block_world({share, seed}));
}
// The cell the generated maps' charger is docked from.
Cell charger_cell(const CoverageGrid& g) {
  return *g.nearest_free(worlds::staging_pose(worlds::cell_block_world({0, 1})).position());
}

bool adjacent(Cell a, Cell b) {
  return std::abs(a.column - b.column) + std::abs(a.row - b.row) == 1;
}

bool is_permutation_of(std::vector<int> order, std::size_t n) {
  std::sort(order.begin(), order.end());
  std::vector<int> expected(n);
  std::iota(expected.begin(), expected.end(), 0);
  return order == expected;
}

TEST(Coverage, SweepVisitsEveryCellOfItsRectangleOnceFromEachCornerAlongEitherAxis) {
  for (CellRect r :
       {CellRect{2, 3, 5, 2}, CellRect{0, 0, 2, 6}, CellRect{1, 1, 1, 1}, CellRect{0, 0, 4, 4}})
    for (bool along_x : {true, false})
      for (int corner = 0; corner < 4; ++corner) {
        const std::vector<Cell> s = sweep(r, corner, along_x);
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

TEST(Coverage, AnEmptyRectangleIsOneSweepAlongItsLongSideWithoutRepetition) {
  const CoverageGrid g = CoverageGrid::from_rows({"......", "......", "......"});
  for (RegionOrdering o : {RegionOrdering::kChnn, RegionOrdering::kPotts, RegionOrdering::kExact,
                           RegionOrdering::kGreedy}) {
    const CoveragePlan p = plan_region_coverage(g, {0, 0}, std::nullopt, o);
    ASSERT_TRUE(p.ok);
    EXPECT_EQ(p.regions.size(), 1u);
    EXPECT_DOUBLE_EQ(p.metrics.coverage, 1.0);
    EXPECT_EQ(p.metrics.repeated_visits, 0);
    EXPECT_EQ(p.metrics.turns, 4);  // three lanes of six: two U-bends of two turns each
    EXPECT_EQ(p.metrics.dead_ends, 0);
    EXPECT_DOUBLE_EQ(p.metrics.length_m, 17 * 2.0);
  }
}

// A dead end, one definition for every method: a stretch over covered cells that ends on a new
// one. Two here (back along the bottom row to reach the top one, and back over two top cells to
// the last new cell); the way home over covered cells after the last new cell is not one.
TEST(Coverage, DeadEndsAreStretchesOverCoveredCellsThatEndOnANewOne) {
  const CoverageGrid g = CoverageGrid::from_rows({"....", "...."});
  const std::vector<Cell> path = {{0, 0}, {1, 0}, {2, 0}, {1, 0}, {1, 1}, {2, 1}, {3, 1},
                                  {3, 0}, {3, 1}, {2, 1}, {1, 1}, {0, 1}, {1, 1}, {1, 0}};
  const CoverageMetrics m = measure_coverage(g, path, {0, 0});
  EXPECT_DOUBLE_EQ(m.coverage, 1.0);
  EXPECT_EQ(m.dead_ends, 2);
  // Every method reports the count of its own path so measured.
  const CoverageGrid pit = CoverageGrid::from_rows({"......", "..##..", "......"});
  for (RegionOrdering o : {RegionOrdering::kGreedy, RegionOrdering::kExact}) {
    const CoveragePlan p = plan_region_coverage(pit, {0, 0}, Cell{5, 0}, o);
    ASSERT_TRUE(p.ok);
    EXPECT_EQ(p.metrics.dead_ends, measure_coverage(pit, p.cells, {0, 0}).dead_ends);
  }
}

// What D adds up along an order is what the assembled path travels and turns: cells stepped
// outside the sweeps (w1) and every turn (w2), the way to the end included; except the turn
// the path may make inside a one-cell region (at most two quarter turns each), which depends
// on the way out, unknown when D prices the way in.
TEST(SweepModel, TheOrderCostIsThePathsOwnTravelAndTurns) {
  int exact_matches = 0, without_single_cells = 0;
  CoverageParams params;
  // Fewer prefixes in the sanitizer tree: the cost identity holds for any order the search ends on.
  params.exact.max_prefixes = test::scaled(100000, 10000);
  const std::uint64_t last_seed = test::full_size() ? 4 : 0;  // the pit alone in the sanitizer tree
  for (std::uint64_t seed = 0; seed <= last_seed; ++seed) {
    const auto pit =
        worlds::load_world(test::source_file("data/worlds/plants/depot_pit_coverage.json"));
    const CoverageGrid g = seed == 0 ? grid_of(pit) : generated_map(0.2, seed);
    const Cell start = seed == 0 ? *g.nearest_free(pit.start.position()) : Cell{0, 0};
    const Cell end =
        seed == 0 ? *g.nearest_free(worlds::staging_pose(pit).position()) : charger_cell(g);
    for (RegionOrdering o :
         {RegionOrdering::kPotts, RegionOrdering::kGreedy, RegionOrdering::kExact}) {
      const CoveragePlan p = plan_region_coverage(g, start, end, o, params);
      ASSERT_TRUE(p.ok) << p.failure;
      const int steps = static_cast<int>(p.cells.size()) - 1;
      const int in_sweeps = p.metrics.reachable_cells - static_cast<int>(p.regions.size());
      const int single_cells = static_cast<int>(std::count_if(
          p.regions.begin(), p.regions.end(), [](const CellRect& r) { return r.cells() == 1; }));
      const double measured = 0.8 * (steps - in_sweeps) + 0.2 * p.metrics.turns;
      EXPECT_GE(measured, p.order_cost - 1e-9) << "seed " << seed;
      EXPECT_LE(measured, p.order_cost + 0.2 * 2 * single_cells + 1e-9) << "seed " << seed;
      if (single_cells == 0) {
        EXPECT_NEAR(measured, p.order_cost, 1e-9);
        ++without_single_cells;
      }
      exact_matches += std::abs(measured - p.order_cost) < 1e-9;
      EXPECT_TRUE(p.cells.back() == end);
    }
  }
  EXPECT_GT(without_single_cells, 0);
  std::printf(
      "order cost equal to the path's own measure in %d of %d plans (%d without one-cell "
      "regions)\n",
      exact_matches, 3 * static_cast<int>(last_seed + 1), without_single_cells);
}

// Brute force over every order and, for each, every sweep of every region.
double brute_force_cost(const SweepModel& m) {
  std::vector<int> order(m.regions());
  std::iota(order.begin(), order.end(), 0);
  double best = INFINITY;
  do {
    std::vector<int> v(order.size(), 0);
    for (;;) {
      double c = 0;
      int last = SweepModel::kStart, lv = 0;
      for (std::size_t k = 0; k < order.size(); ++k)
        c += m.cost(last, lv, order[k], v[k]), last = order[k], lv = v[k];
      best = std::min(best, c + m.cost_to_end(last, lv));
      std::size_t k = 0;
      while (k < v.size() && ++v[k] == m.variants(order[k])) v[k++] = 0;
      if (k == v.size()) break;
    }
  } while (std::next_permutation(order.begin(), order.end()));
  return best;
}

TEST(ExactOrder, MatchesBruteForceOverOrdersAndSweeps) {
  // Random 5 x 4 grids with a few blocked cells: those of 3 to 6 regions are searched both ways.
  std::mt19937_64 rng(11);
  int checked = 0;
  for (int trial = 0; trial < 200 && checked < 12; ++trial) {
    std::vector<std::string> rows(4, std::string(5, '.'));
    for (int k = 0; k < 4; ++k) rows[rng() % 4][rng() % 5] = '#';
    rows[3][0] = '.';  // the start, bottom-left
    const CoverageGrid g = CoverageGrid::from_rows(rows);
    const auto regions = g.decompose(g.reachable({0, 0}));
    if (regions.size() < 3 || regions.size() > 6) continue;
    const bool with_end = checked % 2 == 1;
    std::optional<Cell> end;
    if (with_end) end = Cell{regions.back().column, regions.back().row};  // the top region's corner
    const SweepModel m(g, regions, {0, 0}, end);
    const ExactOrder e = exact_order(m, {greedy_order(m)});
    ASSERT_TRUE(e.proven);
    EXPECT_NEAR(e.cost, brute_force_cost(m), 1e-9)
        << regions.size() << " regions, end " << with_end;
    EXPECT_NEAR(m.best_sweeps(e.order).cost, e.cost, 1e-9);
    EXPECT_TRUE(is_permutation_of(e.order, regions.size()));
    ++checked;
  }
  EXPECT_EQ(checked, 12);
}

TEST(ExactOrder, NoOtherMethodsOrderIsCheaperOnThePit) {
  const auto w =
      worlds::load_world(test::source_file("data/worlds/plants/depot_pit_coverage.json"));
  const CoverageGrid g = grid_of(w);
  const Cell start = *g.nearest_free(w.start.position()),
             end = *g.nearest_free(worlds::staging_pose(w).position());
  const CoveragePlan exact = plan_region_coverage(g, start, end, RegionOrdering::kExact);
  ASSERT_TRUE(exact.exact.has_value());
  EXPECT_TRUE(exact.exact->proven);  // 21 regions
  EXPECT_GT(exact.regions.size(), 20u);
  for (RegionOrdering o :
       {RegionOrdering::kChnn, RegionOrdering::kPotts, RegionOrdering::kGreedy}) {
    const CoveragePlan p = plan_region_coverage(g, start, end, o);
    ASSERT_TRUE(p.ok);
    EXPECT_GE(p.order_cost, exact.order_cost - 1e-9);
  }
  std::printf("pit: %zu regions, optimum %.2f proven in %.2f s; repetition %.2f %%\n",
              exact.regions.size(), exact.order_cost, exact.exact->seconds,
              100 * exact.metrics.repetition);
}

// The generated map with 31 regions is proven within the default limits (measured: 70.00, after
// about 60,000 prefixes); cut short, the search says so and its bound holds.
TEST(ExactOrder, ACrowdedMapIsProvenAndCutShortGivesAnHonestBound) {
  // A minute under the sanitizers; the 21-region proof of the pit takes the same path there.
  if (!test::full_size()) GTEST_SKIP() << "the 31-region proof runs in the Release tree only";
  const CoverageGrid g = generated_map(0.25, 2);
  const auto regions = g.decompose(g.reachable({0, 0}));
  ASSERT_GE(regions.size(), 30u);
  const SweepModel m(g, regions, {0, 0}, charger_cell(g));
  const std::vector<int> greedy = greedy_order(m);
  ExactOrderOptions by_count;  // the prefix count alone stops it (sanitizer builds are slow)
  by_count.time_limit_s = 600;
  const ExactOrder e = exact_order(m, {greedy}, by_count);
  EXPECT_TRUE(e.proven);
  EXPECT_TRUE(is_permutation_of(e.order, regions.size()));
  EXPECT_NEAR(m.best_sweeps(e.order).cost, e.cost, 1e-9);
  EXPECT_LT(e.cost, m.best_sweeps(greedy).cost);
  ExactOrderOptions short_search = by_count;
  short_search.max_prefixes = 1000;
  const ExactOrder cut = exact_order(m, {greedy}, short_search);
  EXPECT_FALSE(cut.proven);
  EXPECT_GE(cut.cost, e.cost - 1e-9);
  EXPECT_LE(cut.lower_bound, e.cost + 1e-9);
  EXPECT_GT(cut.lower_bound, 0.9 * e.cost);  // the relaxation: 67.20 of 70.00 measured
  std::printf(
      "%zu regions: optimum %.2f proven in %.2f s after %llu prefixes; cut short: %.2f, bound "
      "%.2f\n",
      regions.size(), e.cost, e.seconds, static_cast<unsigned long long>(e.prefixes), cut.cost,
      cut.lower_bound);
}

// The relaxation's bound holds order by order: base + the reduced costs of an order's ways is at
// most the order's cost, for random orders with their best sweeps and for orders that start with
// the prefix it was solved for; and its value is at most the optimum.
TEST(ExactOrder, TheRelaxationBoundsEveryOrderWayByWay) {
  std::mt19937_64 rng(5);
  for (std::uint64_t seed : {3u, 9u}) {
    // One sparser map in the sanitizer tree, where the proof costs ten times more.
    if (seed == 9 && !test::full_size()) break;
    const CoverageGrid g = generated_map(test::full_size() ? 0.25 : 0.15, seed);
    const SweepModel m(g, g.decompose(g.reachable({0, 0})), {0, 0}, charger_cell(g));
    ExactOrderOptions by_count;
    by_count.time_limit_s = 600;
    const ExactOrder best = exact_order(m, {greedy_order(m)}, by_count);
    ASSERT_TRUE(best.proven);
    OrderRelaxation relaxation(m);
    const auto later = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    const OrderRelaxation::Bound root = relaxation.solve({}, later);
    ASSERT_TRUE(root.solved);
    EXPECT_LE(root.value, best.cost + 1e-9);
    EXPECT_GT(root.value, 0.8 * best.cost);
    const std::vector<int> prefix(best.order.begin(), best.order.begin() + 2);
    const OrderRelaxation::Bound fixed = relaxation.solve(prefix, later);
    ASSERT_TRUE(fixed.solved);
    EXPECT_GE(fixed.value, root.value - 1e-9);  // fewer orders
    EXPECT_LE(fixed.value, best.cost + 1e-9);   // the optimum starts with the prefix
    auto reduced_cost = [&](const OrderRelaxation::Bound& b, const std::vector<int>& order) {
      const SweepModel::Sweeps s = m.best_sweeps(order);
      double sum = b.base;
      int from = SweepModel::kStart, from_sweep = 0;
      for (std::size_t k = 0; k < order.size(); ++k) {
        sum += b.reduced[relaxation.way(from, from_sweep, order[k], s.variants[k])];
        from = order[k], from_sweep = s.variants[k];
      }
      return std::pair{sum + b.reduced[relaxation.way_to_end(from, from_sweep)], s.cost};
    };
    for (int trial = 0; trial < 200; ++trial) {
      std::vector<int> order = best.order;
      std::shuffle(order.begin() + (trial % 2 == 0 ? 0 : 2), order.end(), rng);
      const auto [bound, cost] = reduced_cost(trial % 2 == 0 ? root : fixed, order);
      EXPECT_LE(bound, cost + 1e-9) << "seed " << seed << " trial " << trial;
    }
  }
}

TEST(Hopfield, SettlesOnAValidOrderInAStatedShareOfRestartsOnThePit) {
  const auto w =
      worlds::load_world(test::source_file("data/worlds/plants/depot_pit_coverage.json"));
  const CoverageGrid g = grid_of(w);
  const Cell start = *g.nearest_free(w.start.position()),
             end = *g.nearest_free(worlds::staging_pose(w).position());
  const SweepModel m(g, g.decompose(g.reachable(start)), start, end);
  const HopfieldResult r = hopfield_order(m.region_distances());
  EXPECT_EQ(r.restarts, 50);
  // Measured with the defaults: 35 of 50 (docs/seeds.md). A change that drops the share below
  // half is a change of the method.
  EXPECT_GE(r.valid, 25);
  ASSERT_TRUE(r.order.has_value());
  EXPECT_TRUE(is_permutation_of(*r.order, m.regions()));
  std::printf("Hopfield network on the pit: valid order in %d of %d restarts\n", r.valid,
              r.restarts);
}

TEST(Hopfield, WithTheOriginalActivityTargetItSettlesNowhereAndThePlannerSaysSo) {
  const auto w =
      worlds::load_world(test::source_file("data/worlds/plants/depot_pit_coverage.json"));
  const PlannerInput in = planner_input(w, true);
  CoverageParams params;
  params.chnn.eta = 500;
  params.chnn.target_ratio = 1.0;
  params.chnn.restarts = 10;
  CoveragePlanner p(in, "coverage-chnn", params);
  const PlanResult r = p.plan(w.start.position(), worlds::staging_pose(w).position());
  EXPECT_EQ(r.status, PlanStatus::kNoPath);
  EXPECT_NE(r.note.find("0 of 10 restarts"), std::string::npos) << r.note;
  EXPECT_FALSE(p.last_plan().ok);
}

TEST(CellMethod, ValuesAndTurnConfidenceAreTheDocuments) {
  EXPECT_DOUBLE_EQ(cell_value(0), 1.0);
  EXPECT_DOUBLE_EQ(cell_value(1), 0.5);
  EXPECT_DOUBLE_EQ(cell_value(3), -0.5);
  EXPECT_DOUBLE_EQ(turn_confidence(0, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(turn_confidence(std::numbers::pi / 2, 1.0), 0.5);
  EXPECT_DOUBLE_EQ(turn_confidence(std::numbers::pi, 1.0), 0.0);
  // With w1 = 0.8, w2 = 0.2 an uncovered cell straight behind still beats a covered one ahead.
  EXPECT_GT(0.8 * cell_value(0) + 0.2 * turn_confidence(std::numbers::pi, 1),
            0.8 * cell_value(1) + 0.2 * turn_confidence(0, 1));
}

TEST(CellMethod, RingSearchFindsTheEuclideanNearestUncoveredCellEvenBehindAWall) {
  // From the dead point D the cell U beyond the wall is 2 away as the crow flies but 8 cells by
  // the grid; V is 3 away both ways. The document's ring search picks U.
  const CoverageGrid g = CoverageGrid::from_rows({
      ".....",
      ".###.",
      "U#D..",
      ".#...",
      ".#.V.",
  });
  std::vector<int> visits(25, 1);
  const std::vector<bool> reach = g.reachable({2, 2});
  visits[g.index({0, 2})] = 0;  // U
  visits[g.index({3, 0})] = 0;  // V
  const auto found = ring_search(g, {2, 2}, visits, reach);
  ASSERT_TRUE(found.has_value());
  EXPECT_TRUE(*found == (Cell{0, 2}));
}

TEST(CellMethod, APocketIsADeadEndAndTheEscapeNeverWalksIntoAWall) {
  const CoverageGrid g = CoverageGrid::from_rows({
      "........",
      ".######.",
      ".#....#.",
      ".#.##.#.",
      "........",
  });
  const CoveragePlan p = plan_cell_coverage(g, {0, 0}, std::nullopt);
  EXPECT_EQ(p.metrics.covered_cells, p.metrics.reachable_cells);
  EXPECT_GE(p.metrics.dead_ends, 1);
  for (std::size_t i = 1; i < p.cells.size(); ++i) {
    ASSERT_TRUE(adjacent(p.cells[i - 1], p.cells[i]));
    ASSERT_TRUE(g.free(p.cells[i]));
  }
}

class Shares : public ::testing::TestWithParam<double> {};

TEST_P(Shares, EveryMethodCoversAllReachableCellsAndEndsAtTheCharger) {
  // The sanitizer tree runs the two lighter shares: the same paths, a third of the time.
  if (GetParam() > 0.25 && !test::full_size())
    GTEST_SKIP() << "the densest share runs in the Release tree only";
  for (std::uint64_t seed = 1; seed <= (test::full_size() ? 3u : 1u); ++seed) {
    const worlds::World w = worlds::cell_block_world({GetParam(), seed});
    const PlannerInput in = planner_input(w, true);
    CoverageParams params;
    // Proven or not, the exact order is never dearer than the greedy one it starts from.
    params.exact.max_prefixes = test::scaled(200000, 10000);
    for (const char* name : {"coverage-chnn", "coverage-potts", "coverage-exact", "coverage-greedy",
                             "coverage-cells"}) {
      CoveragePlanner planner(in, name, params);
      const PlanResult r = planner.plan(w.start.position(), worlds::staging_pose(w).position());
      if (r.status != PlanStatus::kOk) {  // only the network may find no order, and it says so
        EXPECT_STREQ(name, "coverage-chnn");
        EXPECT_NE(r.note.find("restarts"), std::string::npos);
        continue;
      }
      const CoveragePlan& p = planner.last_plan();
      EXPECT_EQ(p.metrics.covered_cells, p.metrics.reachable_cells)
          << name << " share " << GetParam() << " seed " << seed;
      ASSERT_FALSE(p.cells.empty());
      EXPECT_TRUE(p.cells.front() == *planner.grid().nearest_free(w.start.position()));
      EXPECT_TRUE(p.cells.back() ==
                  *planner.grid().nearest_free(worlds::staging_pose(w).position()));
      for (std::size_t i = 1; i < p.cells.size(); ++i) {
        ASSERT_TRUE(adjacent(p.cells[i - 1], p.cells[i])) << name << " " << i;
        ASSERT_TRUE(planner.grid().free(p.cells[i]));
      }
      if (!p.regions.empty()) {
        EXPECT_TRUE(is_permutation_of(p.order, p.regions.size()));
        EXPECT_LE(p.order_cost,
                  std::string(name) == "coverage-exact" ? p.greedy_cost + 1e-9 : INFINITY);
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(ThreeShares, Shares, ::testing::Values(0.1, 0.2, 0.3));

TEST(Coverage, TheRobotSweepsThePitAndDocks) {
  const auto w =
      worlds::load_world(test::source_file("data/worlds/plants/depot_pit_coverage.json"));
  auto p = make_planner("coverage-cells", planner_input(w, true));
  episode::EpisodeConfig config;
  config.timeout_s = 3600;
  const episode::EpisodeResult e = episode::run_episode(w, *p, config);
  EXPECT_TRUE(e.docked) << episode::status_name(e);
  EXPECT_EQ(e.collisions, 0);
  // Cells the robot's centre passed: nearly all (it turns inside corner cells).
  auto& cp = dynamic_cast<CoveragePlanner&>(*p);
  const std::vector<bool> reach = cp.grid().reachable(*cp.grid().nearest_free(w.start.position()));
  std::vector<bool> seen(reach.size(), false);
  for (const auto& s : e.trajectory)
    if (const auto c = cp.grid().cell_at(s.truth.position())) seen[cp.grid().index(*c)] = true;
  int reachable = 0, passed = 0;
  for (std::size_t i = 0; i < reach.size(); ++i)
    reachable += reach[i], passed += reach[i] && seen[i];
  EXPECT_GE(passed, 0.9 * reachable);
}

TEST(CoverageParams, TheDefaultsFileIsTheDefaults) {
  const CoverageParams p = load_coverage_params(test::source_file("configs/coverage_params.json"));
  EXPECT_EQ(coverage_params_json(p), coverage_params_json(CoverageParams{}));
}

TEST(CoverageParams, BadFilesAreRefusedNamingTheField) {
  auto refused = [](const std::string& text, const std::string& field) {
    try {
      parse_coverage_params(text, "p.json");
    } catch (const worlds::WorldError& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
      return true;
    }
    return false;
  };
  EXPECT_TRUE(refused(R"({"chnn": {"alpah": 1}})", "chnn.alpah"));
  EXPECT_TRUE(refused(R"({"chnn": {"restarts": 0}})", "chnn.restarts"));
  EXPECT_TRUE(refused(R"({"chnn": {"restarts": 2.5}})", "chnn.restarts"));
  EXPECT_TRUE(refused(R"({"w1_cells": 0.9})", "w1_cells"));
  EXPECT_TRUE(refused(R"({"exact": {"time_limit_s": "ten"}})", "exact.time_limit_s"));
  EXPECT_TRUE(refused(R"({"cell_m": 1e400})", "p.json"));  // not a double: refused as JSON
  EXPECT_TRUE(refused(R"([1, 2])", "p.json"));
  EXPECT_TRUE(refused(R"({"chnn": {"restarts": 5, "restarts": 50}})",
                      "field 'chnn.restarts': given twice"));
  EXPECT_FALSE(refused(R"({"comment": "defaults", "chnn": {"restarts": 5}})", ""));
}

}  // namespace
}  // namespace plantsim::planner
