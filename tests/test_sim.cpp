// Closed-loop episodes in Box2D: docking within tolerance with no collisions on the shared
// worlds, the wheel model, and bit-for-bit determinism.
#include <box2d/box2d.h>
#include <gtest/gtest.h>

#include "episode/episode_config.h"
#include "episode/episode_config_json.h"
#include "episode/episode_result.h"
#include "episode/run_episode.h"
#include "episode/stepped_episode.h"
#include "planner/planner.h"
#include "planner/registry.h"
#include "sim/box2d_step_timers.h"
#include "sim/physics_world.h"
#include "sim/wheel_drive.h"
#include "test_paths.h"
#include "worlds/world_loader.h"

namespace plantsim::sim {
using namespace plantsim::episode;  // the episode's config and result
using episode::default_config_json;
using episode::parse_episode_config;
using episode::run_episode;
namespace {

EpisodeResult dock(const worlds::World& world, std::uint64_t seed = 1) {
  auto p = planner::make_planner("vg", planner::planner_input(world, true));
  EpisodeConfig config;
  config.seed = seed;
  return run_episode(world, *p, config);
}

class DockingOnSharedWorlds : public ::testing::TestWithParam<const char*> {};

TEST_P(DockingOnSharedWorlds, DocksWithinTolerance) {
  const auto world = worlds::load_world(test::shared_data(GetParam()));
  const EpisodeResult r = dock(world);
  EXPECT_EQ(episode::status_name(r), "docked");
  EXPECT_TRUE(r.docked);
  EXPECT_LE(r.position_error_m, 0.02);
  EXPECT_LE(r.heading_error_deg, 2.0);
  EXPECT_EQ(r.collisions, 0);
  EXPECT_GT(r.driven_length_m, r.path_length_m);  // plan ends at staging; docking adds ~1 m
}

INSTANTIATE_TEST_SUITE_P(SharedData, DockingOnSharedWorlds,
                         ::testing::Values("worlds/world_N10.json", "worlds/world_N50.json"));

TEST(Docking, ExampleWorldWithChargerAgainstTheWall) {
  const auto world = worlds::load_world(test::source_file("data/worlds/examples/small_plant.json"));
  const EpisodeResult r = dock(world);
  EXPECT_TRUE(r.docked) << episode::status_name(r);
  EXPECT_EQ(r.collisions, 0);
}

TEST(Determinism, SameEpisodeTwiceGivesIdenticalTrajectories) {
  const auto world = worlds::load_world(test::shared_data("worlds/world_N10.json"));
  const EpisodeResult a = dock(world, 42), b = dock(world, 42);
  ASSERT_EQ(a.trajectory.size(), b.trajectory.size());
  for (std::size_t i = 0; i < a.trajectory.size(); ++i) {
    ASSERT_EQ(a.trajectory[i].truth.x, b.trajectory[i].truth.x) << i;
    ASSERT_EQ(a.trajectory[i].truth.y, b.trajectory[i].truth.y) << i;
    ASSERT_EQ(a.trajectory[i].truth.yaw, b.trajectory[i].truth.yaw) << i;
  }
}

worlds::World empty_floor() {
  worlds::World w;
  w.floor = {0, 0, 10, 10};
  w.start = {5, 5, 0};
  w.charger = {9, 5, 0};
  return w;
}

TEST(WheelDrive, OppositeWheelSpeedsTurnInPlace) {
  const worlds::World w = empty_floor();
  PhysicsWorld physics(w);
  WheelDrive drive(w.robot, {});
  StepSettings s;
  for (int k = 0; k < 120; ++k) {
    drive.command({-0.2, 0.2}, s.dt_s);
    drive.apply(physics, s.dt_s);
    physics.step(s);
  }
  const Pose2 p = physics.robot_pose();
  EXPECT_NEAR(p.x, 5.0, 1e-3);
  EXPECT_NEAR(p.y, 5.0, 1e-3);
  EXPECT_NEAR(physics.robot_yaw_rate(), 0.4 / w.robot.wheel_base_m, 0.02);
}

TEST(WheelDrive, EqualWheelSpeedsDriveStraightAtThatSpeed) {
  const worlds::World w = empty_floor();
  PhysicsWorld physics(w);
  WheelDrive drive(w.robot, {});
  StepSettings s;
  for (int k = 0; k < 120; ++k) {
    drive.command({0.5, 0.5}, s.dt_s);
    drive.apply(physics, s.dt_s);
    physics.step(s);
  }
  EXPECT_NEAR(physics.robot_velocity().x, 0.5, 0.01);
  EXPECT_NEAR(physics.robot_pose().y, 5.0, 1e-4);
  EXPECT_NEAR(physics.robot_pose().yaw, 0.0, 1e-4);
}

}  // namespace
}  // namespace plantsim::sim

