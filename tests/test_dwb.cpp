// DWB's parts checked by hand (the window, each critic's cost, a collision, the oscillation
// critic, the local goal in sight) and the planner closing the loop on a unicycle: a straight
// plan at full speed, the heading turned at the goal, a box on the plan stopped short of, one
// beside it passed, a sharp corner at the plan's margin turned without touching.
#include <gtest/gtest.h>

#include <cmath>

#include "controller/dwb/dwb_planner.h"
#include "geometry/clearance.h"

namespace plantsim::controller::dwb {
namespace {

TEST(DwbPlanner, SamplesWhatSimTimeOfAccelerationReaches) {
  DwbParams p;
  p.acc_lim_x = 0.1;  // 0.17 m/s in sim_time: below max_vel_x
  DwbPlanner dwb(p);
  dwb.set_path({{0, 0}, {5, 0}});
  dwb.step({{0, 0, 0}, {0, 0}, {5, 0, 0}});
  ASSERT_EQ(dwb.trajectories().size(), 400u);
  double top_v = 0, top_w = 0;
  for (const ScoredTrajectory& t : dwb.trajectories()) {
    EXPECT_GE(t.command.v_mps, 0.0);
    top_v = std::max(top_v, t.command.v_mps);
    top_w = std::max(top_w, std::fabs(t.command.omega_radps));
  }
  EXPECT_NEAR(top_v, 0.1 * 1.7, 1e-12);
  EXPECT_NEAR(top_w, 1.0, 1e-12);  // 3.2 rad/s^2 for 1.7 s: max_vel_theta
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

TEST(DwbPlanner, ATurnReversedWhileStandingIsNotReversedAgainInPlace) {
  OscillationCritic o;
  const geom::Pose2 here{0, 0, 0};
  o.sent({0, 0.5}, here);
  o.sent({0, -0.5}, here);               // the first reversal is free ...
  EXPECT_TRUE(o.oscillating({0, 0.5}));  // ... turning back is an oscillation
  EXPECT_FALSE(o.oscillating({0, -0.5}));
  EXPECT_FALSE(o.oscillating({0.2, 0}));
  o.sent({0, -0.5}, {0, 0, -0.25});  // turned 0.25 rad past the reversal: forgotten
  EXPECT_FALSE(o.oscillating({0, 0.5}));
}

TEST(DwbPlanner, TurnsWhileDrivingOnAreNoOscillation) {
  OscillationCritic o;
  o.sent({0.2, 0.5}, {0, 0, 0});
  o.sent({0.2, -0.5}, {0.01, 0, 0});  // steering along a corridor
  EXPECT_FALSE(o.oscillating({0.2, 0.5}));
  EXPECT_FALSE(o.oscillating({0, 0.5}));
}

TEST(DwbPlanner, AForwardReversalIsForgottenAfterOscillationResetDist) {
  OscillationCritic o;
  o.sent({0.1, 0}, {0, 0, 0});
  o.sent({-0.1, 0}, {0, 0, 0});
  EXPECT_TRUE(o.oscillating({0.1, 0}));
  o.sent({-0.1, 0}, {-0.06, 0, 0});
  EXPECT_FALSE(o.oscillating({0.1, 0}));
}

TEST(DwbPlanner, OnlyAPoseThatReallyTouchesRejectsATrajectory) {
  // A wall 0.42 m beside the straight run: 0.02 m to spare for the 0.2 m disk, closer than a
  // field cell's half diagonal (3.5 cm), which the field's interpolation resolves.
  const ClearanceGrid grid({1, 0}, 3, 0.05, {{0, 0.42, 3, 1}}, {-5, -5, 5, 5});
  DwbPlanner dwb({});
  dwb.set_path({{0, 0}, {3, 0}});
  EXPECT_TRUE(dwb.score({{0, 0, 0}, {0.26, 0}, {3, 0, 0}, &grid, 0.2}, {0.26, 0}).valid);
  // Already overlapping where it stands (by the field): turning in place or leaving is allowed,
  // going deeper is not.
  const DwbQuery grazing{{1, 0.23, 0}, {0, 0}, {3, 0, 0}, &grid, 0.2};
  EXPECT_TRUE(dwb.score(grazing, {0, 0.5}).valid);
  EXPECT_TRUE(dwb.score(grazing, {0.1, -0.5}).valid);
  EXPECT_FALSE(dwb.score(grazing, {0.1, 0.5}).valid);
}

TEST(DwbPlanner, TheLocalGoalIsTheCornerUntilThePlanBeyondIsInSight) {
  // A left turn round a box's corner at (1, 0.6): the plan turns 0.3 m off it, at the inflated
  // margin, as the visibility graph plans.
  const geom::Rect box{-2, 0.6, 1, 3};
  const ClearanceGrid grid({1, 1}, 3, 0.05, {box}, {-3, -2, 5, 4});
  PlanWindow w;
  w.set_path({{-1, 0.3}, {1.3, 0.3}, {1.3, 3}});
  w.update({0, 0.3}, 2.0, &grid, 0.2, 0.05);
  EXPECT_TRUE(w.goal_at_corner());
  EXPECT_LT(geom::distance(w.local_goal(), {1.3, 0.3}), 0.06);
  w.update({1.25, 0.3}, 2.0, &grid, 0.2, 0.05);  // at the corner: the plan beyond is seen
  EXPECT_GT(w.local_goal().y, 1.5);
  PlanWindow free;  // without a field, Nav2's: the pruned plan's end
  free.set_path({{-1, 0.3}, {1.3, 0.3}, {1.3, 3}});
  free.update({0, 0.3}, 2.0, nullptr, 0.2, 0.05);
  EXPECT_FALSE(free.goal_at_corner());
  EXPECT_GT(free.local_goal().y, 0.5);
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

// cable_tunnel_ring's first corner in small (issue 87): a 1.2 m tunnel turning left, the plan
// turning at the inflated corner (0.3 m off the wall's corner). The goal beyond the corner
// pulled every arc across it: DWB touched the corner, or stopped against it for good.
TEST(DwbPlanner, TurnsASharpCornerAtThePlansMarginWithoutTouching) {
  const geom::Rect corner{-3, 0.6, 0.6, 5};
  const ClearanceGrid grid({0.5, 1.5}, 4, 0.05, {corner, {-3, -2, 3, -0.6}, {1.8, -0.6, 3, 5}},
                           {-3, -2, 3, 5});
  DwbPlanner dwb({});
  dwb.set_path({{-1.5, 0}, {0.9, 0.3}, {1.2, 3.5}});
  const Drive d = drive(dwb, {-1.5, 0, 0}, {1.2, 3.5, 1.48}, &grid, 40.0, &corner);
  EXPECT_GT(d.nearest_box_m, 0.2);
  EXPECT_LT(geom::distance(d.pose.position(), {1.2, 3.5}), 0.25);
}

}  // namespace
}  // namespace plantsim::controller::dwb
