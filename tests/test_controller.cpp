// Controller maths without physics: kinematics, and pure pursuit closed around an ideal
// unicycle so that tracking errors come from the controller alone.
#include <gtest/gtest.h>

#include <cmath>

#include "controller/collision_check.h"
#include "controller/diff_drive.h"
#include "controller/docking.h"
#include "controller/pure_pursuit.h"
#include "controller/traction.h"

namespace plantsim::controller {
namespace {

TEST(DiffDrive, EqualWheelsGoStraightOppositeWheelsTurnInPlace) {
  const Twist straight = to_twist({0.5, 0.5}, 0.4);
  EXPECT_DOUBLE_EQ(straight.v_mps, 0.5);
  EXPECT_DOUBLE_EQ(straight.omega_radps, 0.0);
  const Twist spin = to_twist({-0.2, 0.2}, 0.4);
  EXPECT_DOUBLE_EQ(spin.v_mps, 0.0);
  EXPECT_DOUBLE_EQ(spin.omega_radps, 1.0);
  const WheelSpeeds w = to_wheels({0.3, 0.5}, 0.4);
  EXPECT_DOUBLE_EQ(w.left_mps, 0.2);
  EXPECT_DOUBLE_EQ(w.right_mps, 0.4);
}

TEST(DiffDrive, SaturationKeepsCurvature) {
  const WheelSpeeds w = saturate({0.5, 2.0}, 1.0);
  EXPECT_DOUBLE_EQ(w.right_mps, 1.0);
  EXPECT_DOUBLE_EQ(w.left_mps, 0.25);
}

struct TrackRun {
  double max_cross_track = 0;
  double max_cross_track_turning_in_place = 0;
  double final_cross_track = 0;
  bool reached = false;
  Pose2 end;
};

// Ideal unicycle at 50 Hz; cross-track error measured after `settle_m` of travel.
TrackRun track(const std::vector<Vec2>& path, Pose2 pose, double settle_m,
               PurePursuitParams params = {}) {
  PurePursuit pp(params, path);
  TrackRun run;
  const double dt = 0.02;
  double travelled = 0, speed = 0;
  for (int k = 0; k < 20000; ++k) {
    const TrackingCommand c = pp.step(pose, speed);
    if (travelled > settle_m)
      run.max_cross_track = std::max(run.max_cross_track, c.cross_track_error_m);
    run.final_cross_track = c.cross_track_error_m;
    if (c.twist.v_mps == 0 && c.twist.omega_radps != 0)
      run.max_cross_track_turning_in_place =
          std::max(run.max_cross_track_turning_in_place, c.cross_track_error_m);
    if (c.goal_reached) {
      run.reached = true;
      break;
    }
    speed = c.twist.v_mps;
    pose.x += c.twist.v_mps * std::cos(pose.yaw) * dt;
    pose.y += c.twist.v_mps * std::sin(pose.yaw) * dt;
    pose.yaw += c.twist.omega_radps * dt;
    travelled += std::fabs(c.twist.v_mps) * dt;
  }
  run.end = pose;
  return run;
}

TEST(PurePursuit, StraightLineFromAnOffsetConverges) {
  const TrackRun r = track({{0, 0}, {20, 0}}, {0, 0.3, 0}, 3.0);
  EXPECT_TRUE(r.reached);
  EXPECT_LT(r.max_cross_track, 0.01);
  EXPECT_NEAR(r.end.x, 20.0, 0.03);
}

TEST(PurePursuit, CircleIsTrackedWithinTwoCentimetres) {
  std::vector<Vec2> circle;
  for (int i = 0; i <= 200; ++i) {
    const double a = -M_PI / 2 + 2 * M_PI * i / 200.0 * 0.9;
    circle.push_back({3.0 * std::cos(a), 3.0 + 3.0 * std::sin(a)});
  }
  const TrackRun r = track(circle, {0, 0, 0}, 1.0);
  EXPECT_TRUE(r.reached);
  EXPECT_LT(r.max_cross_track, 0.02);  // radius 3 m, lookahead up to 0.9 m
}

TEST(PurePursuit, SharpCornerCutIsBounded) {
  // A right-angle turn: the robot slows on the curvature and turns in place when the carrot
  // swings far off its heading, so the corner is cut by little.
  const TrackRun r = track({{0, 0}, {5, 0}, {5, 5}}, {0, 0, 0}, 0.0);
  EXPECT_TRUE(r.reached);
  EXPECT_LT(r.max_cross_track, 0.12);
  EXPECT_NEAR(r.end.y, 5.0, 0.03);
}

TEST(PurePursuit, TurningInPlaceShortOfACornerIsOnThePath) {
  // The robot stops within the corner release distance of the vertex on the incoming leg and
  // turns there: its distance from the path is that from the incoming leg (about zero for this
  // ideal drive), not from the next leg (up to the release distance), which is what made every
  // turn in place read as ~10 cm of cross-track error.
  const TrackRun r = track({{0, 0}, {5, 0}, {5, 5}}, {0, 0, 0}, 0.0);
  ASSERT_TRUE(r.reached);
  EXPECT_LT(r.max_cross_track_turning_in_place, 0.01);
}

TEST(PurePursuit, DoesNotOvershootTheEnd) {
  const TrackRun r = track({{0, 0}, {3, 0}}, {0, 0, 0}, 0.0);
  EXPECT_TRUE(r.reached);
  EXPECT_LE(r.end.x, 3.0 + 1e-9);
  EXPECT_GE(r.end.x, 3.0 - 0.03);
}

DockingInput at(Pose2 p, bool contact = false, bool charging = false) {
  DockingInput in;
  in.pose = p;  // map and odometry frames agree here
  in.odom_pose = p;
  in.charger_contact = contact;
  in.charging = charging;
  in.dt_s = 0.02;
  return in;
}

// Pads touched but no charging for the press timeout: a miss. 0.02 s steps.
DockingCommand press_until_given_up(DockingController& dc, Pose2 p) {
  DockingCommand c = dc.step(at(p, true, false));
  for (int i = 0; i < 200 && c.phase == DockPhase::kApproach; ++i) {
    EXPECT_GT(c.twist.v_mps, 0.0);  // holds the pads pressed while waiting for the charger
    EXPECT_EQ(c.twist.omega_radps, 0.0);
    c = dc.step(at(p, i % 2 == 0, false));  // contact may flicker as the springs bounce
  }
  return c;
}

TEST(Docking, PadsHeldUntilTheChargerSaysChargingPressedWithoutIsAMissAndBacksOff) {
  DockingController dc(PurePursuitParams{}, {}, {{0, 0}, {1, 0}}, Pose2{2, 0, 0});
  EXPECT_EQ(dc.step(at({1, 0, 0})).phase, DockPhase::kAlign);     // path end reached
  EXPECT_EQ(dc.step(at({1, 0, 0})).phase, DockPhase::kApproach);  // already aligned
  const DockingCommand miss = press_until_given_up(dc, {2, 0.05, 0});
  EXPECT_EQ(miss.phase, DockPhase::kBackOff);
  EXPECT_EQ(dc.retries(), 1);
  EXPECT_LT(dc.step(at({1.9, 0.05, 0})).twist.v_mps, 0);           // reverses away from the charger
  EXPECT_EQ(dc.step(at({1.0, 0.0, 0})).phase, DockPhase::kAlign);  // back at staging
  dc.step(at({1.0, 0.0, 0}));                                      // approach
  const DockingCommand touched = dc.step(at({2, 0.0, 0}, true, false));
  EXPECT_EQ(touched.phase, DockPhase::kApproach);  // touched is not docked: the dwell runs
  EXPECT_GT(touched.twist.v_mps, 0.0);
  const DockingCommand ok = dc.step(at({2, 0.0, 0}, true, true));
  EXPECT_EQ(ok.phase, DockPhase::kDocked);
  EXPECT_EQ(ok.twist.v_mps, 0.0);
}

TEST(Docking, AfterTheLastRetryItBacksOffBeforeFailing) {
  DockingParams p;
  p.max_retries = 1;
  DockingController dc(PurePursuitParams{}, p, {{0, 0}, {1, 0}}, Pose2{2, 0, 0});
  dc.step(at({1, 0, 0}));
  dc.step(at({1, 0, 0}));
  EXPECT_EQ(press_until_given_up(dc, {2, 0.05, 0}).phase, DockPhase::kBackOff);  // retry 1
  EXPECT_EQ(dc.step(at({1.0, 0.0, 0})).phase, DockPhase::kAlign);
  dc.step(at({1.0, 0.0, 0}));
  EXPECT_EQ(press_until_given_up(dc, {2, 0.05, 0}).phase, DockPhase::kBackOff);  // no retries left
  EXPECT_LT(dc.step(at({1.95, 0.05, 0})).twist.v_mps, 0);  // still backs away, not pressed on
  EXPECT_EQ(dc.step(at({1.0, 0.0, 0})).phase, DockPhase::kFailed);
  EXPECT_EQ(dc.retries(), 1);
}

TEST(Docking, TheBumperOnSomethingOtherThanThePadsIsAMiss) {
  DockingController dc(PurePursuitParams{}, {}, {{0, 0}, {1, 0}}, Pose2{2, 0, 0});
  dc.step(at({1, 0, 0}));
  dc.step(at({1, 0, 0}));
  DockingInput in = at({1.8, 0.1, 0});
  in.bumper_front = true;
  const DockingCommand c = dc.step(in);
  EXPECT_EQ(c.phase, DockPhase::kBackOff);
  EXPECT_LE(c.twist.v_mps, 0.0);
}

TEST(Docking, TheApproachAndTheBackOffStopForWhatTheySense) {
  DockingController dc(PurePursuitParams{}, {}, {{0, 0}, {1, 0}}, Pose2{2, 0, 0});
  dc.step(at({1, 0, 0}));
  dc.step(at({1, 0, 0}));
  DockingInput in = at({1.2, 0, 0});
  EXPECT_GT(dc.step(in).twist.v_mps, 0.0);                  // nothing sensed: approaches
  in.nearby_obstacles = {{{1.5, -0.3, 1.7, 0.3}, {0, 0}}};  // a box between robot and charger
  DockingCommand c = dc.step(in);
  EXPECT_EQ(c.twist.v_mps, 0.0);
  EXPECT_TRUE(c.blocked);
  EXPECT_EQ(dc.stops(), 1);
  // What is sensed at the charger itself (a charger off its mapped pose) does not stop it.
  in.nearby_obstacles = {{{2.2, -0.15, 2.3, 0.15}, {0, 0}}};
  EXPECT_GT(dc.step(in).twist.v_mps, 0.0);
  // Backing off with something behind: stops, then gives up stopped.
  const DockingCommand miss = press_until_given_up(dc, {2, 0.05, 0});
  ASSERT_EQ(miss.phase, DockPhase::kBackOff);
  DockingInput back = at({1.9, 0.05, 0});
  back.nearby_obstacles = {{{1.3, -0.3, 1.5, 0.3}, {0, 0}}};
  c = dc.step(back);
  EXPECT_EQ(c.twist.v_mps, 0.0);
  for (int i = 0; i < 2000 && c.phase == DockPhase::kBackOff; ++i) c = dc.step(back);
  EXPECT_EQ(c.phase, DockPhase::kFailed);
  EXPECT_EQ(c.twist.v_mps, 0.0);
}

// Someone person-sized standing beside the approach may step into it: aligned at the staging
// pose the robot waits for them to go (at most bystander_wait_s), then docks anyway; a fixture
// larger than a person, or the charger's own block, does not hold it.
TEST(Docking, APersonStandingBesideTheApproachIsWaitedForAtTheStagingPose) {
  DockingParams p;
  p.yield.bystander_wait_s = 2.0;
  DockingController dc(PurePursuitParams{}, p, {{0, 0}, {1, 0}}, Pose2{2, 0, 0});
  EXPECT_EQ(dc.step(at({1, 0, 0})).phase, DockPhase::kAlign);
  DockingInput in = at({1, 0, 0});
  in.nearby_obstacles = {{{1.3, 0.9, 1.8, 1.4}, {0, 0}}};  // 0.9 m to the side, halfway in
  DockingCommand c = dc.step(in);
  EXPECT_EQ(c.phase, DockPhase::kAlign);
  EXPECT_TRUE(c.blocked);
  EXPECT_EQ(c.twist.v_mps, 0.0);
  for (int i = 0; i < 90; ++i) c = dc.step(in);  // 1.8 s: still waiting
  EXPECT_EQ(c.phase, DockPhase::kAlign);
  for (int i = 0; i < 20 && c.phase == DockPhase::kAlign; ++i) c = dc.step(in);
  EXPECT_EQ(c.phase, DockPhase::kApproach);                        // waited its 2 s: docks anyway
  for (const geom::Rect& other : {geom::Rect{1.3, 0.9, 2.8, 1.4},  // a 1.5 m fixture
                                  geom::Rect{1.3, 2.5, 1.8, 3.0},  // 2.5 m away
                                  geom::Rect{2.2, -0.15, 2.3, 0.15}})  // the charger
  {
    DockingController fresh(PurePursuitParams{}, p, {{0, 0}, {1, 0}}, Pose2{2, 0, 0});
    fresh.step(at({1, 0, 0}));
    DockingInput near = at({1, 0, 0});
    near.nearby_obstacles = {{other, {0, 0}}};
    EXPECT_EQ(fresh.step(near).phase, DockPhase::kApproach) << other.xmin << " " << other.ymin;
  }
}

TEST(CollisionCheck, SegmentToBoxDistance) {
  const geom::Rect box{1, 1, 2, 2};
  EXPECT_DOUBLE_EQ(segment_distance_to_box({0, 0}, {3, 0}, box), 1.0);          // passes below
  EXPECT_DOUBLE_EQ(segment_distance_to_box({0, 0}, {3, 3}, box), 0.0);          // through it
  EXPECT_DOUBLE_EQ(segment_distance_to_box({1.5, 1.5}, {1.6, 1.5}, box), 0.0);  // inside
  EXPECT_NEAR(segment_distance_to_box({0, 4}, {4, 0}, box), 0.0, 1e-12);        // touches a corner
  EXPECT_NEAR(segment_distance_to_box({0, 5}, {5, 0}, box), std::sqrt(0.5),
              1e-12);                                                       // corner nearest
  EXPECT_DOUBLE_EQ(segment_distance_to_box({5, 1.5}, {5, 1.5}, box), 3.0);  // a point
}

TEST(Docking, DetectionsReanchorTheDockInTheOdometryFrame) {
  DockingController dc(PurePursuitParams{}, {}, {{0, 0}, {1, 0}}, Pose2{2, 0, 0});
  dc.step(at({1, 0, 0}));  // staging reached: dock placed from the map
  // The charger is really 3 cm to the left of where the map says: detections show it.
  DockingInput in = at({1, 0, 0});
  in.charger_in_robot = Pose2{1.0, 0.03, 0.0};
  for (int i = 0; i < 60; ++i) dc.step(in);
  EXPECT_NEAR(dc.dock_estimate().y, 0.03, 1e-6);
  EXPECT_NEAR(dc.dock_estimate().x, 2.0, 1e-6);
}

}  // namespace
}  // namespace plantsim::controller

