// Closed-loop docking from many random start poses: success rate, collisions and pose
// errors, with ideal sensing and with odometry noise (with and without charger detection).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <random>

#include "episode/episode_config.h"
#include "episode/episode_config_json.h"
#include "episode/episode_result.h"
#include "episode/run_episode.h"
#include "planner/planner.h"
#include "planner/registry.h"
#include "test_paths.h"
#include "worlds/world_loader.h"

namespace plantsim::sim {
using namespace plantsim::episode;  // the episode's config and result
using episode::load_episode_config;
using episode::run_episode;

using namespace robot;  // the robot's side under test, beside the simulator that feeds it
namespace {

struct SuiteResult {
  int episodes = 0, docked = 0, collisions = 0;
  std::vector<double> position_errors_m;
  std::vector<std::string> failures;
  double median_error_m() const {
    auto v = position_errors_m;
    if (v.empty()) return 0;
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  }
  double success_rate() const { return episodes ? static_cast<double>(docked) / episodes : 0; }
};

// Start poses uniform over the free floor (outside every inflated obstacle), random heading.
std::vector<geom::Pose2> random_starts(const worlds::World& w, int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(w.floor.xmin, w.floor.xmax),
      uy(w.floor.ymin, w.floor.ymax), yaw(-M_PI, M_PI);
  auto planner = planner::make_planner("vg", planner::planner_input(w, true));
  const geom::Vec2 staging = worlds::staging_pose(w).position();
  std::vector<geom::Pose2> out;
  while (static_cast<int>(out.size()) < count) {
    const geom::Pose2 p{ux(rng), uy(rng), yaw(rng)};
    if (geom::distance(p.position(), w.charger.position()) < 2.0) continue;
    if (planner->plan(p.position(), staging).status == planner::PlanStatus::kOk) out.push_back(p);
  }
  return out;
}

SuiteResult run_suite(const std::string& file, int count, const EpisodeConfig& base,
                      std::uint64_t seed) {
  count = test::scaled(count, 6);  // smaller in the sanitizer tree (tests/test_paths.h)
  worlds::World w = worlds::load_world(test::shared_data(file));
  auto planner = planner::make_planner("vg", planner::planner_input(w, true));
  SuiteResult s;
  int k = 0;
  for (const geom::Pose2& start : random_starts(w, count, seed)) {
    w.start = start;
    EpisodeConfig config = base;
    config.seed = seed * 1000 + static_cast<std::uint64_t>(k++);
    const EpisodeResult r = run_episode(w, *planner, config);
    ++s.episodes;
    s.docked += r.docked;
    s.collisions += r.collisions;
    if (r.docked) s.position_errors_m.push_back(r.position_error_m);
    if (!r.docked || r.collisions)
      s.failures.push_back(episode::status_name(r) + " from (" + std::to_string(start.x) + ", " +
                           std::to_string(start.y) + ", " + std::to_string(start.yaw) +
                           "), collisions " + std::to_string(r.collisions) + ", error " +
                           std::to_string(r.position_error_m));
  }
  return s;
}

void report(const std::string& what, const SuiteResult& s) {
  std::printf("%s: %d/%d docked (%.1f %%), collisions %d, median position error %.2f mm\n",
              what.c_str(), s.docked, s.episodes, 100 * s.success_rate(), s.collisions,
              1000 * s.median_error_m());
  for (std::size_t i = 0; i < std::min<std::size_t>(s.failures.size(), 10); ++i)
    std::printf("  %s\n", s.failures[i].c_str());
}

TEST(DockingSuite, RandomStartsInN50AndN200) {
  const SuiteResult n50 = run_suite("worlds/world_N50.json", 200, {}, 50);
  report("world_N50, 200 random starts", n50);
  const SuiteResult n200 = run_suite("worlds/world_N200.json", 50, {}, 200);
  report("world_N200, 50 random starts", n200);
  EXPECT_GE((n50.success_rate() * 200 + n200.success_rate() * 50) / 250, 0.99);
  EXPECT_EQ(n50.collisions + n200.collisions, 0);
  EXPECT_LE(n50.median_error_m(), 0.01);
}

TEST(DockingSuite, NoisyOracleSensingDocksThanksToDetectionAndFailsWithout) {
  const EpisodeConfig noisy = load_episode_config(test::source_file("configs/oracle_noisy.json"));
  ASSERT_EQ(noisy.perception.mode, PerceptionMode::kOracle);
  ASSERT_GT(noisy.localization.period_s, 0);
  const SuiteResult with = run_suite("worlds/world_N50.json", 100, noisy, 7);
  report("world_N50, noisy oracle sensing, detection on", with);
  EpisodeConfig blind = noisy;
  blind.detection.enabled = false;
  const SuiteResult without = run_suite("worlds/world_N50.json", 100, blind, 7);
  report("world_N50, noisy oracle sensing, detection off", without);
  EXPECT_GE(with.success_rate(), 0.98);
  EXPECT_EQ(with.collisions, 0);
  // Without the detection the final approach inherits the localiser's centimetres of error:
  // even with three retries about half the episodes miss the 2 cm tolerance (45 of 100 dock
  // when this was written, against 100 of 100 with detection).
  EXPECT_LE(without.success_rate(), 0.7);
  EXPECT_GE(with.success_rate() - without.success_rate(), 0.3);
}

}  // namespace
}  // namespace plantsim::sim

namespace plantsim::sim {
namespace {

// Perception in the loop (the defaults) under detection stress: 30 % of the charger
// detections missed, and no detection at all (odometry, gyro and the scan-matching EKF).
TEST(DockingSuite, SensorsModeWithMissedDetectionsAndWithoutDetection) {
  EpisodeConfig misses;
  misses.detection.false_negative_probability = 0.3;
  const SuiteResult m = run_suite("worlds/world_N50.json", 100, misses, 30);
  report("world_N50, sensors, 30 % detections missed", m);
  EXPECT_GE(m.success_rate(), 0.98);
  EXPECT_EQ(m.collisions, 0);
  EpisodeConfig blind;
  blind.detection.enabled = false;
  const SuiteResult b = run_suite("worlds/world_N50.json", 100, blind, 31);
  report("world_N50, sensors, no detection", b);
  // Without detection the final approach rests on the EKF alone, whose error stays at
  // millimetres on a map that equals the plant: it docks nearly always (measured 100 %).
  EXPECT_GE(b.success_rate(), 0.95);
  EXPECT_EQ(b.collisions, 0);
}

}  // namespace
}  // namespace plantsim::sim
