// Batches: shards merged equal one run, a killed run resumes without redoing or losing
// episodes, bad input is refused before any episode, the Wilson interval, and the docking
// suite over the plant scenarios and the ROS maps.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "batch/batch_merge.h"
#include "batch/batch_runner.h"
#include "batch/episode_runner.h"
#include "batch/navigation_tally.h"
#include "batch/shortest_possible.h"
#include "batch/wilson_interval.h"
#include "batch_folder_test.h"
#include "episode/episode_json.h"
#include "planner/registry.h"
#include "test_paths.h"
#include "worlds/world_error.h"

namespace plantsim::batch {
namespace {

namespace fs = std::filesystem;

class BatchFiles : public test::BatchFolderTest {
 protected:
  // Three seeds and two planners; in the sanitizer tree, where each episode costs several times
  // more, two seeds and one planner (every path of sharding, merging and resuming all the same).
  static int seeds() { return test::full_size() ? 3 : 2; }
  static int planners() { return test::full_size() ? 2 : 1; }
  std::string small_scenario() {
    return write("s.yaml", "name: small\nworlds: [" + test::shared_data("worlds/world_N10.json") +
                               ", " + test::source_file("data/worlds/examples/small_plant.json") +
                               "]\nplanners: [vg" + (planners() == 2 ? ", vg-traditional" : "") +
                               "]\nfaults:\n  none: {}\n  slip: "
                               "{odometry: {left_scale_error: 0.002}}\n"
                               "  crossing: {crossing_obstacle: true}\nseeds: " +
                               std::to_string(seeds()) + "\n");
  }
  // The records without their wall times (the controller's compute time differs from run to
  // run of the same episode; episode/episode_json.h), sorted.
  static std::vector<std::string> sorted_lines(const std::string& path) {
    std::ifstream in(path);
    std::vector<std::string> lines;
    for (std::string l; std::getline(in, l);)
      lines.push_back(episode::without_wall_times(nlohmann::ordered_json::parse(l)).dump());
    std::sort(lines.begin(), lines.end());
    return lines;
  }
  static std::string read(const std::string& path) {
    std::ifstream in(path);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
};

TEST_F(BatchFiles, FourShardsMergedEqualOneRun) {
  const std::string scenario = small_scenario();
  const BatchOutcome whole = run_batch(scenario, options("whole"));
  EXPECT_EQ(whole.episodes, 2 * planners() * 3 * seeds());
  // The crossing person makes the robot stop in some episodes, and never hits it. (The slip
  // fault, dead reckoning with a 0.2 % wheel error and no localiser, may drift into walls.)
  int crossing_stops = 0;
  for (const auto& line : sorted_lines((dir_ / "whole/episodes.jsonl").string())) {
    const auto j = nlohmann::json::parse(line);
    if (j["fault"] != "crossing") continue;
    crossing_stops += j["stops"].get<int>();
    EXPECT_EQ(j["collisions"].get<int>(), 0) << line;
    EXPECT_TRUE(j["docked"].get<bool>()) << line;
  }
  EXPECT_GT(crossing_stops, 0);
  std::vector<std::string> shard_dirs;
  std::int64_t sum = 0;
  for (int i = 0; i < 4; ++i) {
    sum += run_batch(scenario, options("shard" + std::to_string(i), i, 4)).episodes;
    shard_dirs.push_back((dir_ / ("shard" + std::to_string(i))).string());
  }
  EXPECT_EQ(sum, whole.episodes);
  EXPECT_EQ(merge_batches(shard_dirs, (dir_ / "merged").string()).episodes, whole.episodes);
  EXPECT_EQ(sorted_lines((dir_ / "merged/episodes.jsonl").string()),
            sorted_lines((dir_ / "whole/episodes.jsonl").string()));
  EXPECT_EQ(csv_without_wall_times(read((dir_ / "merged/summary.csv").string())),
            csv_without_wall_times(read((dir_ / "whole/summary.csv").string())));
}

TEST_F(BatchFiles, AKilledRunResumesWithoutRedoingOrLosingEpisodes) {
  const std::string scenario = small_scenario();
  run_batch(scenario, options("full"));
  const auto full = sorted_lines((dir_ / "full/episodes.jsonl").string());
  // A run killed mid-way: the first 7 episodes written, the 8th torn half-way.
  fs::create_directories(dir_ / "killed");
  {
    std::ifstream in((dir_ / "full/episodes.jsonl").string());
    std::ofstream out((dir_ / "killed/episodes.jsonl").string());
    std::string line;
    for (int k = 0; k < 7 && std::getline(in, line); ++k) out << line << "\n";
    std::getline(in, line);
    out << line.substr(0, line.size() / 2);
  }
  const BatchOutcome resumed = run_batch(scenario, options("killed"));
  EXPECT_EQ(resumed.skipped, 7);
  EXPECT_EQ(resumed.ran, resumed.episodes - 7);
  EXPECT_EQ(sorted_lines((dir_ / "killed/episodes.jsonl").string()),
            full);                                           // nothing twice, nothing lost
  EXPECT_EQ(run_batch(scenario, options("killed")).ran, 0);  // a finished batch runs nothing
}

TEST_F(BatchFiles, BadInputIsRefusedBeforeAnyEpisode) {
  auto refused = [&](const std::string& scenario, const std::string& needle,
                     const std::string& out = "out") {
    try {
      run_batch(scenario, options(out));
      ADD_FAILURE() << "accepted " << scenario;
    } catch (const std::exception& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(dir_ / out / "episodes.jsonl") &&
                 fs::file_size(dir_ / out / "episodes.jsonl") > 0);
  };
  refused(write("a.yaml", "worlds: [1, 2"), "malformed YAML");
  refused(write("b.yaml", "worlds: []\nseeds: 1\n"), "field 'worlds'");
  refused(write("c.yaml", "worlds: [" + (dir_ / "missing.json").string() + "]\nseeds: 1\n"),
          "not found");
  refused(write("d.yaml", "worlds: [" + test::shared_data("worlds/world_N10.json") +
                              "]\nplanners: [teleport]\nseeds: 1\n"),
          "unknown planner");
  refused(write("e.yaml", "worlds: [" + test::shared_data("worlds/world_N10.json") +
                              "]\nseeds: 1\nfaults:\n  x: {odometry: {wheel_nois: 1}}\n"),
          "unknown parameter");
  refused(write("f.yaml", "worlds: [" + test::shared_data("worlds/world_N10.json") + "]\n"),
          "field 'seeds'");
  // yaml-cpp keeps the first copy of a repeated key: seeds 1 or 2? The file is refused.
  refused(write("h.yaml", "worlds: [" + test::shared_data("worlds/world_N10.json") +
                              "]\nseeds: 1\nfaults:\n  wet: {drive: {tyre_friction: 0.2}}\n"
                              "  dry: {}\nseeds: 2\n"),
          "field 'seeds': given twice in one mapping");
  refused(write("i.yaml", "worlds: [" + test::shared_data("worlds/world_N10.json") +
                              "]\nseeds: 1\nfaults:\n  wet: {lidar: {range_noise_m: 0.01, "
                              "range_noise_m: 0.05}}\n"),
          "field 'faults.wet.lidar.range_noise_m': given twice");
  // A sweep value twice ran two configurations with one name and one id per episode.
  for (const std::string values : {"[0.2, 0.2]", "[0.5, 5e-1]", "[1, 1.0]"})
    refused(write("j.yaml", "worlds: [" + test::shared_data("worlds/world_N10.json") +
                                "]\nseeds: 1\nsweep: {parameter: drive.tyre_friction, values: " +
                                values + "}\n"),
            "field 'sweep.values'");
  write("file_in_the_way", "x");
  refused(
      write("g.yaml", "worlds: [" + test::shared_data("worlds/world_N10.json") + "]\nseeds: 1\n"),
      "cannot be created", "file_in_the_way/sub");
}

// The driven length's lower bound, by hand: around one wall with a gap at its top, the box grown
// by (inscribed radius - 0.01 m) / sqrt(2); split into legs at a carry; none from inside a box.
TEST(ShortestPossible, ByHandAroundAWallSplitAtACarryNoneFromInsideABox) {
  worlds::World w;
  w.floor = {0, 0, 10, 10};
  w.obstacles = {{4, 0, 6, 8}};
  w.robot.radius_m = 0.2;
  const double d = (0.2 - 0.01) / std::sqrt(2.0);
  EXPECT_NEAR(shortest_possible_input(w).inflation_m, d, 1e-12);
  const auto bound = planner::make_planner("vg", shortest_possible_input(w));
  const double over = 2 * std::hypot(2 - d, 6 + d) + (2 + 2 * d);
  const auto around = shortest_possible_m(*bound, {2, 2, 0}, {}, {8, 2});
  ASSERT_TRUE(around.has_value());
  EXPECT_NEAR(*around, over, 1e-9);
  const std::vector<episode::EpisodeResult::Carry> lifted = {{10.0, {3, 2, 0}, {7, 2, 1.0}}};
  const auto carried = shortest_possible_m(*bound, {2, 2, 0}, lifted, {8, 2});
  ASSERT_TRUE(carried.has_value());
  EXPECT_NEAR(*carried, 2.0, 1e-9);  // 1 m to where it was lifted, 1 m from where it landed
  EXPECT_FALSE(shortest_possible_m(*bound, {2, 2, 0}, {}, {5, 2}).has_value());
  // A rectangular footprint: the largest disk inside it, not its circumscribed radius.
  w.robot.length_m = 0.6;
  w.robot.width_m = 0.4;
  w.robot.radius_m = 0.36;
  EXPECT_NEAR(shortest_possible_input(w).inflation_m, d, 1e-12);
}

TEST(Wilson, KnownValues) {
  const auto [lo, hi] = wilson_interval(10, 10);
  EXPECT_NEAR(lo, 0.7225, 1e-4);  // the interval for 10 of 10
  EXPECT_DOUBLE_EQ(hi, 1.0);
  const auto [lo2, hi2] = wilson_interval(50, 100);
  EXPECT_NEAR(lo2, 0.4038, 1e-4);
  EXPECT_NEAR(hi2, 0.5962, 1e-4);
}

// The docking suite: 504 episodes over the five plant scenarios (the substation with its people
// and van moving) and both ROS maps, from random starts, with ideal and with noisy sensing.
TEST_F(BatchFiles, DockingSuiteOverPlantsAndRosMaps) {
  std::string worlds;
  for (const char* w :
       {"data/worlds/plants/desulfurization_plant.json", "data/worlds/plants/substation_yard.json",
        "data/worlds/plants/coal_mine_roadways.json", "data/worlds/plants/cable_tunnel_maze.json",
        "data/worlds/plants/rail_maintenance_pit.json"})
    worlds += test::source_file(w) + ", ";
  worlds += test::shared_data("ros_maps/depot.yaml") + ", " +
            test::shared_data("ros_maps/tb3_sandbox.yaml");
  const std::string scenario =
      write("suite.yaml",
            "name: docking_suite\nworlds: [" + worlds +
                "]\nfaults:\n  none: {}\n  noisy:\n    odometry: {wheel_speed_noise: 0.02, "
                "left_scale_error: 0.003, "
                "right_scale_error: -0.003}\n    lidar: {range_noise_m: 0.03, dropout_probability: "
                "0.05}\n    imu: {yaw_rate_noise_radps: 0.006, bias_radps: 0.006}\n"
                "    detection: {position_noise_m: 0.005, yaw_noise_rad: 0.005}\nseeds: " +
                std::to_string(test::scaled(36, 1)) + "\n");
  const BatchOutcome r = run_batch(scenario, options("suite"));
  std::printf("docking suite: %lld episodes, %lld docked, %lld collisions\n",
              static_cast<long long>(r.episodes), static_cast<long long>(r.succeeded),
              static_cast<long long>(r.collisions));
  EXPECT_GE(r.episodes, test::scaled(500, 14));
  EXPECT_GE(r.succeeded, static_cast<std::int64_t>(std::ceil(0.99 * r.episodes)));
  EXPECT_EQ(r.collisions, 0);
  // The efficiency measure's yardstick is a true lower bound: no docked episode drove less than
  // the shortest possible (the planning optimum with its margin was beaten by most of them).
  int bounded = 0;
  for (const auto& line : sorted_lines((dir_ / "suite/episodes.jsonl").string())) {
    const auto j = nlohmann::json::parse(line);
    if (!j["docked"].get<bool>()) continue;
    ASSERT_TRUE(j.contains("shortest_possible_m")) << j["id"];
    const double shortest = j["shortest_possible_m"].get<double>();
    EXPECT_GT(shortest, 0.0) << j["id"];
    EXPECT_GE(j["driven_length_m"].get<double>(), shortest) << j["id"];
    ++bounded;
  }
  EXPECT_EQ(bounded, r.succeeded);
}

}  // namespace
}  // namespace plantsim::batch

namespace plantsim::batch {
namespace {

// A kidnap on a tuning yard (yard_s2, start and kidnap of seed 4 as the scenario draws them): set
// down 9 m from the top boundary with nothing else in range, the particle filter's robot follows
// that wall to the corner. The place its reseed kept for the estimate slid 0.4 m along the wall
// and, refined a few centimetres a scan, could not climb out when the wall's end came into view;
// particles drawn about it every third scan restarted the confirmation until the robot gave up
// with its estimate 1 cm off. The place now moves onto the estimate that fits clearly better,
// and the robot charges (by issue 89's rule off its estimate: it drove its search lost). The case
// was recorded with the robot setting off at the motors' limit (before the soft start,
// traction.full_grip_accel_mps2): a later set-off moves the kidnap's moment, and the landing with
// it (in the sanitizer build to a place the search found only at 184 s, past the time a lost robot
// has), so the test keeps that limit.
TEST_F(BatchFiles, AKidnappedParticleFilterConfirmsItsPlaceAtAYardsCorner) {
  const std::string scenario =
      write("yard.yaml", "name: yard_kidnap\nworlds: [" +
                             test::source_file("data/worlds/generated/styles/yard_s2.json") +
                             "]\nplanners: [vg]\ncontrollers:\n  particles: {localization: "
                             "{estimator: particles}, traction: {full_grip_accel_mps2: 0}}\n"
                             "faults:\n  kidnap: {random_kidnap: "
                             "{after_s: [10, 60], distance_m: [3, 10]}}\nseeds: 4\n");
  const ReplayedEpisode e = replay_batch_episode(scenario, "yard_s2|vg|particles|kidnap|4");
  const episode::EpisodeResult& r = e.result;
  EXPECT_TRUE(r.charging) << episode::status_name(r)
                          << (r.failure ? ": " + r.failure->detail : std::string());
  EXPECT_GE(r.relocalizations, 1);
  EXPECT_EQ(r.collisions, 0);
  // Issue 89: its search drove 27.8 m in all on an estimate more than 0.25 m off (measured on
  // e03a352), reported lost all the while. Saying so no longer makes that a success: it charged,
  // off its estimate, by the integrity rule's distance side (docs/failures.md).
  EXPECT_EQ(r.status, episode::EpisodeStatus::kDockedOffEstimate);
  ASSERT_TRUE(r.integrity.breach.has_value());
  EXPECT_EQ(r.integrity.breach->kind, sim::BreachKind::kDrivenOff);
  EXPECT_GT(r.integrity.driven_off_m, 1.0);
}

// With the lidar, the EKF and the tracker on (the defaults), one thread or two give the same
// episode records, to the last digit.
TEST_F(BatchFiles, ThreadsDoNotChangeResultsWithPerceptionOn) {
  const std::string scenario =
      write("t.yaml", "name: threads\nworlds: [" +
                          test::source_file("data/worlds/examples/corridor_crossing.json") +
                          "]\nplanners: [vg]\nfaults:\n  none: {}\n  lossy: {lidar: "
                          "{dropout_probability: 0.1}}\nseeds: 2\n");
  RunOptions one = options("one"), two = options("two");
  one.threads = 1;
  two.threads = 2;
  run_batch(scenario, one);
  run_batch(scenario, two);
  const auto a = sorted_lines(one.out_dir + "/episodes.jsonl"),
             b = sorted_lines(two.out_dir + "/episodes.jsonl");
  ASSERT_EQ(a.size(), 4u);
  EXPECT_EQ(a, b);
  EXPECT_NE(a[0].find("\"perception_mode\":\"sensors\""), std::string::npos);
}

}  // namespace
}  // namespace plantsim::batch