namespace plantsim::controller {
namespace {

TEST(Docking, UndockReversesToTheStagingPoseGuarded) {
  DockingParams p;
  p.undock = true;
  DockingController dc(PurePursuitParams{}, p, {{0, 0}, {1, 0}}, Pose2{2, 0, 0});
  DockingInput in;
  auto at_pose = [&](Pose2 pose, bool contact, bool charging) {
    in = {};
    in.pose = in.odom_pose = pose;
    in.charger_contact = contact;
    in.charging = charging;
    in.dt_s = 0.02;
    return dc.step(in);
  };
  at_pose({1, 0, 0}, false, false);
  at_pose({1, 0, 0}, false, false);
  EXPECT_EQ(at_pose({2, 0, 0}, true, true).phase, DockPhase::kUndock);  // charging: now back out
  DockingCommand c = at_pose({1.9, 0, 0}, false, false);
  EXPECT_LT(c.twist.v_mps, 0);
  in.nearby_obstacles = {{{1.2, -0.3, 1.4, 0.3}, {0, 0}}};  // someone behind: stops
  c = dc.step(in);
  EXPECT_EQ(c.twist.v_mps, 0.0);
  EXPECT_TRUE(c.blocked);
  EXPECT_EQ(at_pose({1.0, 0, 0}, false, false).phase, DockPhase::kUndocked);
}

}  // namespace
}  // namespace plantsim::controller

