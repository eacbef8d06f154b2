// Every number a YAML input gives plantsim read by one rule, decimal (worlds/decimal_number.h;
// issue 85): yaml-cpp's as<long>() read `seeds: 010` as 8 and `budget: 010` as 8 while the
// command line's `--budget 010` is 10, and took `negate: 0x1` as hexadecimal.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "app/nav2_import.h"
#include "batch/batch_spec.h"
#include "scratch_folder.h"
#include "test_paths.h"
#include "tune/tune_spec.h"
#include "worlds/decimal_number.h"
#include "worlds/ros_map.h"
#include "worlds/world_error.h"

namespace plantsim {
namespace {

class YamlNumbers : public test::ScratchFolder {
 protected:
  std::string scenario(const std::string& rest) {
    return write("s.yaml", "worlds: [" + test::shared_data("worlds/world_N10.json") +
                               "]\nplanners: [vg]\n" + rest);
  }
  template <typename Load>
  static std::string refusal(Load&& load) {
    try {
      load();
    } catch (const std::exception& e) {
      return e.what();
    }
    return "";
  }
};

// yaml-cpp's as<int>() reads a leading 0 as octal and 0x as hexadecimal; the command line reads
// decimal. One rule for all: decimal.
TEST(DecimalNumbers, LeadingZerosAreDecimalAndOtherBasesAndInfinitiesAreRefused) {
  EXPECT_EQ(worlds::decimal_whole_number(std::string("010")), 10u);
  EXPECT_EQ(worlds::decimal_whole_number(std::string("+7")), 7u);
  EXPECT_EQ(worlds::decimal_whole_number(std::string("18446744073709551615")),
            18446744073709551615u);
  for (const char* bad :
       {"0x10", "0o10", "-1", "1e3", "1.0", "", "+", "1_000", "18446744073709551616", " 1"})
    EXPECT_FALSE(worlds::decimal_whole_number(std::string(bad))) << bad;
  EXPECT_EQ(worlds::decimal_number(std::string("010")), 10.0);
  EXPECT_EQ(worlds::decimal_number(std::string(".5")), 0.5);
  EXPECT_EQ(worlds::decimal_number(std::string("-2.5e-1")), -0.25);
  for (const char* bad : {"0x10", ".inf", "-.inf", ".nan", "1e999", "1,5", "e5", "."})
    EXPECT_FALSE(worlds::decimal_number(std::string(bad))) << bad;
  EXPECT_FALSE(worlds::decimal_number(YAML::Load("[1]")));
  EXPECT_EQ(worlds::decimal_whole_number(YAML::Load("'010'")), 10u);
}

TEST_F(YamlNumbers, AScenariosCountsAndSeedsAreDecimal) {
  EXPECT_EQ(batch::load_batch_spec(scenario("seeds: 010\n")).seeds.size(), 10u);
  EXPECT_EQ(batch::load_batch_spec(scenario("seeds: [010, 011]\n")).seeds,
            (std::vector<std::uint64_t>{10, 11}));
  const batch::BatchSpec s =
      batch::load_batch_spec(scenario("seeds: 1\nfaults: {boxes: {unmapped_obstacles: 010}}\n"));
  EXPECT_EQ(s.faults.at(0).unmapped_obstacles, 10);
  EXPECT_NE(
      refusal([&] { batch::load_batch_spec(scenario("seeds: 0x10\n")); }).find("field 'seeds'"),
      std::string::npos);
  EXPECT_NE(refusal([&] {
              batch::load_batch_spec(
                  scenario("seeds: 1\nfaults: {k: {charger_map_offset: [.inf, 0, 0]}}\n"));
            }).find("field 'faults.k.charger_map_offset[0]': expected a finite decimal number"),
            std::string::npos);
}

TEST_F(YamlNumbers, ATuningsBudgetIsDecimalAsOnTheCommandLine) {
  tune::TuneRequest r;
  r.scenario = scenario("seeds: 2\ntune:\n  validation_seeds: [5]\n  budget: 010\n");
  EXPECT_EQ(tune::load_tune_spec(r).budget, 10);
  r.scenario = scenario("seeds: 2\ntune:\n  validation_seeds: [5]\n  budget: 0x10\n");
  EXPECT_NE(refusal([&] { tune::load_tune_spec(r); }).find("field 'tune.budget'"),
            std::string::npos);
  r.scenario = scenario(
      "seeds: 2\ntune:\n  validation_seeds: [5]\n  parameters: "
      "{tracking.max_linear_speed_mps: [0x1p-2, 1]}\n");
  EXPECT_NE(refusal([&] { tune::load_tune_spec(r); }).find("'0x1p-2' is not a number"),
            std::string::npos);
}

TEST_F(YamlNumbers, ARosMapsNegateIsDecimal) {
  write("m.pgm", "P2\n2 1\n255\n0 255\n");
  const std::string head =
      "image: m.pgm\nresolution: 0.5\norigin: [0, 0, 0]\noccupied_thresh: 0.65\n"
      "free_thresh: 0.196\n";
  EXPECT_EQ(worlds::load_ros_map(write("a.yaml", head + "negate: 01\n")).grid.cells.at(0), '.');
  EXPECT_NE(refusal([&] {
              worlds::load_ros_map(write("b.yaml", head + "negate: 0x1\n"));
            }).find("field 'negate': must be 0 or 1"),
            std::string::npos);
  EXPECT_NE(refusal([&] {
              worlds::load_ros_map(write("c.yaml", "image: m.pgm\nresolution: .inf\n"));
            }).find("field 'resolution': expected a decimal number"),
            std::string::npos);
}

TEST_F(YamlNumbers, ANav2ParameterIsADecimalNumber) {
  const std::string head =
      "controller_server:\n  ros__parameters:\n    FollowPath:\n      plugin: "
      "nav2_regulated_pure_pursuit_controller::RegulatedPurePursuitController\n";
  const app::Nav2Import ok =
      app::import_nav2_params(write("ok.yaml", head + "      desired_linear_vel: 0.50\n"));
  EXPECT_EQ(ok.mapped.size(), 1u);
  EXPECT_NE(refusal([&] {
              app::import_nav2_params(write("bad.yaml", head + "      desired_linear_vel: .inf\n"));
            }).find("expected a finite decimal number"),
            std::string::npos);
}

}  // namespace
}  // namespace plantsim
