// The round inflation (planner vg-round, `plan --inflation round`): the clearance predicates
// against dense sampling, the planner's length squeezed between two exact rectangle planners
// (obstacles a staircase inside the rounded shapes: a lower bound; a staircase around them: an
// upper bound), the path's clearance checked point by point, and a robot driving it to dock.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "episode/episode_config.h"
#include "episode/episode_result.h"
#include "episode/run_episode.h"
#include "geometry/clearance.h"
#include "planner/inflation.h"
#include "planner/planner.h"
#include "planner/registry.h"
#include "planner/round/tangent_planner.h"
#include "test_paths.h"
#include "worlds/world_loader.h"

namespace plantsim::planner {
namespace {

using geom::Rect;
using geom::Vec2;

TEST(Clearance, ArcAndSegmentAgreeWithDenseSampling) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int blocked = 0, clear = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Rect r{u(rng) * 4, u(rng) * 4, 0, 0};
    const Rect q{r.xmin, r.ymin, r.xmin + u(rng) * 2, r.ymin + u(rng) * 2};
    const Vec2 c{u(rng) * 6 - 1, u(rng) * 6 - 1};
    const double radius = 0.2 + u(rng), clearance = 0.2 + u(rng), from = u(rng) * 7,
                 sweep = u(rng) * 2 * M_PI;
    double nearest = 1e9;
    for (int i = 0; i <= 20000; ++i)
      nearest = std::min(
          nearest,
          geom::distance_to_rect(c + radius * geom::unit_from_angle(from + sweep * i / 20000), q));
    const bool keeps = geom::arc_keeps_clearance(c, radius, from, sweep, q, clearance);
    // Sampling finds the nearest point to within the sample spacing (radius * sweep / 20000).
    if (nearest < clearance - 1e-3) {
      EXPECT_FALSE(keeps) << trial;
    }
    if (nearest > clearance + 1e-3) {
      EXPECT_TRUE(keeps) << trial;
    }
    (keeps ? clear : blocked) += 1;

    const Vec2 p{u(rng) * 6 - 1, u(rng) * 6 - 1}, p2{u(rng) * 6 - 1, u(rng) * 6 - 1};
    double seg = 1e9;
    for (int i = 0; i <= 20000; ++i)
      seg = std::min(seg, geom::distance_to_rect(p + (i / 20000.0) * (p2 - p), q));
    EXPECT_NEAR(geom::segment_rect_distance(p, p2, q), seg, 1e-3 + 1e-9) << trial;
  }
  EXPECT_GT(blocked, 250);  // both outcomes exercised
  EXPECT_GT(clear, 250);
}

// Staircases of `steps` rectangles per corner: inside the rounded rectangle (every step's outer
// corner on the circle) or around it (the planner's own --corner-steps inflation).
std::vector<Rect> inscribed(const std::vector<Rect>& raw, double r, int steps) {
  std::vector<Rect> out;
  for (const Rect& o : raw) {
    out.push_back({o.xmin - r, o.ymin, o.xmax + r, o.ymax});
    out.push_back({o.xmin, o.ymin - r, o.xmax, o.ymax + r});
    for (int j = 1; j < steps; ++j) {
      const double a = 0.5 * M_PI * j / steps, dx = r * std::cos(a), dy = r * std::sin(a);
      out.push_back({o.xmin - dx, o.ymin - dy, o.xmax + dx, o.ymax + dy});
    }
  }
  return out;
}