// The docking stack's collaborators on their own (controller/docking.h's split along Nav2's
// lines): each is specified here without the phases around it.
namespace plantsim::controller {
namespace {

TEST(DockPoseFilter, NothingBeforeItIsPlacedAnOutlierAloneIsIgnoredTwoAgreeingMoveIt) {
  DockPoseFilter f({0.5, 0.1}, 1.0, Pose2{2, 0, 0});
  f.update(Pose2{2, 0.05, 0});  // not placed yet: the map's pose stands
  EXPECT_EQ(f.pose().y, 0.0);
  f.place(Pose2{2, 0, 0});
  f.update(Pose2{2, 0.04, 0});  // within the gate: blended by half
  EXPECT_NEAR(f.pose().y, 0.02, 1e-12);
  f.update(Pose2{2, 0.5, 0});  // 0.48 m off, alone: held back
  EXPECT_NEAR(f.pose().y, 0.02, 1e-12);
  f.update(Pose2{2, 0.02, 0});  // back near the estimate: the outlier forgotten
  f.update(Pose2{2, 0.5, 0});   // off again, alone again
  EXPECT_NEAR(f.pose().y, 0.02, 1e-12);
  f.update(Pose2{2, 0.52, 0});  // and confirmed by the next: the estimate moves
  EXPECT_NEAR(f.pose().y, 0.27, 1e-12);
  // A yaw gate of gate / staging distance: 0.2 rad off is an outlier at 0.1 m over 1 m.
  f.update(Pose2{2, 0.27, 0.2});
  EXPECT_NEAR(f.pose().yaw, 0.0, 1e-12);
  f.forget();  // shoved: the next placement starts afresh, the held-back one gone
  f.update(Pose2{2, 0.27, 0.2});
  EXPECT_NEAR(f.pose().yaw, 0.0, 1e-12);
}

TEST(MotionGuard, ABoxAheadBlocksOneStopPerEncounterBrakingSizesTheCheck) {
  MotionGuard g(MotionGuardParams{});
  const Pose2 at{0, 0, 0};
  const std::vector<MovingBox> ahead = {{{0.9, -0.3, 1.1, 0.3}, {0, 0}}};
  // At 0.3 m/s: 0.045 m braking + 0.4 m checked, plus 0.35 m of disk: the box at 0.9 m is clear.
  EXPECT_TRUE(g.clear(at, 0.3, {0.3, 0}, ahead));
  // At 1 m/s: 0.5 m braking reaches it.
  EXPECT_FALSE(g.clear(at, 1.0, {1.0, 0}, ahead));
  EXPECT_EQ(g.stops(), 1);
  g.note_clear(0.5);
  EXPECT_FALSE(g.clear(at, 1.0, {1.0, 0}, ahead));  // half a second of go: the same stop
  EXPECT_EQ(g.stops(), 1);
  g.note_clear(1.0);
  EXPECT_FALSE(g.clear(at, 1.0, {1.0, 0}, ahead));  // a second of go: a new one
  EXPECT_EQ(g.stops(), 2);
  EXPECT_TRUE(g.clear(at, 1.0, {-0.5, 0}, ahead));  // backing away from it is allowed
}

TEST(YieldPolicy, OnlyWhatMovesThreatensAndOnlyPersonSizedBystandersHold) {
  const YieldParams p;
  const std::vector<MovingBox> walker = {{{2.0, -0.2, 2.4, 0.2}, {-1.0, 0}}};  // 1 m/s at it
  const std::vector<MovingBox> standing = {{{0.6, -0.2, 1.0, 0.2}, {0, 0}}};
  EXPECT_TRUE(threatened_by_movers(p, {0, 0}, 0.3, walker));
  EXPECT_FALSE(threatened_by_movers(p, {0, 0}, 0.3, standing));                // near, yet standing
  EXPECT_TRUE(threatened(p, {0, 0}, 0.3, {{{0.2, -0.2, 0.5, 0.2}, {0, 0}}}));  // already there
  // Beside the corridor from (0, 0) to (3, 0), 1 m off: within 0.35 + 1.5 m.
  const std::vector<MovingBox> person = {{{1.3, 1.0, 1.7, 1.4}, {0, 0}}};
  EXPECT_TRUE(bystander_near_corridor(p, {0, 0}, {3, 0}, {3.3, 0}, 0.35, person));
  const std::vector<MovingBox> fixture = {{{1.0, 1.0, 2.5, 1.4}, {0, 0}}};  // 1.5 m: not a person
  EXPECT_FALSE(bystander_near_corridor(p, {0, 0}, {3, 0}, {3.3, 0}, 0.35, fixture));
  const std::vector<MovingBox> charger = {{{3.2, -0.2, 3.4, 0.2}, {0, 0}}};
  EXPECT_FALSE(bystander_near_corridor(p, {0, 0}, {3, 0}, {3.3, 0}, 0.35, charger));
}

// At full grip forward speed grows at most `full_grip_accel_mps2` (0.3 m/s^2 by default; 0 passes
// the twist through). A soft start: on a floor of friction 0.05 a set-off at the motors' 1 m/s^2
// spins the wheels, unseen along a lone wall. Braking and reversing to yield keep the motors'
// limits.
TEST(Traction, AFullGripAccelerationLimitRampsForwardSpeedOnly) {
  const double dt = 0.05;
  TractionParams motors_limit;
  motors_limit.full_grip_accel_mps2 = 0.0;
  TractionGovernor passing(motors_limit);
  EXPECT_DOUBLE_EQ(passing.limit({0.6, 0.2}, false, dt).v_mps, 0.6);
  TractionGovernor governor({});  // the default: 0.3 m/s^2
  double v = 0;
  for (int k = 1; k <= 40; ++k) {
    const Twist out = governor.limit({0.6, 0.2}, false, dt);
    EXPECT_NEAR(out.v_mps, std::min(0.6, 0.3 * dt * k), 1e-12);
    EXPECT_DOUBLE_EQ(out.omega_radps, 0.2);  // turning is not limited at full grip
    v = out.v_mps;
  }
  EXPECT_DOUBLE_EQ(v, 0.6);
  EXPECT_DOUBLE_EQ(governor.limit({0.0, 0.0}, false, dt).v_mps, 0.0);    // braking: at once
  EXPECT_DOUBLE_EQ(governor.limit({-0.5, 0.0}, false, dt).v_mps, -0.5);  // yielding: at once
  EXPECT_EQ(governor.slips(), 0);
}

}  // namespace
}  // namespace plantsim::controller
