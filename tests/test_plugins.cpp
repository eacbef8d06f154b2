// Plugins: one that loads registers its components by name, chosen and configured as built-ins
// are; each way a plugin is refused names the file before any episode (and the command line
// exits 2, writing nothing); a plugin's part that throws in an episode ends that episode with
// `plugin_error`, and a batch goes on with the others.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "cli_fixture.h"
#include "controller/local_controller_registry.h"
#include "episode/episode_config_json.h"
#include "episode/run_episode.h"
#include "planner/registry.h"
#include "plugins/plugin_loader.h"
#include "robot/failure.h"
#include "test_paths.h"
#include "worlds/world_loader.h"

namespace plantsim {
namespace {

episode::EpisodeResult run_with(const std::string& config_text, double timeout_s = 60) {
  const worlds::World w =
      worlds::load_world(test::source_file("data/worlds/examples/corridor_crossing.json"));
  auto planner = planner::make_planner("vg", planner::planner_input(w, true));
  episode::EpisodeConfig c = episode::parse_episode_config(config_text, "c.json");
  c.timeout_s = timeout_s;
  return episode::run_episode(w, *planner, c);
}

TEST(Plugins, OneThatLoadsRegistersItsComponentsOnce) {
  const plugins::LoadedPlugin& p = plugins::load_plugin(TEST_PLUGIN_GOOD);
  EXPECT_EQ(p.local_controllers, (std::vector<std::string>{"test-thrower", "test-map-refuser"}));
  EXPECT_EQ(controller::local_controllers().at("test-thrower").origin, TEST_PLUGIN_GOOD);
  EXPECT_EQ(&plugins::load_plugin(TEST_PLUGIN_GOOD), &p);  // the same file: loaded once
  // Its parameter is a configuration row with its bounds, as a built-in's.
  EXPECT_EQ(episode::number_parameter("test-thrower.throw_after_steps").hi, 100000);
  EXPECT_THROW(
      episode::parse_episode_config(R"({"test-thrower": {"throw_after_steps": -2}})", "c.json"),
      std::exception);
}

TEST(Plugins, EachBadOneIsRefusedNamingItsFile) {
  struct Bad {
    const char* file;
    const char* says;
  };
  for (const Bad& b :
       {Bad{TEST_PLUGIN_NO_ABI, "not a plantsim plugin"}, Bad{TEST_PLUGIN_WRONG_ABI, "ABI version"},
        Bad{TEST_PLUGIN_CLASH, "clashes with the one from built-in"},
        Bad{TEST_PLUGIN_FACTORY_THROWS, "cannot be built"},
        Bad{TEST_PLUGIN_UNRESOLVED, "plantsim_test_symbol_nobody_defines"},
        Bad{TEST_PLUGIN_BAD_BOUNDS, "outside its bounds"},
        Bad{TEST_PLUGIN_PLANNER_FACTORY_THROWS, "no planner today"},
        Bad{"/nonexistent/plugin.so", "no such plugin file"}}) {
    try {
      plugins::load_plugin(b.file);
      ADD_FAILURE() << b.file << " was loaded";
    } catch (const plugins::PluginError& e) {
      EXPECT_NE(std::string(e.what()).find(b.file), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(b.says), std::string::npos) << e.what();
    }
  }
  // Nothing of a refused plugin was registered.
  EXPECT_FALSE(controller::local_controllers().find("test-factory-throws"));
  EXPECT_FALSE(controller::local_controllers().find("test-bad-bounds"));
  EXPECT_FALSE(planner::planners().find("test-planner-factory-throws"));
}

TEST(Plugins, APlannerIsChosenByNameWithItsOptionsAndCapabilities) {
  const plugins::LoadedPlugin& p = plugins::load_plugin(TEST_PLUGIN_GOOD);
  EXPECT_EQ(p.planners, (std::vector<std::string>{"test-straight", "test-planner-thrower"}));
  EXPECT_EQ(planner::planners().at("test-straight").origin, TEST_PLUGIN_GOOD);
  const auto names = planner::planner_names();
  EXPECT_NE(std::find(names.begin(), names.end(), "test-straight"), names.end());
  // Render asks capabilities, not names: the plugin's lists none, the built-ins theirs.
  EXPECT_FALSE(planner::planner_can("test-straight", planner::capability::kSearchesAMesh));
  EXPECT_TRUE(planner::planner_can("polyanya", planner::capability::kSearchesAMesh));
  EXPECT_TRUE(planner::planner_can("vg-round", planner::capability::kRoundMargin));
  EXPECT_TRUE(planner::planner_can("coverage", planner::capability::kCoverage));
  EXPECT_FALSE(planner::planner_can("no-such-planner", planner::capability::kCoverage));
  // Its option is bounded as a built-in family's: 7 m is refused, 2 m bends the line.
  planner::PlannerInput in;
  in.floor = {0, 0, 20, 20};
  in.options.set("detour_m", 7.0);
  EXPECT_THROW(planner::make_planner("test-straight", in), std::invalid_argument);
  in.options = {};
  in.options.set("detour_m", 2.0);
  const planner::PlanResult r = planner::make_planner("test-straight", in)->plan({1, 1}, {9, 1});
  ASSERT_EQ(r.path.size(), 3u);
  EXPECT_DOUBLE_EQ(r.path[1].y, 3.0);
  EXPECT_NEAR(r.length, 2 * std::hypot(4.0, 2.0), 1e-12);
}

// A plugin's dock detector drives the docking: sightings 4 cm to the side dock the robot 4 cm off
// (the pads still take it); one that throws ends the episode with plugin_error.
TEST(Plugins, ADockDetectorIsChosenByNameAndItsSightingsSteerTheDocking) {
  const plugins::LoadedPlugin& p = plugins::load_plugin(TEST_PLUGIN_GOOD);
  EXPECT_EQ(p.dock_detectors,
            (std::vector<std::string>{"test-offset-camera", "test-detector-thrower"}));
  const episode::EpisodeResult straight =
      run_with(R"({"docking": {"detector": "test-offset-camera"}})", 600);
  const episode::EpisodeResult shifted = run_with(
      R"({"docking": {"detector": "test-offset-camera"}, "test-offset-camera": {"offset_m": 0.04}})",
      600);
  ASSERT_TRUE(straight.error_measured && shifted.error_measured);
  EXPECT_LT(straight.position_error_m, 0.01);
  EXPECT_GT(shifted.position_error_m, 0.025);
  const episode::EpisodeResult thrown =
      run_with(R"({"docking": {"detector": "test-detector-thrower"}})", 600);
  ASSERT_TRUE(thrown.failure);
  EXPECT_EQ(thrown.failure->reason, robot::FailureReason::kPluginError);
  EXPECT_NE(thrown.failure->detail.find("the test detector is blinded"), std::string::npos);
}

TEST(Plugins, APlannerThatThrowsEndsItsEpisodeWithPluginError) {
  plugins::load_plugin(TEST_PLUGIN_GOOD);
  const worlds::World w =
      worlds::load_world(test::source_file("data/worlds/examples/corridor_crossing.json"));
  auto thrower = planner::make_planner("test-planner-thrower", planner::planner_input(w, true));
  const episode::EpisodeResult r = episode::run_episode(w, *thrower, episode::EpisodeConfig{});
  ASSERT_TRUE(r.failure);
  EXPECT_EQ(r.failure->reason, robot::FailureReason::kPluginError);
  EXPECT_NE(r.failure->detail.find("the test planner found no way"), std::string::npos);
  EXPECT_NE(r.failure->detail.find(TEST_PLUGIN_GOOD), std::string::npos);
}

TEST(Plugins, APartThatThrowsEndsItsEpisodeWithPluginError) {
  plugins::load_plugin(TEST_PLUGIN_GOOD);
  const episode::EpisodeResult r = run_with(
      R"({"local_controller": "test-thrower", "test-thrower": {"throw_after_steps": 40}})");
  ASSERT_TRUE(r.failure);
  EXPECT_EQ(r.failure->reason, robot::FailureReason::kPluginError);
  EXPECT_NE(r.failure->detail.find("the test controller gave up"), std::string::npos);
  EXPECT_NE(r.failure->detail.find(TEST_PLUGIN_GOOD), std::string::npos);
  EXPECT_GT(r.time_s, 1.0);  // after the 40 steps, not at the start
  // A factory that refuses this episode's map: the episode ends before it starts.
  const episode::EpisodeResult refused = run_with(R"({"local_controller": "test-map-refuser"})");
  ASSERT_TRUE(refused.failure);
  EXPECT_EQ(refused.failure->reason, robot::FailureReason::kPluginError);
  EXPECT_NE(refused.failure->detail.find("this map has boxes"), std::string::npos);
}

class PluginCli : public Cli {};

TEST_F(PluginCli, ABadPluginExitsTwoBeforeAnyWork) {
  const std::string world = test::source_file("data/worlds/examples/corridor_crossing.json");
  for (const char* bad : {TEST_PLUGIN_WRONG_ABI, TEST_PLUGIN_CLASH, "missing.so"}) {
    const Outcome o = run("run " + world + " --out out --plugin " + bad);
    EXPECT_EQ(o.exit_code, 2) << o.err;
    EXPECT_NE(o.err.find(bad), std::string::npos) << o.err;
    EXPECT_FALSE(fs::exists(dir_ / "out"));
  }
  const Outcome info = run(std::string("info --plugin ") + TEST_PLUGIN_GOOD);
  EXPECT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.out.find("test-thrower.throw_after_steps = 30  whole in [-1, 100000]"),
            std::string::npos)
      << info.out;
  EXPECT_NE(info.out.find("option detour_m = 0  real in [0, 5]"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("capabilities: searches-a-mesh"), std::string::npos) << info.out;
  // A planner no built-in or plugin has: exit 2 before work, the known ones listed.
  const Outcome unknown = run("run " + world + " --out out --planner straight");
  EXPECT_EQ(unknown.exit_code, 2) << unknown.err;
  EXPECT_NE(unknown.err.find("unknown planner \"straight\""), std::string::npos) << unknown.err;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(PluginCli, APluginsPlannerDrivesARun) {
  const std::string world = test::source_file("data/worlds/examples/corridor_crossing.json");
  const Outcome o = run("run " + world + " --out out --planner test-straight --plugin " +
                        std::string(TEST_PLUGIN_GOOD));
  EXPECT_NE(o.exit_code, 2) << o.err;
  const nlohmann::json summary =
      nlohmann::json::parse(std::ifstream(dir_ / "out" / "summary.json"));
  EXPECT_EQ(summary["planner"], "test-straight") << summary.dump();
}

TEST_F(PluginCli, ABatchGoesOnPastAPluginThatThrows) {
  const std::string world = test::source_file("data/worlds/examples/corridor_crossing.json");
  write("s.yaml", "name: plug\nplugins: [" + std::string(TEST_PLUGIN_GOOD) + "]\nworlds: [" +
                      world +
                      "]\nplanners: [vg]\nseeds: [1, 2]\nstarts: world\ncontrollers:\n"
                      "  thrower: {local_controller: test-thrower}\n  rpp: {}\n");
  const Outcome o = run("batch s.yaml --out b --quiet --no-figures", 300);
  EXPECT_EQ(o.exit_code, 0) << o.err;  // no gate: the batch ran every episode
  std::ifstream records(dir_ / "b" / "episodes.jsonl");
  int thrown = 0, docked = 0;
  for (std::string line; std::getline(records, line);) {
    const nlohmann::json j = nlohmann::json::parse(line);
    if (j["failure"].is_string() && j["failure"] == "plugin_error") ++thrown;
    if (j.value("docked", false)) ++docked;
  }
  EXPECT_EQ(thrown, 2);
  EXPECT_EQ(docked, 2);
}

}  // namespace
}  // namespace plantsim
