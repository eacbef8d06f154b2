// Planner answers against known optima (shared/data/worlds, from an independent brute-force
// visibility graph with 0.3 m square inflation), and the statuses for bad queries.
#include <gtest/gtest.h>

#include "planner/obstacle_map.h"
#include "planner/planner.h"
#include "planner/registry.h"
#include "planner/vg/vg_planner.h"
#include "test_paths.h"
#include "worlds/world_loader.h"

namespace plantsim::planner {
namespace {

struct KnownOptimum {
  const char* file;
  double length;  // ../shared/data/README.md
};

class KnownWorlds : public ::testing::TestWithParam<KnownOptimum> {};

TEST_P(KnownWorlds, FastPlannerFindsTheOptimalLength) {
  const auto world = worlds::load_world(test::shared_data(GetParam().file));
  PlannerInput in = planner_input(world, false);
  ASSERT_DOUBLE_EQ(in.inflation_m, 0.3);
  auto p = make_planner("vg", in);
  const PlanResult r = p->plan(world.start.position(), world.charger.position());
  ASSERT_EQ(r.status, PlanStatus::kOk);
  EXPECT_NEAR(r.length, GetParam().length, 1e-6);
  EXPECT_EQ(r.path.front(), world.start.position());
  EXPECT_EQ(r.path.back(), world.charger.position());
}

INSTANTIATE_TEST_SUITE_P(SharedData, KnownWorlds,
                         ::testing::Values(KnownOptimum{"worlds/world_N10.json", 94.490208432},
                                           KnownOptimum{"worlds/world_N50.json", 98.808046206},
                                           KnownOptimum{"worlds/world_N200.json", 95.155793238},
                                           KnownOptimum{"worlds/world_N1000.json", 97.127599918}));

TEST(TraditionalPlanner, SameLengthAndTheDocumentedVisiblePairs) {
  // The README lists 259 and 2561 corner-to-corner visible pairs for N10 and N50.
  const std::pair<const char*, std::int64_t> cases[] = {{"worlds/world_N10.json", 259},
                                                        {"worlds/world_N50.json", 2561}};
  for (const auto& [file, pairs] : cases) {
    const auto world = worlds::load_world(test::shared_data(file));
    const PlannerInput in = planner_input(world, false);
    auto fast = make_planner("vg", in);
    auto traditional = make_planner("vg-traditional", in);
    const auto a = fast->plan(world.start.position(), world.charger.position());
    const auto b = traditional->plan(world.start.position(), world.charger.position());
    ASSERT_EQ(b.status, PlanStatus::kOk);
    EXPECT_NEAR(a.length, b.length, 1e-9) << file;
    EXPECT_EQ(b.stats.edges, pairs) << file;
    EXPECT_LT(a.stats.vertices, b.stats.vertices + 1) << file;
  }
}

PlannerInput box_world() {
  PlannerInput in;
  in.floor = {0, 0, 10, 10};
  in.obstacles = {{4, 4, 6, 6}};
  in.inflation_m = 0.5;
  return in;
}

TEST(PlannerStatus, StartOrGoalInsideInflatedObstacleOrOffFloor) {
  auto p = make_planner("vg", box_world());
  EXPECT_EQ(p->plan({5, 5}, {1, 1}).status, PlanStatus::kStartBlocked);
  EXPECT_EQ(p->plan({1, 1}, {3.8, 5}).status, PlanStatus::kGoalBlocked);  // in the margin
  EXPECT_EQ(p->plan({1, 1}, {0.2, 5}).status, PlanStatus::kGoalBlocked);  // wall margin
  EXPECT_EQ(p->plan({-3, 1}, {1, 5}).status, PlanStatus::kStartBlocked);  // off the floor
}

TEST(PlannerStatus, EnclosedGoalHasNoPath) {
  PlannerInput in;
  in.floor = {0, 0, 10, 10};
  in.obstacles = {{3, 3, 7, 3.2}, {3, 6.8, 7, 7}, {3, 3, 3.2, 7}, {6.8, 3, 7, 7}};
  in.inflation_m = 0.1;
  for (const char* name : {"vg", "vg-traditional"}) {
    auto p = make_planner(name, in);
    const auto r = p->plan({1, 1}, {5, 5});
    EXPECT_EQ(r.status, PlanStatus::kNoPath) << name;
    EXPECT_TRUE(r.path.empty());
  }
}

TEST(PlannerStatus, GoesAroundABoxWithTheExactLength) {
  auto p = make_planner("vg", box_world());
  // Around the inflated box [3.5, 6.5]^2: start (1,5) to goal (9,5) bends at two corners.
  const auto r = p->plan({1, 5}, {9, 5});
  ASSERT_EQ(r.status, PlanStatus::kOk);
  const double leg = std::hypot(2.5, 1.5);
  EXPECT_NEAR(r.length, 2 * leg + 3.0, 1e-12);
}

// Two rows of small boxes along a corridor (brackets on a tunnel's walls), the start behind one
// row at one end and the goal behind the other at the far end: the gap corners see each other
// across the corridor, so the exact searches grow with the square of the boxes (8,000 boxes:
// vg 102 s and 4.9 GB, interval 2.3 GB). Past its memory budget a search stops and says so.
TEST(PlannerStatus, ASearchPastItsMemoryBudgetStopsAndSaysSo) {
  PlannerInput in;
  const int per_row = 60;
  const double length = 2 * per_row + 10;
  in.floor = {0, 0, length, 12};
  for (int i = 0; i < per_row; ++i) {
    const double x = 5 + 2 * i;
    in.obstacles.push_back({x, 1, x + 1, 2});
    in.obstacles.push_back({x, 10, x + 1, 11});
  }
  in.inflation_m = 0.3;
  const Vec2 start{3, 0.5}, goal{length - 3, 11.5};
  double vg_length = 0;
  for (const char* name : {"vg", "interval", "polyanya"}) {
    const PlanResult within = make_planner(name, in)->plan(start, goal);
    ASSERT_EQ(within.status, PlanStatus::kOk) << name;
    if (vg_length == 0) vg_length = within.length;
    EXPECT_NEAR(within.length, vg_length, 1e-9 * vg_length) << name;
    PlannerInput tight = in;
    tight.search_budget_bytes = std::size_t{64} << 10;
    const PlanResult stopped = make_planner(name, tight)->plan(start, goal);
    EXPECT_EQ(stopped.status, PlanStatus::kSearchLimit) << name;
    EXPECT_TRUE(stopped.path.empty()) << name;
    EXPECT_NE(stopped.note.find("memory budget of 0.1 MiB"), std::string::npos)
        << name << ": " << stopped.note;
  }
}

TEST(PlannerRegistry, UnknownNameThrows) {
  EXPECT_THROW(make_planner("teleport", box_world()), std::invalid_argument);
}

}  // namespace
}  // namespace plantsim::planner

