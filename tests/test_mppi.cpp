// MPPI's parts on cases small enough to check by hand (each critic's cost), and the optimizer
// closing the loop on a unicycle: it follows a straight plan at speed, goes around a box on the
// plan without touching it, and gives the same commands for the same seed.
#include <gtest/gtest.h>

#include <cmath>

#include "controller/mppi/mppi_optimizer.h"
#include "geometry/clearance.h"

namespace plantsim::controller::mppi {
namespace {

// Two samples of two steps, poses given by hand (the critics read poses and commands only).
struct HandRollouts {
  MppiParams p;
  Rollouts r;
  std::vector<geom::Vec2> path{{0, 0}, {1, 0}, {2, 0}, {3, 0}};
  std::vector<float> path_s{0, 1, 2, 3};
  HandRollouts() {
    r.resize(2, 2);
    r.x << 0.5f, 1.0f, 0.5f, 0.5f;
    r.y << 0.0f, 0.0f, 1.0f, 2.0f;
    r.yaw << 0.0f, 0.0f, 1.5707963f, 1.5707963f;
    r.vx << 0.5f, 0.5f, -0.2f, -0.2f;
    r.wz.setZero();
  }
  CriticInput input(RobotState s, geom::Pose2 goal, const ClearanceGrid* grid = nullptr) const {
    return {r, p, s, path, path_s, goal, grid, 0.2f};
  }
};

TEST(MppiCritics, GoalIsTheWeightedMeanDistanceAndOnlyNearTheGoal) {
  HandRollouts h;
  Costs costs = Costs::Zero(2);
  CriticParams c;
  goal_critic(h.input({0, 0, 0, 0, 0}, {1, 0, 0}), c, costs);  // 1 m away: within 1.4
  EXPECT_NEAR(costs(0), 5.0 * (0.5 + 0.0) / 2, 1e-5);
  EXPECT_NEAR(costs(1), 5.0 * (std::hypot(0.5, 1.0) + std::hypot(0.5, 2.0)) / 2, 1e-5);
  costs.setZero();
  goal_critic(h.input({0, 0, 0, 0, 0}, {3, 0, 0}), c, costs);  // 3 m away: not considered
  EXPECT_EQ(costs(0), 0.0f);
  EXPECT_EQ(costs(1), 0.0f);
}

TEST(MppiCritics, PreferForwardChargesReverseByTimeDriven) {
  HandRollouts h;
  Costs costs = Costs::Zero(2);
  prefer_forward_critic(h.input({0, 0, 0, 0, 0}, {3, 0, 0}), CriticParams{}, costs);
  EXPECT_EQ(costs(0), 0.0f);
  EXPECT_NEAR(costs(1), 5.0 * 0.2 * 2 * h.p.model_dt, 1e-6);
}

TEST(MppiCritics, GoalAngleIsTheMeanWrappedHeadingError) {
  HandRollouts h;
  Costs costs = Costs::Zero(2);
  goal_angle_critic(h.input({0.8f, 0, 0, 0, 0}, {1, 0, 3.0}), CriticParams{}, costs);
  EXPECT_NEAR(costs(0), 3.0 * 3.0, 1e-4);
  EXPECT_NEAR(costs(1), 3.0 * std::fabs(1.5707963 - 3.0), 1e-4);
}

TEST(MppiCritics, ObstaclesChargeACollisionAndLeaveAClearSampleAlmostFree) {
  HandRollouts h;
  const ClearanceGrid grid({1, 1}, 4, 0.05, {{{-1, 1.6, 3, 3}}}, {-10, -10, 10, 10});
  Costs costs = Costs::Zero(2);
  obstacles_critic(h.input({0, 0, 0, 0, 0}, {3, 0, 0}, &grid), CriticParams{}, costs);
  EXPECT_EQ(costs(1), 10000.0f);  // its second pose is inside the box
  EXPECT_LT(costs(0), 1.0f);      // 1.6 m from the box, beyond the inflation radius
  EXPECT_NEAR(grid.at(0.5f, 1.0f), 0.6f, 0.05f);
  EXPECT_EQ(grid.at(20.0f, 0.0f), 0.0f);  // outside the window: unknown is not free
}

TEST(MppiCritics, PathAlignIsZeroOnThePathAndTheOffsetBesideIt) {
  HandRollouts h;
  h.r.x << 1.0f, 2.0f, 1.0f, 2.0f;
  h.r.y << 0.0f, 0.0f, 0.5f, 0.5f;
  CriticParams c;
  c.path_align_trajectory_point_step = 1;
  Costs costs = Costs::Zero(2);
  path_align_critic(h.input({0, 0, 0, 0, 0}, {3, 0, 0}), c, costs);
  EXPECT_NEAR(costs(0), 0.0, 1e-5);
  EXPECT_GT(costs(1), 14.0 * 0.5 * 0.9);
}

// A unicycle driven by the optimizer's commands (the model MPPI assumes), `seconds` long.
struct Drive {
  RobotState state;
  std::vector<Twist> commands;
  double nearest_box_m = INFINITY;
};

Drive drive(MppiOptimizer& mppi, RobotState s, geom::Pose2 goal, const ClearanceGrid* grid,
            double seconds, const geom::Rect* box = nullptr) {
  Drive d;
  const double dt = 0.05;
  for (double t = 0; t < seconds; t += dt) {
    const Twist u = mppi.step({s, goal, grid, 0.2f});
    d.commands.push_back(u);
    s.x += static_cast<float>(u.v_mps * std::cos(s.yaw) * dt);
    s.y += static_cast<float>(u.v_mps * std::sin(s.yaw) * dt);
    s.yaw += static_cast<float>(u.omega_radps * dt);
    s.vx = static_cast<float>(u.v_mps), s.wz = static_cast<float>(u.omega_radps);
    if (box) d.nearest_box_m = std::min(d.nearest_box_m, geom::distance_to_rect({s.x, s.y}, *box));
  }
  d.state = s;
  return d;
}

MppiParams test_params() {
  MppiParams p;
  p.batch_size = 1000;  // Nav2's default halved: the loop is checked, not the sampling density
  return p;
}

// With nav2_bringup's weights Nav2's MPPI cruises below vx_max (navigation2#4970, #4849: the
// weighted mean of samples cut at vx_max sits below it); so does this one, well above half.
TEST(MppiOptimizer, FollowsAStraightPlanAtSpeed) {
  MppiOptimizer mppi(test_params(), CriticParams{}, 7);
  mppi.set_path({{0, 0}, {8, 0}});
  const Drive d = drive(mppi, {0, 0, 0, 0, 0}, {8, 0, 0}, nullptr, 8.0);
  EXPECT_GT(d.state.x, 2.4f);  // a mean of more than 0.3 m/s, from rest
  EXPECT_LT(std::fabs(d.state.y), 0.15f);
  EXPECT_GT(d.commands.back().v_mps, 0.3);
  EXPECT_LE(d.commands.back().v_mps, 0.5);
}

// A box the robot sees on a plan that runs through it: it stops short, never touching (going
// around is the path follower's replan, as with Nav2's global planner).
TEST(MppiOptimizer, StopsShortOfABoxOnThePlan) {
  const geom::Rect box{2.5, -0.3, 3.0, 0.3};
  const ClearanceGrid grid({3, 0}, 5, 0.05, {box}, {-2, -3, 10, 3});
  MppiOptimizer mppi(test_params(), CriticParams{}, 11);
  mppi.set_path({{0, 0}, {6, 0}});
  const Drive d = drive(mppi, {0, 0, 0, 0, 0}, {6, 0, 0}, &grid, 15.0, &box);
  EXPECT_GT(d.nearest_box_m, 0.2);  // the robot's radius: never touched
  EXPECT_GT(d.state.x, 1.5f);       // it drove up to it
  EXPECT_LT(std::fabs(d.commands.back().v_mps), 0.1);
}

// A plan passing 0.3 m from a box's side (inside the inflation radius, outside the critical
// margin): followed past it without touching.
TEST(MppiOptimizer, PassesABoxBesideThePlan) {
  const geom::Rect box{2.5, 0.5, 3.0, 1.5};
  const ClearanceGrid grid({3, 0}, 5, 0.05, {box}, {-2, -3, 10, 3});
  MppiOptimizer mppi(test_params(), CriticParams{}, 11);
  mppi.set_path({{0, 0}, {6, 0}});
  const Drive d = drive(mppi, {0, 0, 0, 0, 0}, {6, 0, 0}, &grid, 15.0, &box);
  EXPECT_GT(d.nearest_box_m, 0.2);
  EXPECT_GT(d.state.x, 4.0f);
}

TEST(MppiOptimizer, TheSameSeedGivesTheSameCommands) {
  MppiOptimizer a(test_params(), CriticParams{}, 3), b(test_params(), CriticParams{}, 3),
      c(test_params(), CriticParams{}, 4);
  for (MppiOptimizer* m : {&a, &b, &c}) m->set_path({{0, 0}, {4, 2}});
  const Drive da = drive(a, {0, 0, 0, 0, 0}, {4, 2, 0}, nullptr, 2.0);
  const Drive db = drive(b, {0, 0, 0, 0, 0}, {4, 2, 0}, nullptr, 2.0);
  const Drive dc = drive(c, {0, 0, 0, 0, 0}, {4, 2, 0}, nullptr, 2.0);
  ASSERT_EQ(da.commands.size(), db.commands.size());
  for (std::size_t i = 0; i < da.commands.size(); ++i) {
    EXPECT_EQ(da.commands[i].v_mps, db.commands[i].v_mps);
    EXPECT_EQ(da.commands[i].omega_radps, db.commands[i].omega_radps);
  }
  EXPECT_NE(da.commands.back().v_mps, dc.commands.back().v_mps);
}

}  // namespace
}  // namespace plantsim::controller::mppi
