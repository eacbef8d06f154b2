// A plant that is not its map: unmapped obstacles and a charger off its mapped pose loaded
// and refused as the world format says, the robot's map built without them, the local
// obstacle layer marking and clearing, and an episode through all of it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "episode/episode_config.h"
#include "episode/episode_result.h"
#include "episode/run_episode.h"
#include "planner/planner.h"
#include "planner/registry.h"
#include "robot/local_obstacle_layer.h"
#include "sim/charger_pads.h"
#include "test_paths.h"
#include "worlds/world_error.h"
#include "worlds/world_loader.h"

namespace plantsim {
namespace {

const std::string kMismatch = "data/worlds/examples/small_plant_mismatch.json";

TEST(PlantMismatch, TheMapLeavesOutUnmappedObstaclesAndMovesTheCharger) {
  const worlds::World plant = worlds::load_world(test::source_file(kMismatch));
  ASSERT_EQ(plant.unmapped.size(), 3u);
  EXPECT_TRUE(worlds::differs_from_map(plant));
  const worlds::World map = worlds::robot_map(plant);
  EXPECT_TRUE(map.unmapped.empty());
  EXPECT_FALSE(worlds::differs_from_map(map));
  EXPECT_DOUBLE_EQ(map.charger.x, plant.charger.x + 0.03);
  EXPECT_DOUBLE_EQ(map.charger.y, plant.charger.y - 0.04);
  EXPECT_DOUBLE_EQ(map.charger.yaw, plant.charger.yaw + 0.05);
  // The planner is given the map: its obstacles are the mapped ones and the charger's body
  // where the map puts it.
  const planner::PlannerInput in = planner::planner_input(plant, true);
  EXPECT_EQ(in.obstacles.size(), plant.obstacles.size() + 1);
  const planner::PlannerInput from_map = planner::planner_input(map, true);
  EXPECT_DOUBLE_EQ(in.obstacles.back().xmin, from_map.obstacles.back().xmin);
  EXPECT_DOUBLE_EQ(in.obstacles.back().ymin, from_map.obstacles.back().ymin);
}

class MismatchFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = (std::filesystem::temp_directory_path() /
             ("plantsim_mismatch_" + std::to_string(::getpid()) + "_" +
              ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".json"))
                .string();
  }
  void TearDown() override { std::filesystem::remove(path_); }
  void expect_error(const nlohmann::json& j, const std::string& needle) {
    std::ofstream(path_) << j.dump();
    try {
      worlds::load_world(path_);
      FAIL() << "no error (expected '" << needle << "')";
    } catch (const worlds::WorldError& e) {
      EXPECT_NE(std::string(e.what()).find(path_), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  }
  static nlohmann::json good() {
    return nlohmann::json::parse(std::ifstream(test::source_file(kMismatch)));
  }
  std::string path_;
};

TEST_F(MismatchFiles, BadUnmappedObstaclesAndOffsetsAreRefusedNamingTheField) {
  auto j = good();
  j["unmapped"][1] = {23, 1, 25, 2};
  expect_error(j, "field 'unmapped[1]': lies outside the floor");
  j = good();
  j["unmapped"][0] = {1.0, 6.8, 1.5, 7.2};  // on the start (1.2, 7.0)
  expect_error(j, "field 'unmapped[0]': covers the start");
  j = good();
  j["unmapped"][2] = {23.2, 11.8, 23.4, 12.2};  // on the docked pose (23.5, 12.0)
  expect_error(j, "field 'unmapped[2]': covers the charger's docked pose");
  j = good();
  j["unmapped"][2] = {23.75, 11.9, 23.8, 12.1};  // on the charger block (23.7 .. 23.8)
  expect_error(j, "field 'unmapped[2]': covers the charger");
  j = good();
  j["unmapped"][0] = {3, 2, 1, 5};
  expect_error(j, "field 'unmapped[0]': needs xmax > xmin");
  j = good();
  j["charger_map_offset"] = {0.1, 0.2};
  expect_error(j, "field 'charger_map_offset': expected [dx, dy, dyaw]");
  j = good();
  j["charger_map_offset"] = {0.1, "up", 0};
  expect_error(j, "field 'charger_map_offset[1]': expected a number");
  j = good();
  j["charger_map_offset"] = {3.0, 0.0, 0.0};  // the mapped charger beyond the floor
  expect_error(j, "field 'charger_map_offset'");
}

TEST(LocalObstacleLayer, MarksWhatTwoScansSeeAndClearsWhatIsSeenThroughLater) {
  robot::ObstacleLayerParams p;
  robot::LocalObstacleLayer layer(p);
  // A lidar at the origin facing +x, 181 beams over 180 degrees.
  robot::LidarScan scan;
  scan.angle_min_rad = -M_PI / 2;
  scan.angle_increment_rad = M_PI / 180;
  scan.min_range_m = 0.05;
  scan.max_range_m = 20;
  scan.ranges.assign(181, 20.0);
  const geom::Pose2 sensor{0, 0, 0};
  // A face at x = 2.03 from y = -0.2 to 0.2 (the beams within +-5.7 degrees).
  std::vector<geom::Vec2> face;
  for (int i = 85; i <= 95; ++i) {
    const double a = scan.angle(static_cast<std::size_t>(i));
    scan.ranges[static_cast<std::size_t>(i)] = 2.03 / std::cos(a);
    face.push_back({2.03, 2.03 * std::tan(a)});
  }
  layer.update(scan, sensor, face);
  EXPECT_TRUE(layer.occupied().empty());  // one scan is not enough
  layer.update(scan, sensor, face);
  const std::vector<geom::Rect> cells = layer.occupied();
  ASSERT_EQ(cells.size(), 1u);  // one column of cells, merged
  // Tight to the returns, not grown to whole cells.
  EXPECT_NEAR(cells[0].xmin, 2.03, 1e-9);
  EXPECT_NEAR(cells[0].xmax, 2.03, 1e-9);
  EXPECT_NEAR(cells[0].ymin, 2.03 * std::tan(-5 * M_PI / 180), 1e-9);
  // The thing is gone: beams pass where it stood. Evidence 4 is cleared by 4 free views.
  for (int i = 85; i <= 95; ++i) scan.ranges[static_cast<std::size_t>(i)] = 20.0;
  layer.update(scan, sensor, {});
  EXPECT_FALSE(layer.occupied().empty());  // one free view does not erase two sightings
  for (int k = 0; k < 3; ++k) layer.update(scan, sensor, {});
  EXPECT_TRUE(layer.occupied().empty());
  EXPECT_EQ(layer.cells(), 0u);
  // Dropouts (NaN) and beams stopping short of a cell never clear it.
  layer.update(scan, sensor, face);
  layer.update(scan, sensor, face);
  for (int i = 85; i <= 95; ++i) scan.ranges[static_cast<std::size_t>(i)] = (i % 2) ? NAN : 1.0;
  for (int k = 0; k < 5; ++k) layer.update(scan, sensor, {});
  EXPECT_EQ(layer.occupied().size(), 1u);
}

TEST(PlantMismatch, DocksOnTheRealChargerAroundObstaclesItsMapLacks) {
  const worlds::World plant = worlds::load_world(test::source_file(kMismatch));
  auto planner = planner::make_planner("vg", planner::planner_input(plant, true));
  episode::EpisodeConfig c;
  c.timeout_s = 300;
  const episode::EpisodeResult r = episode::run_episode(plant, *planner, c);
  EXPECT_TRUE(r.docked) << episode::status_name(r);
  EXPECT_EQ(r.collisions, 0);
  EXPECT_EQ(r.unmapped_seen, 3);
  EXPECT_GE(r.replans, 1);
  // Errors against the real charger, 5 cm and 3 degrees from where the map has it.
  EXPECT_LT(r.position_error_m, 0.02);
  EXPECT_LT(r.heading_error_deg, 2.0);
  EXPECT_FALSE(r.layer_final.empty());
}

}  // namespace
}  // namespace plantsim

