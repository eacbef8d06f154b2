// Seed 002's gradient / coordinate-rotation planner: straight on an empty floor, around a
// block by coordinate rotation, the optimised path never crossing an obstacle and never longer
// than the raw walk, and failures that say why.
#include <gtest/gtest.h>

#include <random>

#include "geometry/polyline.h"
#include "geometry/predicates.h"
#include "planner/gcr/gcr_planner.h"
#include "planner/inflation.h"

namespace plantsim::planner {
namespace {

using geom::polyline_length;

PlannerInput floor_with(std::vector<Rect> obstacles) {
  PlannerInput in;
  in.floor = {0, 0, 100, 100};
  in.obstacles = std::move(obstacles);
  in.inflation_m = 0.3;
  return in;
}

TEST(Gcr, EmptyFloorGoesStraight) {
  GcrPlanner p(floor_with({}));
  const auto r = p.plan({5, 5}, {95, 80});
  ASSERT_EQ(r.status, PlanStatus::kOk);
  EXPECT_NEAR(r.length, std::hypot(90.0, 75.0), 1e-9);
  EXPECT_EQ(r.path.size(), 2u);
}

TEST(Gcr, ABlockOnTheLineIsPassedByCoordinateRotationThenShortcut) {
  // The document's first example in miniature: A(0,0) to B(100,100) with a block across.
  GcrPlanner p(floor_with({{40, 30, 60, 70}}));
  const GcrPlanner::Walk raw = p.walk({5, 5}, {95, 95});
  ASSERT_TRUE(raw.reached) << raw.failure;
  EXPECT_EQ(raw.rotations, 1);
  EXPECT_EQ(raw.rotation_ends.size(), 1u);
  const auto r = p.plan({5, 5}, {95, 95});
  ASSERT_EQ(r.status, PlanStatus::kOk);
  EXPECT_LT(r.length, polyline_length(raw.points));
  EXPECT_LE(r.length, std::hypot(90.0, 90.0) * 1.2);
}

TEST(Gcr, RandomWorldsNeverCrossAnObstacleNorExceedTheWalk) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  int reached = 0, failed = 0;
  for (int world = 0; world < 150; ++world) {
    std::vector<Rect> obstacles;
    for (int i = 0; i < 15; ++i) {
      const double x = 5 + 80 * u(rng), y = 5 + 80 * u(rng);
      obstacles.push_back({x, y, x + 2 + 12 * u(rng), y + 2 + 12 * u(rng)});
    }
    const PlannerInput in = floor_with(obstacles);
    GcrPlanner p(in);
    const Vec2 s{1 + 3 * u(rng), 1 + 98 * u(rng)}, g{96 + 3 * u(rng), 1 + 98 * u(rng)};
    const auto r = p.plan(s, g);
    if (r.status == PlanStatus::kStartBlocked || r.status == PlanStatus::kGoalBlocked) continue;
    if (r.status != PlanStatus::kOk) {
      ++failed;
      EXPECT_FALSE(r.note.empty()) << "a failure must say why";
      continue;
    }
    ++reached;
    const auto inflated = inflate(in.obstacles, in.inflation_m);
    for (std::size_t i = 1; i < r.path.size(); ++i)
      for (const Rect& o : inflated) ASSERT_FALSE(geom::segment_enters_open_rect(r.path[i - 1], r.path[i], o)) << world;
    const auto raw = p.walk(s, g);
    EXPECT_LE(r.length, polyline_length(raw.points) + 1e-9) << world;
    EXPECT_GE(r.length, geom::distance(s, g) - 1e-9);
  }
  std::printf("gcr on 150 random worlds: %d reached, %d failed (trapped / oscillating / timed out)\n", reached, failed);
  EXPECT_GT(reached, 60);
}

TEST(Gcr, AUShapedTrapIsReportedNotFaked) {
  // A cup open away from the goal: the walk cannot leave it by the document's rules.
  GcrPlanner p(floor_with({{40, 30, 42, 70}, {20, 30, 42, 32}, {20, 68, 42, 70}}));
  // Inside, the gradient pushes against the cup's bottom and rotation runs up and down it.
  const auto r = p.plan({35, 50}, {90, 50});
  EXPECT_EQ(r.status, PlanStatus::kNoPath);
  EXPECT_NE(r.note.find("oscillating"), std::string::npos) << r.note;
}

}  // namespace
}  // namespace plantsim::planner
