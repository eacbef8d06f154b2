// Stopping within sight (issue 88): the stopping speed's formula, the traction governor's bound
// at the learnt grip, the free range a scan leaves ahead of the footprint, and a robot on a very
// wet floor (tyre friction 0.05) that meets an unmapped box on its path: with the bound it arrives
// at a creep and keeps its estimate; without it, it brakes hard, slides and loses it.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "controller/stopping_bound.h"
#include "controller/traction.h"
#include "episode/episode_config.h"
#include "episode/episode_result.h"
#include "episode/run_episode.h"
#include "planner/registry.h"
#include "robot/free_range.h"
#include "worlds/world.h"

namespace plantsim {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// v t + v^2 / (2a) = free - margin at the bound, for a table of floors and reaction times.
TEST(StoppingBound, TheSpeedStopsExactlyWithinTheFreeRangeLessTheMargin) {
  for (double a : {0.05, 0.49, 1.0, 3.0})
    for (double t : {0.0, 0.15, 0.5})
      for (double free : {0.12, 0.5, 2.0, 19.8}) {
        const double v = controller::stopping_speed_mps(free, a, t, 0.1);
        EXPECT_GT(v, 0);
        EXPECT_NEAR(controller::stopping_distance_m(v, a, t), free - 0.1, 1e-9)
            << "a " << a << " t " << t << " free " << free;
      }
  // Without reaction time it is sqrt(2 a d): 1 m at 0.5 m/s^2 gives 1 m/s.
  EXPECT_NEAR(controller::stopping_speed_mps(1.1, 0.5, 0.0, 0.1), 1.0, 1e-12);
  EXPECT_EQ(controller::stopping_speed_mps(0.1, 0.5, 0.15, 0.1), 0.0);  // within the margin
  EXPECT_EQ(controller::stopping_speed_mps(0.0, 0.5, 0.15, 0.1), 0.0);
  EXPECT_EQ(controller::stopping_speed_mps(kInf, 0.5, 0.15, 0.1), kInf);  // nothing seen ahead
  // More room, more grip: faster; more reaction time: slower.
  EXPECT_LT(controller::stopping_speed_mps(1.0, 0.5, 0.15, 0.1),
            controller::stopping_speed_mps(2.0, 0.5, 0.15, 0.1));
  EXPECT_LT(controller::stopping_speed_mps(1.0, 0.3, 0.15, 0.1),
            controller::stopping_speed_mps(1.0, 0.5, 0.15, 0.1));
  EXPECT_LT(controller::stopping_speed_mps(1.0, 0.5, 0.3, 0.1),
            controller::stopping_speed_mps(1.0, 0.5, 0.15, 0.1));
}

// Every command the governor sends is within the bound for the free range it was given and the
// grip it has learnt (stop_decel_mps2 x its slip scale), or the creep; slips lower the bound.
TEST(StoppingBound, TheGovernorNeverCommandsMoreThanStopsWithinTheFreeRange) {
  controller::TractionParams p;
  p.full_grip_accel_mps2 = 0;  // no soft start: at full grip the twist reaches the bound as wanted
  controller::TractionGovernor governor(p);
  const double dt = 0.05;
  int bounded = 0;
  for (int k = 0; k < 400; ++k) {
    const double free = 3.0 - 0.0075 * k;  // a box coming nearer, to 0 m
    const bool slip = k == 300 || k == 350;
    const controller::Twist out = governor.limit({0.6, 0.3}, slip, dt, free);
    const double a = p.stop_decel_mps2 * governor.scale();
    const double bound = std::max(
        p.creep_mps, controller::stopping_speed_mps(free, a, p.stop_reaction_s, p.stop_margin_m));
    ASSERT_LE(out.v_mps, bound + 1e-12) << "step " << k;
    if (out.v_mps < 0.6 && governor.scale() == 1.0) {
      ++bounded;
      // Slower along the same arc: the curvature 0.3 / 0.6 stays (once slips scale the twist,
      // the creep floors of traction.h change it before the bound).
      EXPECT_NEAR(out.omega_radps / out.v_mps, 0.5, 1e-9) << "step " << k;
    }
  }
  EXPECT_GT(bounded, 50);  // from a free range of 1.45 m on (step 207) to the first slip
  EXPECT_EQ(governor.slips(), 2);
  EXPECT_LT(governor.grip_decel_mps2(), p.stop_decel_mps2);  // learnt: less grip than assumed
  // Near the box only the creep is left (the docking approach still reaches the charger).
  EXPECT_DOUBLE_EQ(governor.limit({0.6, 0.0}, false, dt, 0.05).v_mps, p.creep_mps);
  // Switched off, the free range is not looked at.
  p.stop_within_sight = false;
  controller::TractionGovernor unbounded(p);
  unbounded.limit({0.6, 0.0}, false, 10.0, kInf);  // ramped up at once
  EXPECT_DOUBLE_EQ(unbounded.limit({0.6, 0.0}, false, dt, 0.05).v_mps, 0.6);
  // Reversing (yielding, backing off the charger) is not bounded by what lies ahead.
  p.stop_within_sight = true;
  controller::TractionGovernor fresh(p);
  EXPECT_DOUBLE_EQ(fresh.limit({-0.15, 0.0}, false, dt, 0.0).v_mps, -0.15);
}

robot::LidarScan scan_with(double angle_min, double increment, std::vector<double> ranges) {
  robot::LidarScan s;
  s.angle_min_rad = angle_min;
  s.angle_increment_rad = increment;
  s.min_range_m = 0.05;
  s.max_range_m = 20.0;
  s.ranges = std::move(ranges);
  return s;
}

TEST(FreeRange, TheFootprintsCorridorIsCutByTheNearestReturnInIt) {
  worlds::RobotSpec disk;  // radius 0.2
  // Nothing returns: free up to the lidar's range less the front of the footprint.
  EXPECT_DOUBLE_EQ(robot::free_range_ahead_m(scan_with(-1, 1, {20, 20, 20}), disk), 19.8);
  // A face 2 m straight ahead: the disk's front reaches it after 1.8 m.
  EXPECT_NEAR(robot::free_range_ahead_m(scan_with(0, 0.1, {2.0}), disk), 1.8, 1e-12);
  // A return 0.1 m to the side of the centre line at 2 m: after 2 - sqrt(0.04 - 0.01).
  const double a = std::atan2(0.1, 2.0);
  EXPECT_NEAR(robot::free_range_ahead_m(scan_with(a, 0.1, {std::hypot(2.0, 0.1)}), disk),
              2.0 - std::sqrt(0.03), 1e-12);
  // Beside the corridor (0.3 m off the line), behind the axle, or no return: not in the way.
  EXPECT_DOUBLE_EQ(
      robot::free_range_ahead_m(scan_with(std::atan2(0.3, 1.0), 0.1, {std::hypot(1.0, 0.3)}), disk),
      19.8);
  EXPECT_DOUBLE_EQ(robot::free_range_ahead_m(scan_with(M_PI, 0.1, {0.5}), disk), 19.8);
  EXPECT_DOUBLE_EQ(robot::free_range_ahead_m(scan_with(0, 0.1, {kInf}), disk), 19.8);
  // A mount ahead of the axle moves the returns forward with it.
  robot::LidarScan mounted = scan_with(0, 0.1, {2.0});
  mounted.mount = {0.1, 0, 0};
  EXPECT_NEAR(robot::free_range_ahead_m(mounted, disk), 1.9, 1e-12);
  // A rectangle: its half width and its front face.
  worlds::RobotSpec rect;
  rect.length_m = 0.6;
  rect.width_m = 0.4;
  EXPECT_NEAR(robot::free_range_ahead_m(scan_with(0, 0.1, {2.0}), rect), 1.7, 1e-12);
}

/// A hall 14 m x 6 m with pillars along its walls (something to localise against), the robot
/// at (1, 3) facing the charger at (13.5, 3), a box the map lacks across the way at x 6 to 6.6.
worlds::World wet_hall_with_box() {
  worlds::World w;
  w.name = "wet_hall_with_box";
  w.floor = {0, 0, 14, 6};
  w.obstacles = {
      {3.0, 0.0, 3.4, 0.6}, {4.5, 5.4, 5.0, 6.0}, {8.0, 5.5, 8.4, 6.0}, {10.5, 0.0, 11.0, 0.5}};
  w.start = {1.0, 3.0, 0.0};
  w.charger = {13.5, 3.0, 0.0};
  w.inflation_margin_m = 0.1;
  w.unmapped = {{6.0, 2.4, 6.6, 3.6}};
  return w;
}

episode::EpisodeResult run_wet(bool stop_within_sight, int seed) {
  const worlds::World plant = wet_hall_with_box();
  const worlds::World map = worlds::robot_map(plant);
  auto planner = planner::make_planner("vg", planner::planner_input(map, true));
  episode::EpisodeConfig c;
  c.drive.tyre_friction = 0.05;
  c.traction.stop_within_sight = stop_within_sight;
  c.timeout_s = 90;
  c.seed = static_cast<std::uint64_t>(seed);
  return episode::run_episode(plant, *planner, c);
}

// The robot on a floor of friction 0.05 meets a box its map lacks, straight on its path. Bounded
// by what it can stop in, it arrives at the docking guard's hold at a creep, its estimate stays
// within centimetres, and it goes round and docks. Without the bound it drives on at full speed
// until the guard holds it, brakes harder than the floor allows and slides on while its wheels
// stop: the encoders miss the slide and the estimate ends more than 0.25 m off (0.60 m measured
// with these seeds; `plantsim run` of the same world: 0.58 to 0.60 m off against 0.05 to 0.06 m).
TEST(StoppingBound, OnAVeryWetFloorTheRobotStopsShortOfAnUnmappedBox) {
  for (int seed : {1, 3}) {
    const episode::EpisodeResult bounded = run_wet(true, seed);
    EXPECT_EQ(bounded.collisions, 0) << "seed " << seed;
    EXPECT_GT(bounded.min_clearance_m, 0.1) << "seed " << seed;
    EXPECT_TRUE(bounded.docked) << "seed " << seed << ": " << episode::status_name(bounded) << " "
                                << (bounded.failure ? bounded.failure->detail : "");
    EXPECT_LT(bounded.localization_error_max_m, 0.15) << "seed " << seed;
    const episode::EpisodeResult unbounded = run_wet(false, seed);
    EXPECT_GT(unbounded.localization_error_max_m, 0.25) << "seed " << seed;
  }
}

}  // namespace
}  // namespace plantsim