TEST(RoundInflation, LengthLiesBetweenStaircasesInsideAndAroundTheRoundedObstacles) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int compared = 0, shorter_than_square = 0;
  for (int world = 0; world < 120; ++world) {
    PlannerInput in;
    in.floor = {0, 0, 20, 14};
    in.inflation_m = 0.3 + 0.4 * u(rng);
    const int count = 1 + static_cast<int>(u(rng) * 12);
    for (int i = 0; i < count; ++i) {
      const double x = u(rng) * 18, y = u(rng) * 12;
      in.obstacles.push_back({x, y, x + 0.2 + u(rng) * 4, y + 0.2 + u(rng) * 4});
    }
    RoundTangentPlanner round(in);
    PlannerInput outer = in;
    outer.corner_steps = 16;
    PlannerInput inner;
    inner.floor = in.floor.inflated(-in.inflation_m);
    inner.inflation_m = 0;
    inner.obstacles = inscribed(in.obstacles, in.inflation_m, 16);
    auto upper = make_planner("vg", outer), lower = make_planner("vg", inner),
         square = make_planner("vg", in);
    for (int q = 0; q < 4; ++q) {
      const Vec2 s{0.5 + u(rng) * 19, 0.5 + u(rng) * 13}, g{0.5 + u(rng) * 19, 0.5 + u(rng) * 13};
      const PlanResult a = round.plan(s, g), hi = upper->plan(s, g), lo = lower->plan(s, g),
                       sq = square->plan(s, g);
      const std::string what = "world " + std::to_string(world) + " query " + std::to_string(q);
      // Free for the round inflation: free for the staircase inside, maybe not for the one around.
      if (a.status == PlanStatus::kStartBlocked || a.status == PlanStatus::kGoalBlocked) {
        EXPECT_NE(hi.status, PlanStatus::kOk) << what;
        continue;
      }
      if (lo.status != PlanStatus::kOk) {
        EXPECT_NE(a.status, PlanStatus::kOk) << what;
        continue;
      }
      if (a.status != PlanStatus::kOk) {
        EXPECT_NE(hi.status, PlanStatus::kOk) << what;
        continue;
      }
      ++compared;
      EXPECT_LE(lo.length, a.length + 1e-7) << what;
      if (hi.status == PlanStatus::kOk) {
        EXPECT_LE(a.length, hi.length + 1e-7) << what;
        EXPECT_LE(hi.length - lo.length, 0.01 * lo.length + 1e-6) << what;  // the squeeze is tight
      }
      if (sq.status == PlanStatus::kOk && a.length < sq.length - 1e-6) ++shorter_than_square;
      // Every sampled point keeps the clearance (arcs are sampled on their circles), and the
      // samples trace the exact length to within the chords cut across the arcs.
      double polyline = 0;
      for (std::size_t i = 0; i < a.path.size(); ++i) {
        for (const Rect& o : in.obstacles)
          ASSERT_GE(geom::distance_to_rect(a.path[i], o), in.inflation_m - 1e-7)
              << what << " point " << i;
        if (i > 0) polyline += geom::distance(a.path[i - 1], a.path[i]);
      }
      EXPECT_LE(polyline, a.length + 1e-9) << what;
      EXPECT_GE(polyline, a.length * (1 - 1e-4)) << what;
      // The controller's path (arcs as their tangents' corners) keeps the clearance too, and is
      // no shorter than the optimum nor longer than the square inflation's.
      ASSERT_GE(a.drive_path.size(), 2u) << what;
      double driven = 0;
      for (std::size_t i = 1; i < a.drive_path.size(); ++i) {
        for (const Rect& o : in.obstacles)
          ASSERT_GE(geom::segment_rect_distance(a.drive_path[i - 1], a.drive_path[i], o),
                    in.inflation_m - 1e-7)
              << what;
        driven += geom::distance(a.drive_path[i - 1], a.drive_path[i]);
      }
      EXPECT_GE(driven, a.length - 1e-9) << what;
      if (sq.status == PlanStatus::kOk) {
        EXPECT_LE(driven, sq.length + 1e-7) << what;
      }
    }
  }
  EXPECT_GT(compared, 250);
  EXPECT_GT(shorter_than_square, 100);  // rounding the corners matters
}

TEST(RoundInflation, BadInputIsRefusedWithAReason) {
  PlannerInput in;
  in.floor = {0, 0, 10, 10};
  in.inflation_m = 0;
  EXPECT_THROW(RoundTangentPlanner{in}, std::invalid_argument);
  in.inflation_m = 0.3;
  in.obstacles.assign(RoundTangentPlanner::kMaxObstacles + 1, Rect{1, 1, 2, 2});
  EXPECT_THROW(RoundTangentPlanner{in}, std::invalid_argument);
  in.obstacles = {{4, 4, 6, 6}};
  RoundTangentPlanner p(in);
  EXPECT_EQ(p.plan({5, 5}, {9, 9}).status, PlanStatus::kStartBlocked);
  EXPECT_EQ(p.plan({1, 1}, {4.1, 6.2}).status, PlanStatus::kGoalBlocked);  // 0.2 from the corner
  EXPECT_EQ(p.plan({1, 1}, {9.9, 9}).status,
            PlanStatus::kGoalBlocked);  // within the wall's clearance
  in.snap_to_free = true;
  RoundTangentPlanner snapping(in);
  const PlanResult r = snapping.plan({5, 5}, {9, 9});
  ASSERT_EQ(r.status, PlanStatus::kOk);
  EXPECT_TRUE(r.start_snapped);
}

