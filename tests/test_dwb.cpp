// DWB's parts checked by hand (the window, each critic's cost, a collision, a reversal) and
// the planner closing the loop on a unicycle: a straight plan at full speed, the heading turned
// at the goal, a box on the plan stopped short of, one beside it passed.
#include <gtest/gtest.h>

#include <cmath>

#include "controller/dwb/dwb_planner.h"
#include "geometry/clearance.h"

namespace plantsim::controller::dwb {
namespace {

TEST(DwbPlanner, SamplesOnlyWhatOnePeriodOfAccelerationReaches) {
  DwbPlanner dwb({});
  dwb.set_path({{0, 0}, {5, 0}});
  dwb.step({{0, 0, 0}, {0, 0}, {5, 0, 0}});
  ASSERT_FALSE(dwb.trajectories().empty());
  for (const ScoredTrajectory& t : dwb.trajectories()) {
    EXPECT_LE(t.command.v_mps, 2.5 * 0.05 + 1e-12);
    EXPECT_GE(t.command.v_mps, 0.0);
    EXPECT_LE(std::fabs(t.command.omega_radps), 3.2 * 0.05 + 1e-12);
  }
}

TEST(DwbPlanner, PathAndGoalDistancesAreCellsTimesTheirScales) {
  DwbParams p;
  p.sim_time = 0.025;  // one pose: the end is where a twist of 0 leaves the robot
  DwbPlanner dwb(p);
  dwb.set_path({{0, 0}, {5, 0}});
  const ScoredTrajectory t = dwb.score({{1, 0.1, 0}, {0, 0}, {5, 0, 0}}, {0, 0});
  EXPECT_NEAR(t.path_dist, 32.0 * 0.1 / 0.05, 1e-9);  // 2 cells off the path
  EXPECT_NEAR(t.goal_dist, 24.0 * std::hypot(4, 0.1) / 0.05, 1e-6);
  // 0.325 m ahead, x = 1.325: half way between the plan's 5 cm points at 1.30 and 1.35.
  EXPECT_NEAR(t.path_align, 32.0 * std::hypot(0.025, 0.1) / 0.05, 1e-9);
  EXPECT_NEAR(t.goal_align, 24.0 * std::hypot(4 - 0.325, 0.1) / 0.05, 1e-6);
}

TEST(DwbPlanner, ATrajectoryIntoABoxIsInvalid) {
  const ClearanceGrid grid({1, 0}, 3, 0.05, {{0.6, -0.5, 1.0, 0.5}}, {-5, -5, 5, 5});
  DwbPlanner dwb({});
  dwb.set_path({{0, 0}, {5, 0}});
  const DwbQuery q{{0, 0, 0}, {0.26, 0}, {5, 0, 0}, &grid, 0.2};
  EXPECT_FALSE(dwb.score(q, {0.26, 0}).valid);  // 0.44 m in 1.7 s: into the box
  EXPECT_TRUE(dwb.score(q, {0.0, 0.5}).valid);  // turning on the spot
}

TEST(DwbPlanner, AtTheGoalItTurnsToTheGoalsHeadingInPlace) {
  DwbPlanner dwb({});
  dwb.set_path({{0, 0}, {1, 0}});
  const Twist u = dwb.step({{1, 0, 0}, {0, 0}, {1, 0, 1.5}});
  EXPECT_EQ(u.v_mps, 0.0);
  EXPECT_GT(u.omega_radps, 0.0);  // counter-clockwise, towards +1.5 rad
}

TEST(DwbPlanner, AReversalRightAfterAReversalIsRefused) {
  DwbPlanner dwb({});
  const DwbQuery here{{0, 0, 0}, {0, 0}, {0, 5, 0}};
  dwb.set_path({{0, 0}, {0, 5}});  // to the left: it turns left
  ASSERT_GT(dwb.step(here).omega_radps, 0.0);
  dwb.set_path({{0, 0}, {0, -5}});  // now to the right: the first reversal is free
  DwbQuery right = here;
  right.goal = {0, -5, 0};
  ASSERT_LT(dwb.step(right).omega_radps, 0.0);
  // Turning back left before moving 5 cm is an oscillation; keeping right is not.
  EXPECT_FALSE(dwb.score(right, {0, 0.1}).valid);
  EXPECT_TRUE(dwb.score(right, {0, -0.1}).valid);
  DwbQuery moved = right;
  moved.pose = {0.1, 0, 0};  // 10 cm on: reversing is allowed again
  EXPECT_TRUE(dwb.score(moved, {0, 0.1}).valid);
}

struct Drive {
  geom::Pose2 pose;
  Twist last;
  double peak_v = 0, nearest_box_m = INFINITY;
};

Drive drive(DwbPlanner& dwb, geom::Pose2 s, geom::Pose2 goal, const ClearanceGrid* grid,
            double seconds, const geom::Rect* box = nullptr) {
  Drive d;
  Twist v{0, 0};
  const double dt = 0.05;
  for (double t = 0; t < seconds; t += dt) {
    v = dwb.step({s, v, goal, grid, 0.2});
    s.x += v.v_mps * std::cos(s.yaw) * dt;
    s.y += v.v_mps * std::sin(s.yaw) * dt;
    s.yaw += v.omega_radps * dt;
    d.peak_v = std::max(d.peak_v, v.v_mps);
    if (box) d.nearest_box_m = std::min(d.nearest_box_m, geom::distance_to_rect({s.x, s.y}, *box));
  }
  d.pose = s, d.last = v;
  return d;
}

TEST(DwbPlanner, FollowsAStraightPlanAtFullSpeedAndStopsAtItsEnd) {
  DwbPlanner dwb({});
  dwb.set_path({{0, 0}, {3, 0}});
  const Drive d = drive(dwb, {0, 0, 0}, {3, 0, 0}, nullptr, 20.0);
  EXPECT_NEAR(d.peak_v, 0.26, 1e-9);
  EXPECT_LT(geom::distance(d.pose.position(), {3, 0}), 0.25);  // within xy_goal_tolerance
  EXPECT_LT(std::fabs(d.pose.y), 0.05);
  EXPECT_EQ(d.last.v_mps, 0.0);
}

TEST(DwbPlanner, StopsShortOfABoxOnThePlan) {
  const geom::Rect box{2.0, -0.3, 2.5, 0.3};
  const ClearanceGrid grid({2, 0}, 4, 0.05, {box}, {-2, -3, 8, 3});
  DwbPlanner dwb({});
  dwb.set_path({{0, 0}, {5, 0}});
  const Drive d = drive(dwb, {0, 0, 0}, {5, 0, 0}, &grid, 20.0, &box);
  EXPECT_GT(d.nearest_box_m, 0.2);
  EXPECT_GT(d.pose.x, 1.0);
}

TEST(DwbPlanner, PassesABoxBesideThePlan) {
  const geom::Rect box{2.0, 0.5, 2.5, 1.5};
  const ClearanceGrid grid({2, 0}, 4, 0.05, {box}, {-2, -3, 8, 3});
  DwbPlanner dwb({});
  dwb.set_path({{0, 0}, {5, 0}});
  const Drive d = drive(dwb, {0, 0, 0}, {5, 0, 0}, &grid, 25.0, &box);
  EXPECT_GT(d.nearest_box_m, 0.2);
  EXPECT_GT(d.pose.x, 4.5);
}

}  // namespace
}  // namespace plantsim::controller::dwb