namespace plantsim::sim {
namespace {

TEST(MovingObstacles, ACrossingPersonMakesTheRobotStopWithoutCollision) {
  const auto world =
      worlds::load_world(test::source_file("data/worlds/examples/corridor_crossing.json"));
  ASSERT_EQ(world.moving.size(), 1u);
  const EpisodeResult r = dock(world);
  EXPECT_TRUE(r.docked) << episode::status_name(r);
  EXPECT_GE(r.stops, 1);
  EXPECT_EQ(r.collisions, 0);
  // Without the arc check the same robot drives into the person, unless the stopping bound
  // (traction.stop_within_sight, issue 88: the raw scan's free range ahead, no tracking) slows it
  // first: blind to tracks it still docks without touching the person; blind to both it hits.
  worlds::World blind = world;
  auto p = planner::make_planner("vg", planner::planner_input(blind, true));
  EpisodeConfig config;
  config.perception.tracker.range_m = 1e-3;  // tracks nothing
  EXPECT_EQ(run_episode(blind, *p, config).collisions, 0);
  config.traction.stop_within_sight = false;
  const EpisodeResult hit = run_episode(blind, *p, config);
  EXPECT_GT(hit.collisions, 0);
}

TEST(MovingObstacles, AParkedCartForcesAReplanAndTheRobotStillDocks) {
  const auto world = worlds::load_world(test::source_file("data/worlds/examples/parked_cart.json"));
  const EpisodeResult r = dock(world);
  EXPECT_TRUE(r.docked) << episode::status_name(r);
  EXPECT_GE(r.stops, 1);
  EXPECT_GE(r.replans, 1);
  EXPECT_EQ(r.collisions, 0);
  // The route finally followed goes over the block (y > 8), not under it.
  double highest = 0;
  for (const auto& s : r.trajectory) highest = std::max(highest, s.truth.y);
  EXPECT_GT(highest, 8.0);
}

TEST(MovingObstacles, ScriptedMotionIsAFunctionOfTime) {
  worlds::MovingObstacle m;
  m.waypoints = {{0, 0}, {2, 0}};
  m.speed_mps = 1.0;
  m.start_time_s = 1.0;
  EXPECT_EQ(m.position_at(0.5).x, 0.0);  // waiting
  EXPECT_DOUBLE_EQ(m.position_at(2.0).x, 1.0);
  EXPECT_DOUBLE_EQ(m.position_at(9.0).x, 2.0);  // parked at the end
  m.loop = true;
  EXPECT_DOUBLE_EQ(m.position_at(4.0).x, 1.0);  // on the way back
}

}  // namespace
}  // namespace plantsim::sim

namespace plantsim::sim {
namespace {

TEST(WheelDrive, AHardTurnAtSpeedSkidsOnASlipperyFloor) {
  // Full speed straight, then straight into a spin. With strong motors (5 m/s^2) a dry floor
  // (mu 0.8, 7.8 m/s^2 of grip) stops it as the motors ramp (about 0.13 m); on a wet one (mu 0.1,
  // 0.98 m/s^2) the tyres saturate and the robot slides on, about v^2 / (2 mu g) = 0.33 m.
  double slide[2] = {0, 0};
  bool slipped[2] = {false, false};
  const double mus[2] = {0.8, 0.1};
  for (int i = 0; i < 2; ++i) {
    worlds::World w = empty_floor();
    w.start = {1, 5, 0};
    w.robot.max_accel_mps2 = 5.0;
    PhysicsWorld physics(w);
    DriveParams params;
    params.tyre_friction = mus[i];
    WheelDrive drive(w.robot, params);
    StepSettings s;
    for (int k = 0; k < 120; ++k) {
      drive.command({0.8, 0.8}, s.dt_s);
      drive.apply(physics, s.dt_s);
      physics.step(s);
    }
    ASSERT_NEAR(physics.robot_velocity().x, 0.8, 0.02);
    const geom::Vec2 before = physics.robot_position();
    for (int k = 120; k < 240; ++k) {
      drive.command({-0.8, 0.8}, s.dt_s);
      drive.apply(physics, s.dt_s);
      slipped[i] |= drive.slipping();
      physics.step(s);
    }
    slide[i] = geom::distance(before, physics.robot_position());
  }
  EXPECT_FALSE(slipped[0]);
  EXPECT_LT(slide[0], 0.15);  // the motors ramp the left wheel through 0 in 0.16 s: ~0.13 m
  EXPECT_TRUE(slipped[1]);
  EXPECT_GT(slide[1], 0.25);
  EXPECT_LT(slide[1], 0.45);
}

}  // namespace
}  // namespace plantsim::sim

