// The navigation-benchmark metrics (issue 87 item 4): the true footprint's clearance on
// hand-made cases, jerk and angular acceleration on motions whose answer is known, the
// controller's compute time taken around its calls alone, the fields in the records, summary.csv
// and summary.json, and the wall times left out of every comparison of two runs.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "batch/batch_gate.h"
#include "batch/batch_summary.h"
#include "batch/navigation_tally.h"
#include "batch/record_schema.h"
#include "batch/summary_tables.h"
#include "episode/controller_clock.h"
#include "episode/episode_json.h"
#include "episode/footprint_clearance.h"
#include "episode/navigation_metrics.h"
#include "episode/run_episode.h"
#include "planner/registry.h"
#include "tests/test_paths.h"
#include "worlds/world_loader.h"

namespace plantsim::episode {
namespace {

using geom::Pose2;
using geom::Rect;

/// A 20 x 10 m floor, one box over x 4..6 and y 6.5..7.5, a disk robot of radius 0.25.
worlds::World open_floor() {
  worlds::World w;
  w.floor = {0, 0, 20, 10};
  w.obstacles = {{4, 6.5, 6, 7.5}};
  w.robot.radius_m = 0.25;
  return w;
}

TEST(FootprintClearance, ADiskMeasuresToBoxesWallsAndMovingObstacles) {
  worlds::World w = open_floor();
  const FootprintClearance c(w);
  EXPECT_NEAR(c.at({5, 5, 0}, {}), 1.25, 1e-12);    // 1.5 m below the box, less the radius
  EXPECT_NEAR(c.at({2, 5, 0.7}, {}), 1.75, 1e-12);  // the wall at x = 0 nearer than the box
  EXPECT_NEAR(c.at({5, 5, 0}, {{5.5, 4, 6, 6}}), 0.25, 1e-12);  // a person 0.5 m to the side
  EXPECT_EQ(c.at({5, 6.5, 0}, {}), 0.0);                        // overlapping: 0, not negative
  w.unmapped = {{4.5, 4, 5.5, 4.5}};                            // a box the map lacks counts too
  EXPECT_NEAR(FootprintClearance(w).at({5, 5, 0}, {}), 0.25, 1e-12);
}

TEST(FootprintClearance, ARectangleTurnsWithItsHeading) {
  worlds::World w = open_floor();
  w.robot.length_m = 1.0, w.robot.width_m = 0.4;
  w.robot.radius_m = std::hypot(0.5, 0.2);
  const FootprintClearance c(w);
  // Heading along x: 0.2 m of it reaches towards the box above; along y: 0.5 m.
  EXPECT_NEAR(c.at({5, 5, 0}, {}), 1.3, 1e-9);
  EXPECT_NEAR(c.at({5, 5, M_PI / 2}, {}), 1.0, 1e-9);
  // A small box wholly under the footprint overlaps it though no edge meets it.
  EXPECT_EQ(c.at({10, 5, 0}, {{9.9, 4.9, 10.1, 5.1}}), 0.0);
  EXPECT_NEAR(c.at({10, 9.5, 0}, {}), 0.3, 1e-9);  // the top wall, from the corners
}

TEST(NavigationMetrics, AStraightDrivePastABoxGivesItsClearance) {
  NavigationMetrics m(open_floor(), 0.1);
  // Along y = 5 from x = 1 to 9 at 0.5 m/s: nearest the box (1.25 m) under it, the wall at the
  // start (x = 1: 0.75 m) is nearer still. Start at x = 3: the box is the nearest thing.
  for (int k = 0; k <= 40; ++k) m.sample({3 + 0.1 * k, 5, 0}, 0.5, 0, {}, true);
  EpisodeOutcome r;
  m.write(r);
  EXPECT_NEAR(r.min_clearance_m, 1.25, 1e-12);
  EXPECT_GT(r.mean_clearance_m, 1.25);
  EXPECT_EQ(r.near_obstacle_share, 0.0);
  EXPECT_NEAR(r.rms_jerk_mps3, 0.0, 1e-9);  // constant speed
  EXPECT_NEAR(r.rms_angular_accel_radps2, 0.0, 1e-9);
  // Within 0.3 m of a person for a quarter of the samples.
  NavigationMetrics near(open_floor(), 0.1);
  for (int k = 0; k < 8; ++k)
    near.sample({10, 5, 0}, 0, 0, k < 2 ? std::vector<Rect>{{10.4, 4, 11, 6}} : std::vector<Rect>{},
                true);
  near.write(r);
  EXPECT_NEAR(r.near_obstacle_share, 0.25, 1e-12);
  EXPECT_NEAR(r.min_clearance_m, 0.15, 1e-12);
}

TEST(NavigationMetrics, JerkAndAngularAccelerationOfKnownMotions) {
  const double T = 1.0 / 30;
  EpisodeOutcome r;
  NavigationMetrics accelerating(open_floor(), T);  // constant acceleration 0.5 m/s^2: jerk 0
  for (int k = 0; k < 60; ++k) accelerating.sample({10, 5, 0}, 0.5 * k * T, 0.3, {}, true);
  accelerating.write(r);
  EXPECT_NEAR(r.rms_jerk_mps3, 0.0, 1e-9);
  EXPECT_NEAR(r.rms_angular_accel_radps2, 0.0, 1e-9);  // a constant turn
  NavigationMetrics jerky(open_floor(), T);  // v = j t^2 / 2 with j = 2: jerk 2 throughout
  for (int k = 0; k < 60; ++k) {
    const double t = k * T;
    jerky.sample({10, 5, 0}, t * t, 0.4 * t, {}, true);  // yaw rate ramping at 0.4 rad/s^2
  }
  jerky.write(r);
  EXPECT_NEAR(r.rms_jerk_mps3, 2.0, 1e-6);
  EXPECT_NEAR(r.rms_angular_accel_radps2, 0.4, 1e-9);
}

TEST(NavigationMetrics, OnlyTheTravelCountsAndNoDifferenceSpansABreak) {
  const double T = 0.1;
  NavigationMetrics m(open_floor(), T);
  EpisodeOutcome r;
  m.write(r);  // nothing travelled: nothing measured
  EXPECT_TRUE(std::isnan(r.min_clearance_m) && std::isnan(r.rms_jerk_mps3));
  // Steady at 0.2 m/s, then docking (left out) at another speed, carried, steady at 0.6 m/s.
  for (int k = 0; k < 5; ++k) m.sample({12, 5, 0}, 0.2, 0.1, {}, true);
  m.sample({5, 6.4, 0}, 0.05, 0, {}, false);  // touching the box while docking: not counted
  m.sample({12, 5, 0}, 0.6, 0.5, {}, true);
  m.carried();
  for (int k = 0; k < 5; ++k) m.sample({12, 5, 0}, 0.9, 0.9, {}, true);
  m.write(r);
  EXPECT_NEAR(r.min_clearance_m, 4.75, 1e-12);  // the wall at y = 0 from y = 5
  EXPECT_NEAR(r.rms_jerk_mps3, 0.0, 1e-9);
  EXPECT_NEAR(r.rms_angular_accel_radps2, 0.0, 1e-9);
}

class Echo final : public controller::LocalController {
 public:
  void set_path(std::vector<geom::Vec2> path) override { points = path.size(); }
  controller::TrackingCommand step(const controller::LocalQuery& q) override {
    controller::TrackingCommand c;
    c.twist = {q.speed_mps, 0.25};
    return c;
  }
  std::size_t points = 0;
};

TEST(ControllerClock, TimesEachStepCallAndForwardsEverything) {
  ControllerClock clock;
  EXPECT_TRUE(std::isnan(clock.quantile_ms(0.5)));
  controller::LocalControllerEntry entry;
  entry.name = "echo";
  entry.make = [](const controller::LocalControllerContext&, const util::ParamValues&) {
    auto made = std::make_unique<Echo>();
    made->set_plugin_origin("echo.so");
    return std::unique_ptr<controller::LocalController>(std::move(made));
  };
  const controller::LocalControllerEntry timed = timed_entry(entry, clock);
  EXPECT_EQ(timed.name, "echo");
  auto c = timed.make({}, util::ParamValues{});
  EXPECT_EQ(c->plugin_origin(), "echo.so");  // the follower still names a plugin that throws
  c->set_path({{0, 0}, {1, 0}});
  controller::LocalQuery q;
  q.speed_mps = 0.4;
  for (int k = 0; k < 10; ++k) EXPECT_EQ(c->step(q).twist.v_mps, 0.4);
  EXPECT_EQ(clock.cycles(), 10);
  EXPECT_GE(clock.quantile_ms(0.5), 0.0);
  EXPECT_LE(clock.quantile_ms(0.5), clock.quantile_ms(0.99));
}

TEST(ControllerClock, NearestRankQuantiles) {
  ControllerClock clock;
  for (int k = 100; k >= 1; --k) clock.add(0.001 * k);  // 1 .. 100 ms
  EXPECT_NEAR(clock.quantile_ms(0.5), 50.0, 1e-9);
  EXPECT_NEAR(clock.quantile_ms(0.99), 99.0, 1e-9);
  EXPECT_NEAR(clock.quantile_ms(1.0), 100.0, 1e-9);
}

/// A whole record of `r` as the batch writes its metrics, named as an episode of world `w`.
std::string record_of(const EpisodeOutcome& r, const std::string& world, int seed) {
  nlohmann::ordered_json j;
  j["index"] = seed;
  j["id"] = world + "|vg|default|none|" + std::to_string(seed);
  j["scenario"] = "s";
  j["world"] = world, j["planner"] = "vg", j["controller"] = "default", j["fault"] = "none";
  j["seed"] = seed;
  j["succeeded"] = r.succeeded();
  add_episode_metrics(j, r);
  j["optimal_length_m"] = 10.0;
  return j.dump();
}

TEST(NavigationMetrics, AnEpisodeMeasuresThemAndTheRecordsAndSummariesCarryThem) {
  const worlds::World w =
      worlds::load_world(test::source_file("data/worlds/examples/corridor_crossing.json"));
  EpisodeConfig config;
  config.seed = 5;
  auto planner = planner::make_planner("vg", planner::planner_input(w, true));
  const EpisodeResult e = run_episode(w, *planner, config);
  ASSERT_TRUE(e.docked);
  EXPECT_GT(e.controller_cycles, 100);
  EXPECT_GE(e.controller_ms_median, 0.0);
  EXPECT_LE(e.controller_ms_median, e.controller_ms_p99);
  EXPECT_GT(e.min_clearance_m, 0.0);  // it docked without touching anything
  EXPECT_LE(e.min_clearance_m, e.mean_clearance_m);
  EXPECT_TRUE(e.near_obstacle_share >= 0 && e.near_obstacle_share <= 1);
  EXPECT_TRUE(std::isfinite(e.rms_jerk_mps3) && std::isfinite(e.rms_angular_accel_radps2));
  std::vector<std::string> lines = {record_of(e, "corridor", 1), record_of(e, "corridor", 2)};
  EpisodeOutcome idle;  // never travelled: nulls, still a valid record
  lines.push_back(record_of(idle, "corridor", 3));
  for (const std::string& line : lines) EXPECT_EQ(batch::record_problem(line), "") << line;
  const nlohmann::json j = nlohmann::json::parse(lines[0]);
  for (const char* key : {"min_clearance_m", "mean_clearance_m", "near_obstacle_share",
                          "rms_jerk_mps3", "rms_angular_accel_radps2", "controller_cycles",
                          "controller_ms_median", "controller_ms_p99"})
    EXPECT_TRUE(j.at(key).is_number()) << key;
  EXPECT_TRUE(nlohmann::json::parse(lines[2])["min_clearance_m"].is_null());
  // summary.csv's row and summary.json's configuration: the episodes' values, the idle one left
  // out.
  const std::string csv = batch::summary_csv(lines);
  EXPECT_NE(csv.find(",min_clearance_m,mean_clearance_m,near_obstacle_share,mean_rms_jerk_mps3,"
                     "mean_rms_angular_accel_radps2,controller_ms_median,controller_ms_p99_max,"),
            std::string::npos)
      << csv;
  const batch::Gate gate;
  const nlohmann::json summary =
      batch::batch_summary_json(lines, batch::judge_configurations(lines, gate), gate, "t", "c");
  const nlohmann::json& row = summary["configurations"][0];
  EXPECT_NEAR(row["min_clearance_m"].get<double>(), e.min_clearance_m, 1e-12);
  EXPECT_NEAR(row["mean_rms_jerk_mps3"].get<double>(), e.rms_jerk_mps3, 1e-12);
  EXPECT_NEAR(row["controller_ms_p99_max"].get<double>(), e.controller_ms_p99, 1e-12);
}

TEST(NavigationMetrics, WallTimesAreLeftOutOfEveryComparisonOfTwoRuns) {
  EpisodeOutcome a;
  a.controller_cycles = 10, a.controller_ms_median = 1.0, a.controller_ms_p99 = 2.0;
  EpisodeOutcome b = a;
  b.controller_ms_median = 1.5, b.controller_ms_p99 = 7.0;  // the same episode on a busier machine
  const std::string ra = record_of(a, "w", 1), rb = record_of(b, "w", 1);
  EXPECT_NE(ra, rb);
  EXPECT_EQ(without_wall_times(nlohmann::json::parse(ra)),
            without_wall_times(nlohmann::json::parse(rb)));
  const std::string ca = batch::summary_csv({ra}), cb = batch::summary_csv({rb});
  EXPECT_NE(ca, cb);
  EXPECT_EQ(batch::csv_without_wall_times(ca), batch::csv_without_wall_times(cb));
  EXPECT_EQ(batch::csv_without_wall_times(ca).find("controller_ms"), std::string::npos);
  // A count is not a wall time: it stays.
  EXPECT_NE(without_wall_times(nlohmann::json::parse(ra)).dump().find("controller_cycles"),
            std::string::npos);
}

}  // namespace
}  // namespace plantsim::episode