namespace plantsim::planner {
namespace {

TEST(PlannerSnap, BlockedEndsMoveToTheNearestFreePointAndSaySo) {
  PlannerInput in = box_world();  // inflated box [3.5, 6.5]^2 in a 10 x 10 floor, walls at 0.5
  in.snap_to_free = true;
  for (const char* name : {"vg", "vg-traditional"}) {
    auto p = make_planner(name, in);
    const auto r = p->plan({5.0, 6.0}, {9, 9});  // start inside: nearest free point (5, 6.5)
    ASSERT_EQ(r.status, PlanStatus::kOk) << name;
    EXPECT_TRUE(r.start_snapped);
    EXPECT_FALSE(r.goal_snapped);  // (9, 9) is free: walls inflated to 9.5
    EXPECT_EQ(r.path.front(), (Vec2{5.0, 6.5}));
    const auto off = p->plan({1, 1}, {12, 5});  // goal off the floor: clamped to (9.5, 5)
    ASSERT_EQ(off.status, PlanStatus::kOk);
    EXPECT_TRUE(off.goal_snapped);
    EXPECT_EQ(off.path.back(), (Vec2{9.5, 5}));
  }
  in.snap_to_free = false;
  EXPECT_EQ(make_planner("vg", in)->plan({5.0, 6.0}, {9, 9}).status, PlanStatus::kStartBlocked);
}

TEST(PlannerSnap, DeepInsideMergedObstaclesFindsTheConcaveCornerSide) {
  PlannerInput in;
  in.floor = {0, 0, 20, 20};
  in.inflation_m = 0;
  in.obstacles = {{5, 5, 15, 8}, {5, 8, 8, 15}};  // an L; (7.5, 9) lies inside its upright arm
  in.snap_to_free = true;
  auto p = make_planner("vg", in);
  const auto r = p->plan({7.5, 9}, {1, 1});  // nearest boundary: x = 8 at distance 0.5
  ASSERT_EQ(r.status, PlanStatus::kOk);
  EXPECT_EQ(r.path.front(), (Vec2{8, 9}));
}

// Pinch points are where two rectangles touch only at a corner; a concave corner is not one,
// and the segments through it are refused by the other tests all the same.
TEST(ObstacleMapPinches, DiagonalTouchIsAPinchAConcaveCornerIsNot) {
  const Rect floor{-5, -5, 5, 5};
  const ObstacleMap diagonal({{0, 0, 1, 1}, {1, 1, 2, 2}}, floor, 0);
  ASSERT_EQ(diagonal.pinch_points().size(), 1u);
  EXPECT_TRUE(diagonal.is_pinch_point({1, 1}));
  EXPECT_FALSE(diagonal.segment_free({0, 2}, {2, 0}));  // squeezes through the touching corners
  EXPECT_TRUE(diagonal.segment_free({0, 2}, {1, 1}));   // ends there

  const ObstacleMap ell({{0, 0, 2, 1}, {0, 1, 1, 2}}, floor, 0);  // concave corner at (1, 1)
  EXPECT_TRUE(ell.pinch_points().empty());
  EXPECT_FALSE(ell.segment_free({2, 2}, {0, 0}));   // into the rectangles
  EXPECT_FALSE(ell.segment_free({2, 1}, {-1, 1}));  // between them along their shared edge
  EXPECT_FALSE(ell.segment_free({1, 3}, {1, -1}));  // down through the lower one
  EXPECT_TRUE(ell.segment_free({1, 1}, {2, 2}));    // from the corner into the free quadrant
  EXPECT_TRUE(ell.segment_free({3, 1}, {1, 1}));    // along the lower one's top edge
}

}  // namespace
}  // namespace plantsim::planner