namespace plantsim::sim {
namespace {

TEST(Footprint, RectangularRobotDocksFaceOnWithoutCollision) {
  const auto world =
      worlds::load_world(test::source_file("data/worlds/examples/small_plant_rect_robot.json"));
  ASSERT_TRUE(world.robot.rectangular());
  EXPECT_NEAR(world.robot.radius_m, 0.5 * std::hypot(0.5, 0.36), 1e-12);  // planning radius
  EXPECT_DOUBLE_EQ(world.robot.front_extent_m(), 0.25);
  const EpisodeResult r = dock(world);
  EXPECT_TRUE(r.docked) << episode::status_name(r);
  EXPECT_EQ(r.collisions, 0);
  EXPECT_LE(r.position_error_m, 0.02);
}

TEST(EpisodeConfigFile, ReadsValuesAndRejectsUnknownKeysAndBadValues) {
  const EpisodeConfig c = parse_episode_config(
      R"({"tracking": {"max_linear_speed_mps": 0.4}, "docking": {"max_retries": 5}, "detection": {"enabled": false}})",
      "c.json");
  EXPECT_DOUBLE_EQ(c.tracking.max_linear_speed_mps, 0.4);
  EXPECT_EQ(c.docking.max_retries, 5);
  EXPECT_FALSE(c.detection.enabled);
  EXPECT_DOUBLE_EQ(c.tracking.lookahead_max_m,
                   EpisodeConfig{}.tracking.lookahead_max_m);  // untouched
  auto fails_with = [](const std::string& text, const std::string& needle) {
    try {
      parse_episode_config(text, "c.json");
      ADD_FAILURE() << text;
    } catch (const worlds::WorldError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  fails_with(R"({"tracking": {"max_linear_sped_mps": 0.4}})",
             "tracking.max_linear_sped_mps': unknown");
  fails_with(R"({"tracking": {"max_linear_speed_mps": "fast"}})", "expected a number");
  fails_with(R"({"step": {"dt_s": 0}})", "step.dt_s");
  fails_with(R"({"docking": {"max_retries": -1}})", "docking.max_retries");
  fails_with("{oops", "malformed JSON");
  fails_with(R"({"step": {"dt_s": 0.01}, "step": {"dt_s": 0.02}})",
             "field 'step': given twice in one object");
  // The printed defaults read back to the defaults.
  const EpisodeConfig round = parse_episode_config(default_config_json(), "defaults");
  EXPECT_DOUBLE_EQ(round.step.dt_s, EpisodeConfig{}.step.dt_s);
  EXPECT_EQ(round.control_period_steps, EpisodeConfig{}.control_period_steps);
}

}  // namespace
}  // namespace plantsim::sim

namespace plantsim::sim {
namespace {

// A long episode's logs stay within their limits (EpisodeConfig::log_limits) and still span
// it: the same episode with small limits drives exactly as with none, its trajectory is every
// k-th sample of the whole one plus the last, evenly spaced, and so are the movers' tracks.
TEST(LongEpisodes, LogsKeepTheirLimitsAndStillSpanTheEpisode) {
  const auto world = worlds::load_world(test::source_file("data/worlds/examples/parked_cart.json"));
  auto p = planner::make_planner("vg", planner::planner_input(world, true));
  EpisodeConfig config;
  config.scan_log_period_s = 0.2;
  const EpisodeResult whole = run_episode(world, *p, config);
  config.log_limits = {64, 40, 8, 1};
  const EpisodeResult thin = run_episode(world, *p, config);
  ASSERT_TRUE(whole.docked) << episode::status_name(whole);
  EXPECT_EQ(thin.status, whole.status);
  EXPECT_EQ(thin.time_s, whole.time_s);
  EXPECT_EQ(thin.physics_steps, whole.physics_steps);
  EXPECT_FALSE(whole.thinning.any());

  ASSERT_GT(whole.trajectory.size(), 4 * 64u);
  EXPECT_LE(thin.trajectory.size(), 64u);
  const int k = thin.thinning.trajectory_every;
  EXPECT_GE(k, 4);
  for (std::size_t i = 0; i + 1 < thin.trajectory.size(); ++i) {
    ASSERT_LT(i * k, whole.trajectory.size());
    EXPECT_EQ(thin.trajectory[i].t_s, whole.trajectory[i * k].t_s) << i;
    EXPECT_EQ(thin.trajectory[i].truth.x, whole.trajectory[i * k].truth.x) << i;
  }
  EXPECT_EQ(thin.trajectory.back().t_s, whole.trajectory.back().t_s);  // the end, always
  EXPECT_GE(thin.trajectory.size() * k, whole.trajectory.size() - k);  // nothing lost at the end

  ASSERT_EQ(thin.moving_tracks.size(), 1u);
  const auto& track = thin.moving_tracks.front().t_s;
  EXPECT_LT(track.size(), 40u);
  EXPECT_GT(thin.thinning.moving_every, 1);
  // Every 0.25 s at the control steps' times (30 Hz): up to a step later each.
  const double every = 0.25 * thin.thinning.moving_every, step = 1.0 / 30;
  for (std::size_t i = 0; i + 1 < track.size(); ++i) {
    EXPECT_GE(track[i + 1] - track[i], every - 1e-9) << i;
    EXPECT_LE(track[i + 1] - track[i], every + thin.thinning.moving_every * step + 1e-9) << i;
  }
  EXPECT_GT(track.back(), whole.time_s - 2 * every);

  EXPECT_LE(thin.perception_log.size(), 8u);
  EXPECT_GT(thin.perception_log.back().t_s,
            whole.time_s - 0.2 * thin.thinning.snapshots_every - 0.05);
  EXPECT_GE(whole.events.size(), 2u);  // a stop for the cart, a replan
  EXPECT_EQ(thin.events.size(), 1u);
  EXPECT_EQ(thin.thinning.events_dropped, static_cast<std::int64_t>(whole.events.size()) - 1);
}

}  // namespace
}  // namespace plantsim::sim

namespace plantsim::episode {
namespace {

// Driven a period at a time with plantsim's own command, the episode is the one run_episode runs
// in a call, bit for bit; the outside is asked only while it steers (not during the gyro's
// calibration at rest, not while plantsim docks by itself), and nothing steps after the end.
TEST(SteppedEpisode, DrivenWithTheBuiltinCommandItIsTheSameEpisode) {
  auto world = std::make_shared<const worlds::World>(
      worlds::load_world(test::source_file("data/worlds/examples/corridor_crossing.json")));
  episode::EpisodeConfig config;
  config.seed = 3;
  auto p = planner::make_planner("vg", planner::planner_input(*world, true));
  const episode::EpisodeResult whole = run_episode(*world, *p, config);
  ASSERT_TRUE(whole.docked) << episode::status_name(whole);

  // plantsim docking within the step that reaches the staging pose, and a period a step (the
  // command ignored while it docks): the same episode both ways.
  std::int64_t whole_steps = 0;
  for (const DockingSteps docking :
       {DockingSteps::kBuiltinToTheEnd, DockingSteps::kBuiltinEachPeriod}) {
    SteppedEpisode stepped(world, "vg", config, docking);
    ASSERT_TRUE(stepped.start());
    EXPECT_GE(stepped.view().perception->t_s, config.perception.gyro_calibration_s - 1e-9);
    EXPECT_EQ(stepped.view().phase, controller::DockPhase::kTravel);
    std::int64_t docking_steps = 0;
    while (stepped.step(docking == DockingSteps::kBuiltinEachPeriod && !stepped.outside_steers()
                            ? controller::Twist{5.0, 3.0}  // ignored: plantsim docks
                            : stepped.view().builtin)) {
      if (docking == DockingSteps::kBuiltinToTheEnd) {
        ASSERT_EQ(stepped.view().phase, controller::DockPhase::kTravel);  // docks by itself
      }
      docking_steps += !stepped.outside_steers();
    }
    const episode::EpisodeResult& r = stepped.result();
    EXPECT_EQ(r.status, whole.status);
    EXPECT_EQ(r.time_s, whole.time_s);
    ASSERT_EQ(r.trajectory.size(), whole.trajectory.size());
    EXPECT_EQ(r.trajectory.back().truth.x, whole.trajectory.back().truth.x);
    EXPECT_EQ(r.trajectory.back().truth.y, whole.trajectory.back().truth.y);
    EXPECT_GT(stepped.steps(), 100);
    EXPECT_LE(stepped.steps(), static_cast<std::int64_t>(whole.trajectory.size()));
    EXPECT_THROW(stepped.step({0, 0}), std::logic_error);
    if (docking == DockingSteps::kBuiltinToTheEnd) {
      whole_steps = stepped.steps();
      EXPECT_EQ(docking_steps, 0);
    } else {  // every docking period a step of its own: docking lasts seconds at 15 Hz
      EXPECT_GT(docking_steps, 60);
      EXPECT_EQ(stepped.steps(), whole_steps + docking_steps);
    }
  }

  // Standing still when asked to: the robot never leaves its start, the episode times out.
  config.timeout_s = 8;
  SteppedEpisode still(world, "vg", config, DockingSteps::kOutside);
  ASSERT_TRUE(still.start());
  while (still.step({0, 0})) {
  }
  EXPECT_EQ(episode::status_name(still.result()), "timeout");
  for (const episode::TrajectorySample& s : still.result().trajectory)
    EXPECT_LT(geom::distance(s.truth.position(), world->start.position()), 0.01);
}

}  // namespace
}  // namespace plantsim::episode

// Box2D's profile is what its step timers fill: zero while plantsim keeps them off (the library's
// own b2Timer replaced by the program's), real durations when the bench turns them on, and the
// bodies move the same either way.
TEST(Box2dStepTimers, OffTheProfileStaysZeroOnItMeasuresAndTheMotionIsTheSame) {
  auto fall = [](bool timed, float& profiled_ms) {
    plantsim::sim::set_box2d_step_timers(timed);
    b2World world(b2Vec2(0.0f, -9.8f));
    b2BodyDef ground_def;
    b2Body* ground = world.CreateBody(&ground_def);
    b2PolygonShape floor;
    floor.SetAsBox(50.0f, 0.5f);
    ground->CreateFixture(&floor, 0.0f);
    std::vector<b2Body*> boxes;
    for (int i = 0; i < 40; ++i) {
      b2BodyDef def;
      def.type = b2_dynamicBody;
      def.position.Set(-20.0f + static_cast<float>(i), 2.0f + 0.3f * static_cast<float>(i % 7));
      b2Body* body = world.CreateBody(&def);
      b2PolygonShape box;
      box.SetAsBox(0.4f, 0.4f);
      body->CreateFixture(&box, 1.0f);
      boxes.push_back(body);
    }
    profiled_ms = 0;
    for (int k = 0; k < 600; ++k) {
      world.Step(1.0f / 60.0f, 8, 3);
      profiled_ms += world.GetProfile().step;
    }
    plantsim::sim::set_box2d_step_timers(false);
    std::vector<float> heights;
    for (const b2Body* b : boxes) heights.push_back(b->GetPosition().y);
    return heights;
  };
  EXPECT_FALSE(plantsim::sim::box2d_step_timers());
  float off_ms = -1, on_ms = -1;
  const std::vector<float> off = fall(false, off_ms);
  const std::vector<float> on = fall(true, on_ms);
  EXPECT_EQ(off_ms, 0.0f);
  EXPECT_GT(on_ms, 0.0f);
  EXPECT_EQ(off, on);
  EXPECT_LT(off.front(), 1.0f);  // the boxes fell onto the floor
}