namespace plantsim::sim {
using namespace plantsim::episode;  // the episode's config and result
using episode::run_episode;

using namespace robot;  // the robot's side under test, beside the simulator that feeds it
namespace {

// 1 ms steps; returns the first time charging is reported (or -1).
double charging_after(ChargerPads& pads, const geom::Pose2& robot, double seconds) {
  const geom::Pose2 docked{5, 5, M_PI / 2};
  for (int k = 1; k <= static_cast<int>(seconds * 1000); ++k) {
    pads.step(robot, docked, 0.001);
    if (pads.charging()) return k * 0.001;
  }
  return -1;
}

TEST(ChargerPads, ChargeOnlyWhenPressedWithinToleranceForTheDwell) {
  ChargerPadParams p;  // 5 mm travel, 1 mm press, 2 cm, 2 deg, 0.5 s
  // Pressed 2 mm, centred, square (the docked pose faces +y): charging after the dwell.
  ChargerPads pads(p);
  EXPECT_NEAR(charging_after(pads, {5, 5 - 0.0025 + 0.002, M_PI / 2}, 2.0), 0.5, 0.0015);
  EXPECT_TRUE(pads.touched());
  // Touching the pads without pressing them the minimum: touched, never charging.
  ChargerPads light(p);
  EXPECT_LT(charging_after(light, {5, 5 - 0.0025 + 0.0005, M_PI / 2}, 2.0), 0);
  EXPECT_TRUE(light.touched());
  // Pressed but 3 cm off the axis, or 3 degrees askew: never charging.
  ChargerPads off(p);
  EXPECT_LT(charging_after(off, {5.03, 5.001, M_PI / 2}, 2.0), 0);
  EXPECT_TRUE(off.touched());
  ChargerPads askew(p);
  EXPECT_LT(charging_after(askew, {5, 5.001, M_PI / 2 + 3 * M_PI / 180}, 2.0), 0);
  // Short of the pads: nothing.
  ChargerPads short_of(p);
  EXPECT_LT(charging_after(short_of, {5, 4.99, M_PI / 2}, 1.0), 0);
  EXPECT_FALSE(short_of.touched());
  // On the axis and square but 3 m past the docked pose: behind the charger, across its wall
  // (a maze route's dead end ran there and used to charge with a 3.1 m error).
  ChargerPads behind(p);
  EXPECT_LT(charging_after(behind, {5, 8.1, M_PI / 2}, 1.0), 0);
  EXPECT_FALSE(behind.touched());
  // A break in the press restarts the dwell.
  ChargerPads bounce(p);
  EXPECT_LT(charging_after(bounce, {5, 5.001, M_PI / 2}, 0.4), 0);
  bounce.step({5, 4.99, M_PI / 2}, {5, 5, M_PI / 2}, 0.001);
  EXPECT_NEAR(charging_after(bounce, {5, 5.001, M_PI / 2}, 2.0), 0.5, 0.0015);
}

}  // namespace
}  // namespace plantsim::sim