TEST(RoundInflation, AroundOneBoxTheLengthIsWorkedOutByHand) {
  // From (0, 5) to (10, 5) past the box [4, 6] x [4, 6] with clearance 1. The straight line
  // grazes the box; the path goes over it: a tangent of length sqrt(4^2 + 1^2 - 1) = 4 to the
  // unit circle at (4, 6), touching it at angle pi - atan(4) + atan(1/4), an arc clockwise up to
  // the top (angle pi/2), i.e. through 2 atan(1/4), the flat top of length 2, and the same
  // mirrored: 10 + 4 atan(1/4) in all.
  PlannerInput in;
  in.floor = {-5, -5, 15, 15};
  in.inflation_m = 1;
  in.obstacles = {{4, 4, 6, 6}};
  RoundTangentPlanner p(in);
  const PlanResult r = p.plan({0, 5}, {10, 5});
  ASSERT_EQ(r.status, PlanStatus::kOk);
  EXPECT_NEAR(r.length, 10 + 4 * std::atan(0.25), 1e-9);
  // Square corners, for contrast: to the inflated box's corner (3, 7), across 4 m, and down.
  auto square = make_planner("vg", in);
  EXPECT_NEAR(square->plan({0, 5}, {10, 5}).length, 2 * std::hypot(3.0, 2.0) + 4, 1e-9);
}

TEST(RoundInflation, AnArcThroughAnotherObstaclesClearanceIsRefused) {
  // Around the corner (0, 0) of the box [-2, 0] x [-2, 0], clearance 1: a small box at
  // (1.3, 1.3) leaves a gap of 1.84 m < 2 m beside the corner, so the arc's middle (0.71, 0.71)
  // comes within 0.84 m of it while both its ends and both tangents keep clear. The path must
  // go around the small box as well.
  PlannerInput in;
  in.floor = {-6, -6, 6, 6};
  in.inflation_m = 1;
  in.obstacles = {{-2, -2, 0, 0}, {1.3, 1.3, 1.4, 1.4}};
  RoundTangentPlanner p(in);
  const Vec2 s{-3, 1.5}, g{1.5, -3};
  const PlanResult r = p.plan(s, g);
  ASSERT_EQ(r.status, PlanStatus::kOk);
  for (const Vec2& v : r.path)
    for (const Rect& o : in.obstacles)
      ASSERT_GE(geom::distance_to_rect(v, o), 1 - 1e-7) << v.x << " " << v.y;
  // Going around both is longer than hugging the corner would be.
  in.obstacles.pop_back();
  EXPECT_GT(r.length, RoundTangentPlanner(in).plan(s, g).length + 0.5);
}

class RoundPlansDriven : public ::testing::TestWithParam<const char*> {};

// Pure pursuit on the round plan: the arcs sampled as they are made it cut every tight turn
// (it starts turning a lookahead early) and hit a wall on three of these worlds; on the
// tangents' corners it turns in place, as at a square corner.
TEST_P(RoundPlansDriven, TheRobotDocksWithoutTouchingAWall) {
  const auto world = worlds::load_world(
      test::source_file(std::string("data/worlds/plants/") + GetParam() + ".json"));
  auto p = make_planner("vg-round", planner_input(world, true));
  const episode::EpisodeResult r = episode::run_episode(world, *p, episode::EpisodeConfig{});
  EXPECT_TRUE(r.docked) << episode::status_name(r);
  EXPECT_EQ(r.collisions, 0);
  EXPECT_LE(r.position_error_m, 0.02);
  // It drove the round plan: shorter than the square inflation's wherever a corner was turned.
  auto square = make_planner("vg", planner_input(world, true));
  const PlanResult sq =
      square->plan(world.start.position(), worlds::staging_pose(world).position());
  EXPECT_LT(r.path_length_m, sq.length - 0.05);
}

INSTANTIATE_TEST_SUITE_P(Scenarios, RoundPlansDriven,
                         ::testing::Values("cable_tunnel_ring", "cable_tunnel_maze",
                                           "coal_mine_roadways"));

}  // namespace
}  // namespace plantsim::planner
