// Seed 001's potential field with wall following, on a kinematic robot (no physics here: the
// simulated runs are in test_sim): the document's situations behave as it describes.
#include <gtest/gtest.h>

#include <functional>

#include "controller/potential_field.h"

namespace plantsim::controller {
namespace {

struct KinematicRun {
  bool arrived = false;
  bool trapped = false;
  double time_s = 0;
  double length_m = 0;
  double max_deviation_m = 0;  // from the straight line start -> first target position
  double min_clearance_m = INFINITY;
  int local_minima = 0;
  int wall_follows = 0;
  Vec2 end;
};

// A unicycle driven by the controller at 20 Hz; `target_at(t)` moves the target.
KinematicRun drive(Pose2 start, const std::function<Vec2(double)>& target_at,
                   const std::vector<geom::Rect>& boxes, double timeout_s = 120.0,
                   PotentialFieldParams params = {}) {
  const double radius = 0.2, dt = 0.05;
  PotentialFieldController c(params, radius);
  std::vector<FieldObstacle> obstacles;
  for (const auto& b : boxes) obstacles.push_back({b, {0, 0}});
  KinematicRun run;
  Pose2 pose = start;
  Vec2 velocity{0, 0};
  const Vec2 a = start.position(), b = target_at(0);
  for (double t = 0; t < timeout_s; t += dt) {
    const Vec2 target = target_at(t);
    const Vec2 target_velocity = (1.0 / dt) * (target_at(t + dt) - target);
    const FieldCommand cmd = c.step({pose, velocity, target, target_velocity, dt, obstacles});
    if (cmd.arrived || cmd.trapped) {
      run.arrived = cmd.arrived;
      run.trapped = cmd.trapped;
      break;
    }
    const Vec2 before = pose.position();
    pose.yaw = geom::wrap_angle(pose.yaw + cmd.twist.omega_radps * dt);
    pose.x += cmd.twist.v_mps * dt * std::cos(pose.yaw);
    pose.y += cmd.twist.v_mps * dt * std::sin(pose.yaw);
    velocity = cmd.twist.v_mps * pose.heading();
    run.length_m += geom::distance(before, pose.position());
    run.time_s = t + dt;
    run.max_deviation_m =
        std::max(run.max_deviation_m,
                 std::fabs(geom::cross(geom::unit_from_angle(std::atan2(b.y - a.y, b.x - a.x)),
                                       pose.position() - a)));
    for (const auto& box : boxes)
      run.min_clearance_m = std::min(
          run.min_clearance_m,
          geom::distance(pose.position(), geom::closest_point(box, pose.position())) - radius);
  }
  run.local_minima = c.local_minima();
  run.wall_follows = c.wall_follow_episodes();
  run.end = pose.position();
  return run;
}

std::vector<geom::Rect> walled_floor(double w, double h) {
  const auto walls = geom::surrounding_walls({0, 0, w, h}, 1.0);
  return {walls.begin(), walls.end()};
}

TEST(PotentialField, GoesStraightToTheGoalOnAnEmptyFloor) {
  const KinematicRun r = drive(
      {1, 5, 0},
      [](double) {
        return Vec2{9, 5};
      },
      walled_floor(10, 10));
  ASSERT_TRUE(r.arrived);
  EXPECT_EQ(r.local_minima, 0);
  EXPECT_LT(r.max_deviation_m, 0.01);
  EXPECT_LT(r.length_m, 8.0 * 1.01);
}

TEST(PotentialField, AttractionAndRepulsionBalanceInFrontOfAWall) {
  PotentialFieldParams p;
  // Straight in front of a wall, on the line to the target behind it: the pull is opposed.
  const std::vector<FieldObstacle> wall = {{{5, 2, 5.4, 8}, {0, 0}}};
  const FieldForces far = field_forces(p, 0.2, {2, 5}, {0, 0}, {8, 5}, {0, 0}, wall);
  const FieldForces near = field_forces(p, 0.2, {4.5, 5}, {0, 0}, {8, 5}, {0, 0}, wall);
  EXPECT_GT(far.total.x, 0.9);            // no repulsion out of range
  EXPECT_LT(near.total.x, 0.0);           // pushed back close to the wall
  EXPECT_NEAR(near.total.y, 0.0, 1e-12);  // and nothing sideways: a local minimum in between
  // Closing in on an obstacle adds repulsion along the closing motion.
  const FieldForces moving = field_forces(p, 0.2, {4.0, 5}, {0.5, 0}, {8, 5}, {0, 0}, wall);
  const FieldForces still = field_forces(p, 0.2, {4.0, 5}, {0, 0}, {8, 5}, {0, 0}, wall);
  EXPECT_LT(moving.repulsion.x, still.repulsion.x);
}

TEST(PotentialField, LeavesTheLocalMinimumInFrontOfAWallByFollowingIt) {
  auto boxes = walled_floor(12, 12);
  boxes.push_back({5.8, 3, 6.2, 9});  // a wall across the way
  const KinematicRun r = drive(
      {2, 6, 0},
      [](double) {
        return Vec2{10, 6};
      },
      boxes);
  EXPECT_TRUE(r.arrived) << "ended at " << r.end.x << ", " << r.end.y;
  EXPECT_GE(r.local_minima, 1);
  EXPECT_GE(r.wall_follows, 1);
  EXPECT_GT(r.min_clearance_m, 0.05);
}

TEST(PotentialField, PlainFieldWithoutWallFollowingStaysTrapped) {
  auto boxes = walled_floor(12, 12);
  boxes.push_back({5.8, 3, 6.2, 9});
  PotentialFieldParams p;
  p.max_wall_follows = 0;  // the first local minimum ends the run
  const KinematicRun r = drive(
      {2, 6, 0},
      [](double) {
        return Vec2{10, 6};
      },
      boxes, 120.0, p);
  EXPECT_TRUE(r.trapped);
  EXPECT_LT(r.end.x, 5.8);
}

TEST(PotentialField, EscapesAUShapedTrap) {
  auto boxes = walled_floor(16, 12);
  boxes.push_back({7.6, 3, 8, 9});  // the bottom of the U, facing the robot
  boxes.push_back({5, 3, 8, 3.4});  // its arms
  boxes.push_back({5, 8.6, 8, 9});
  const KinematicRun r = drive(
      {3, 6, 0},
      [](double) {
        return Vec2{13, 6};
      },
      boxes, 240.0);
  EXPECT_TRUE(r.arrived) << "ended at " << r.end.x << ", " << r.end.y;
  EXPECT_GE(r.local_minima, 1);
  EXPECT_GT(r.min_clearance_m, 0.05);
}

TEST(PotentialField, CatchesATargetSlowerThanItself) {
  // The document's first example: robot at most 0.5 m/s, target at 0.4 m/s.
  auto target = [](double t) { return Vec2{6, 2 + 0.4 * std::min(t, 40.0)}; };
  const KinematicRun r = drive({2, 2, 0}, target, walled_floor(30, 30), 60.0);
  ASSERT_TRUE(r.arrived);
  EXPECT_LT(r.time_s, 40.0);  // caught while the target was still moving
}

TEST(PotentialField, DoesNotCatchAFasterTargetUntilItStops) {
  auto target = [](double t) { return Vec2{6, 2 + 0.6 * std::min(t, 30.0)}; };
  const KinematicRun r = drive({2, 2, 0}, target, walled_floor(30, 30), 80.0);
  ASSERT_TRUE(r.arrived);
  EXPECT_GT(r.time_s, 30.0);  // only once it has parked
}

}  // namespace
}  // namespace plantsim::controller