#include <random>

#include "geometry/predicates.h"
#include "planner/vg/vg_overlay.h"

namespace plantsim::planner {
namespace {

// Replanning around sensed boxes on the map's own graph gives the lengths a planner rebuilt
// with the boxes added gives: exact, without the rebuild.
TEST(ReplanOnTheMapGraph, SameLengthsAsARebuildWithTheBoxesAdded) {
  int compared = 0, blocked = 0;
  for (const char* file : {"worlds/world_N50.json", "worlds/world_N200.json"}) {
    const worlds::World w = worlds::load_world(test::shared_data(file));
    const PlannerInput in = planner_input(w, true);
    VisibilityGraphPlanner base(in);  // one graph for every query: its caches warm up as they go
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> ux(w.floor.xmin, w.floor.xmax),
        uy(w.floor.ymin, w.floor.ymax), side(0.3, 1.6);
    for (int trial = 0; trial < 60; ++trial) {
      std::vector<Rect> raw, inflated;
      const int k = 1 + trial % 8;
      for (int i = 0; i < k; ++i) {
        const double x = ux(rng), y = uy(rng), a = side(rng), b = side(rng);
        raw.push_back({x - a / 2, y - b / 2, x + a / 2, y + b / 2});
        inflated.push_back(raw.back().inflated(in.inflation_m));
      }
      PlannerInput with = in;
      with.obstacles.insert(with.obstacles.end(), raw.begin(), raw.end());
      const auto rebuilt = make_planner("vg", with);
      for (int q = 0; q < 5; ++q) {
        const Vec2 s{ux(rng), uy(rng)}, g{ux(rng), uy(rng)};
        const PlanResult full = rebuilt->plan(s, g);
        if (full.status == PlanStatus::kStartBlocked || full.status == PlanStatus::kGoalBlocked)
          continue;
        const PlanResult over = plan_with_added(base, inflated, s, g);
        ASSERT_EQ(over.status, full.status) << file << " trial " << trial << " query " << q;
        ASSERT_FALSE(over.start_snapped);
        if (full.status == PlanStatus::kOk) {
          ASSERT_NEAR(over.length, full.length, 1e-9 * std::max(1.0, full.length))
              << file << " trial " << trial;
          ++compared;
        } else {
          ++blocked;
        }
      }
    }
  }
  EXPECT_GT(compared, 300);
  std::printf("%d paths equal to the rebuilt planner's, %d no-path agreed\n", compared, blocked);
}

TEST(ReplanOnTheMapGraph, AStartWithinAnAddedBoxLeavesByTheNearestSide) {
  worlds::World w;
  w.floor = {0, 0, 10, 10};
  w.start = {1, 1, 0};
  w.charger = {9, 9, 0};
  PlannerInput in = planner_input(w, false);
  VisibilityGraphPlanner base(in);
  const Rect box{4.0, 4.0, 6.0, 6.0};
  const PlanResult r = plan_with_added(base, {box}, {4.2, 5.0}, {8.0, 5.0});
  ASSERT_EQ(r.status, PlanStatus::kOk);
  EXPECT_TRUE(r.start_snapped);
  EXPECT_DOUBLE_EQ(r.path.front().x, 4.0);  // out by the near side
  EXPECT_DOUBLE_EQ(r.path.front().y, 5.0);
  for (std::size_t i = 1; i < r.path.size(); ++i)
    EXPECT_FALSE(geom::segment_enters_open_rect(r.path[i - 1], r.path[i], box));
  EXPECT_EQ(plan_with_added(base, {box}, {1.0, 1.0}, {5.0, 5.0}).status, PlanStatus::kGoalBlocked);
  // A wall with a gap at its top; a sensed box closing the gap leaves no way.
  worlds::World walled = w;
  walled.obstacles = {{4.9, 0.0, 5.1, 8.0}};
  VisibilityGraphPlanner with_wall(planner_input(walled, false));
  EXPECT_EQ(plan_with_added(with_wall, {}, {1, 1}, {9, 1}).status, PlanStatus::kOk);
  EXPECT_EQ(plan_with_added(with_wall, {{4.0, 8.0, 6.0, 10.0}}, {1, 1}, {9, 1}).status,
            PlanStatus::kNoPath);
}

}  // namespace
}  // namespace plantsim::planner
