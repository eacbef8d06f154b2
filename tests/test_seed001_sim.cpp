// Seed 001 in the simulation: the document's two examples (a target slower than the robot
// among moving obstacles; a faster one behind a wall), potential-field travel docking on a
// plant, and the moving target as a scripted sensor body.
#include <gtest/gtest.h>

#include "episode/episode_config.h"
#include "episode/episode_result.h"
#include "episode/run_episode.h"
#include "planner/planner.h"
#include "planner/registry.h"
#include "sim/physics_world.h"
#include "test_paths.h"
#include "worlds/world_loader.h"

namespace plantsim::sim {
using namespace plantsim::episode;  // the episode's config and result
using episode::run_episode;
namespace {

EpisodeResult run(const worlds::World& world, const std::string& travel, std::uint64_t seed = 1) {
  auto p = planner::make_planner("vg", planner::planner_input(world, true));
  EpisodeConfig config;
  config.travel = travel;
  config.seed = seed;
  return episode::run_episode(world, *p, config);
}

// When the scripted target reaches the end of its track.
double park_time(const worlds::MovingObstacle& m) {
  double length = 0;
  for (std::size_t i = 1; i < m.waypoints.size(); ++i)
    length += geom::distance(m.waypoints[i - 1], m.waypoints[i]);
  return m.start_time_s + length / m.speed_mps;
}

// Forty noise seeds, not one or ten: the field's local minima among the moving obstacles delay
// some pursuits past the target's parking, and now and then a person walks into the robot or
// the robot grazes one (a seed's noise decides which). Over 400 seeds (1 to 400, this code)
// the field caught the target in 392, 305 of them while it still moved, with a contact in 18
// episodes, 7 of them begun by the robot. The bounds below are those rates' 0.5 % tails for 40
// seeds: the test fails when the method gets worse, not when a change of the noise's streams
// deals other seeds (ten seeds with every one clean, the old test, held by luck: p = 0.3).
TEST(Seed001, CatchesATargetSlowerThanItselfAmongMovingObstacles) {
  const auto world =
      worlds::load_world(test::source_file("data/worlds/plants/seed001_slow_target.json"));
  ASSERT_TRUE(world.target.has_value());
  int caught = 0, while_moving = 0, with_contact = 0, begun_by_robot = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const EpisodeResult r = run(world, "potential-field", seed);
    caught += r.caught && episode::status_name(r) == "caught";
    while_moving += r.caught && r.time_s < park_time(*world.target);
    with_contact += r.collisions > 0;
    begun_by_robot += r.collisions_robot_moving > 0;
    // Never faster than the document's 0.5 m/s (a small overshoot of the drive's speed loop).
    for (const auto& s : r.trajectory)
      ASSERT_LE(s.speed_mps, 0.52) << "seed " << seed << " " << s.t_s;
  }
  EXPECT_GE(caught, 36);         // 392 / 400: P(<= 35 of 40) = 0.001
  EXPECT_GE(while_moving, 23);   // 305 / 400: P(<= 22) = 0.003
  EXPECT_LE(with_contact, 6);    // 18 / 400: P(>= 7) = 0.002
  EXPECT_LE(begun_by_robot, 4);  // 7 / 400: P(>= 5) = 0.0006
}

TEST(Seed001, FollowsTheWallAroundThenReachesAFasterTarget) {
  const auto world =
      worlds::load_world(test::source_file("data/worlds/plants/seed001_target_behind_wall.json"));
  const EpisodeResult r = run(world, "potential-field");
  EXPECT_EQ(episode::status_name(r), "caught");
  EXPECT_EQ(r.collisions, 0);
  EXPECT_GE(r.local_minima, 1);
  EXPECT_GE(r.wall_follows, 1);
  EXPECT_GT(r.time_s, park_time(*world.target));  // 0.6 m/s is out of reach until it stops
  bool followed = false;
  for (const auto& s : r.trajectory) followed = followed || s.wall_following;
  EXPECT_TRUE(followed);
}

TEST(Seed001, PotentialFieldTravelHandsOverToDocking) {
  const auto world = worlds::load_world(test::source_file("data/worlds/examples/small_plant.json"));
  const EpisodeResult r = run(world, "potential-field");
  EXPECT_TRUE(r.docked) << episode::status_name(r);
  EXPECT_EQ(r.collisions, 0);
  EXPECT_EQ(r.travel, "potential-field");
  EXPECT_GE(r.driven_length_m, r.path_length_m);  // the plan is the optimum it is measured against
}

TEST(Seed001, DrivesEvenWhenTheReferencePlannerFindsNoPath) {
  const auto world = worlds::load_world(test::source_file("data/worlds/examples/small_plant.json"));
  auto p = planner::make_planner("maze-left",
                                 planner::planner_input(world, true));  // no lattice: no path
  EpisodeConfig config;
  config.travel = "potential-field";
  const EpisodeResult r = episode::run_episode(world, *p, config);
  EXPECT_TRUE(r.docked) << episode::status_name(r);
  EXPECT_TRUE(r.plan.empty());
  EXPECT_NE(r.plan_note.find("no reference plan"), std::string::npos);
}

TEST(Seed001, TheTargetMovesOnItsScriptAndCollidesWithNothing) {
  auto world =
      worlds::load_world(test::source_file("data/worlds/plants/seed001_target_behind_wall.json"));
  world.start = {11.0, 5.0, 0.0};  // right in the target's way
  PhysicsWorld physics(world);
  StepSettings s;
  for (int i = 0; i < 120; ++i) physics.step(s);
  const auto target = physics.target();
  ASSERT_TRUE(target.has_value());
  const Vec2 expected = world.target->position_at(120 * s.dt_s);
  EXPECT_NEAR(target->box.center().x, expected.x, 1e-4);
  EXPECT_NEAR(target->box.center().y, expected.y, 1e-4);
  EXPECT_FALSE(physics.contacts().obstacle);
  EXPECT_NEAR(physics.robot_position().x, 11.0, 1e-6);  // a sensor body pushes nothing
}

TEST(Seed001, ATargetOffTheFloorIsRejectedNamingTheField) {
  auto text = R"({"floor": {"xmin": 0, "ymin": 0, "xmax": 10, "ymax": 10}, "obstacles": [],
    "robot": {"radius_m": 0.2, "wheel_base_m": 0.34, "wheel_radius_m": 0.06, "max_speed_mps": 0.8, "max_accel_mps2": 1},
    "start": {"x": 1, "y": 1, "yaw": 0}, "charger": {"x": 9.6, "y": 5, "yaw": 0},
    "target": {"size_m": [0.4, 0.4], "waypoints": [[5, 5], [12, 5]], "speed_mps": 0.4}})";
  try {
    worlds::parse_world_json(text, "t.json");
    FAIL() << "accepted";
  } catch (const worlds::WorldError& e) {
    EXPECT_NE(std::string(e.what()).find("target.waypoints[1]"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace plantsim::sim
