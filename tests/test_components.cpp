// Registered components: the registries' rules (names, clashes), components chosen and
// configured by name in an episode configuration, their parameters as rows that vary and tune
// reach, and the built-in local controllers behind the interface docking where pure pursuit does.
#include <gtest/gtest.h>

#include "controller/local_controller_registry.h"
#include "episode/episode_config_json.h"
#include "episode/run_episode.h"
#include "planner/registry.h"
#include "robot/dock_detector.h"
#include "robot/estimator_registry.h"
#include "robot/travel_registry.h"
#include "test_paths.h"
#include "worlds/world_error.h"
#include "worlds/world_loader.h"

namespace plantsim {
namespace {

struct Entry : util::ComponentInfo {
  std::function<int()> make;
};

TEST(Registry, RefusesNamesAConfigurationCannotSpellAndNamesTakenTwice) {
  util::ComponentRegistry<Entry> r("widget");
  Entry e;
  e.name = "good-name_2";
  e.make = [] { return 1; };
  r.add(e, "built-in");
  EXPECT_EQ(r.at("good-name_2").origin, "built-in");
  try {
    r.add(e, "/x/plugin.so");
    FAIL() << "a clash was accepted";
  } catch (const util::RegistryError& err) {
    EXPECT_NE(std::string(err.what()).find("/x/plugin.so"), std::string::npos) << err.what();
    EXPECT_NE(std::string(err.what()).find("built-in"), std::string::npos) << err.what();
  }
  for (const char* bad : {"", "Upper", "9lives", "sp ace", "dot.ted", "a/b"}) {
    e.name = bad;
    EXPECT_THROW(r.add(e, "built-in"), util::RegistryError) << bad;
  }
  e.name = "no-factory";
  e.make = nullptr;
  EXPECT_THROW(r.add(e, "built-in"), util::RegistryError);
  try {
    r.at("nope");
    FAIL();
  } catch (const util::RegistryError& err) {
    EXPECT_NE(std::string(err.what()).find("good-name_2"), std::string::npos) << err.what();
  }
}

TEST(Components, BuiltInsAreRegisteredWithTheirParameters) {
  const auto& lc = controller::local_controllers();
  EXPECT_EQ(lc.names(), (std::vector<std::string>{"pure-pursuit", "mppi", "dwb"}));
  EXPECT_TRUE(lc.at("mppi").can("samples-trajectories"));
  EXPECT_FALSE(lc.at("pure-pursuit").can("samples-trajectories"));
  EXPECT_EQ(robot::estimators().at("ekf").origin, "built-in");
  EXPECT_TRUE(robot::estimators().find("particles"));
  // Every parameter a component declares is a number parameter vary and tune can reach.
  for (const auto* e : lc.entries())
    for (const util::ParamSpec& s : e->params)
      EXPECT_NO_THROW(episode::number_parameter(s.path())) << s.path();
  EXPECT_EQ(episode::number_parameter("mppi.temperature").default_value, 0.3);
  EXPECT_TRUE(episode::number_parameter("dwb.vx_samples").whole);
  // Travel modes and dock detectors: asked by capability, never by name.
  EXPECT_EQ(robot::travel_modes().names(), (std::vector<std::string>{"path", "potential-field"}));
  EXPECT_TRUE(robot::travel_modes().at("path").can(robot::travel_capability::kNeedsAPlan));
  EXPECT_FALSE(
      robot::travel_modes().at("potential-field").can(robot::travel_capability::kNeedsAPlan));
  EXPECT_EQ(robot::dock_detectors().names(), (std::vector<std::string>{"camera", "none"}));
}

TEST(Components, TravelAndDockDetectorChosenByNameAndWrittenBack) {
  const episode::EpisodeConfig c = episode::parse_episode_config(
      R"({"travel": "potential-field", "docking": {"detector": "none"}})", "c.json");
  EXPECT_EQ(c.travel, "potential-field");
  EXPECT_EQ(c.perception.dock_detector, "none");
  const episode::EpisodeConfig again = episode::parse_episode_config(episode::config_json(c), "w");
  EXPECT_EQ(again.travel, "potential-field");
  EXPECT_EQ(again.perception.dock_detector, "none");
  for (const char* bad : {R"({"travel": "teleport"})", R"({"docking": {"detector": "radar"}})"})
    EXPECT_THROW(episode::parse_episode_config(bad, "bad.json"), worlds::WorldError) << bad;
}

// Without a sighting the docking goes on the map's charger: where the map is right it docks as
// well; where the map's charger is 6 cm off, the camera's sightings correct it and none cannot.
TEST(Components, TheDockDetectorIsWhatCorrectsAMisplacedCharger) {
  worlds::World w =
      worlds::load_world(test::source_file("data/worlds/examples/corridor_crossing.json"));
  w.moving.clear();
  auto run = [&](const worlds::World& plant, const char* detector) {
    auto planner = planner::make_planner("vg", planner::planner_input(plant, true));
    episode::EpisodeConfig c = episode::parse_episode_config(
        std::string(R"({"docking": {"detector": ")") + detector + "\"}}", "c.json");
    return episode::run_episode(plant, *planner, c);
  };
  const episode::EpisodeResult exact = run(w, "none");
  EXPECT_TRUE(exact.docked) << episode::status_name(exact);
  worlds::World shifted = w;
  shifted.charger_map_offset = {0.0, 0.06, 0.0};  // the map's charger 6 cm beside the real one
  const episode::EpisodeResult camera = run(shifted, "camera");
  const episode::EpisodeResult blind = run(shifted, "none");
  EXPECT_TRUE(camera.docked) << episode::status_name(camera);
  EXPECT_LT(camera.position_error_m, 0.02);
  EXPECT_FALSE(blind.docked && blind.position_error_m < 0.02)
      << "docked " << blind.position_error_m << " m off without a sighting";
}

TEST(Components, ChosenAndConfiguredByNameWithTheirBoundsChecked) {
  const episode::EpisodeConfig c = episode::parse_episode_config(
      R"({"local_controller": "mppi", "mppi": {"temperature": 0.5, "batch_size": 800},
          "localization": {"estimator": "particles"}})",
      "c.json");
  EXPECT_EQ(c.local_controller, "mppi");
  EXPECT_EQ(c.perception.estimator, "particles");
  const util::ParamValues v =
      episode::component_values(c, controller::local_controllers().at("mppi").params);
  EXPECT_EQ(v.real("mppi.temperature"), 0.5);
  EXPECT_EQ(v.whole("mppi.batch_size"), 800);
  EXPECT_EQ(v.real("mppi.gamma"), 0.015);  // its default: not set
  // Written out and read back, the choice and the values survive.
  const episode::EpisodeConfig again = episode::parse_episode_config(episode::config_json(c), "w");
  EXPECT_EQ(again.local_controller, "mppi");
  EXPECT_EQ(episode::component_values(again, controller::local_controllers().at("mppi").params)
                .real("mppi.temperature"),
            0.5);
  struct Bad {
    const char* text;
    const char* field;
  };
  for (const Bad& b : {Bad{R"({"local_controller": "stanley"})", "local_controller"},
                       Bad{R"({"local_controller": 3})", "local_controller"},
                       Bad{R"({"localization": {"estimator": "amcl"}})", "localization.estimator"},
                       Bad{R"({"mppi": {"batch_size": 0}})", "mppi.batch_size"},
                       Bad{R"({"dwb": {"sim_time": -1}})", "dwb.sim_time"},
                       Bad{R"({"mppi": {"temprature": 1}})", "mppi.temprature"}}) {
    try {
      episode::parse_episode_config(b.text, "bad.json");
      ADD_FAILURE() << b.text << " was accepted";
    } catch (const worlds::WorldError& e) {
      EXPECT_NE(std::string(e.what()).find(b.field), std::string::npos) << e.what();
    }
  }
}

// The sampling controllers drive the whole docking: travel to the staging pose on their own
// commands, then the docking manoeuvre. Real outcomes: docked, millimetres, no contact.
class SamplingControllers : public ::testing::TestWithParam<const char*> {};

TEST_P(SamplingControllers, DockWithoutContact) {
  const worlds::World w =
      worlds::load_world(test::source_file("data/worlds/examples/corridor_crossing.json"));
  episode::EpisodeConfig c = episode::parse_episode_config(
      std::string(R"({"local_controller": ")") + GetParam() + "\"}", "c.json");
  // Under the sanitizers a quarter of MPPI's samples (the same critics, a noisier optimum).
  if (!test::full_size()) c.component_params.emplace_back("mppi.batch_size", 500);
  c.timeout_s = 200;
  auto planner = planner::make_planner("vg", planner::planner_input(w, true));
  const episode::EpisodeResult r = episode::run_episode(w, *planner, c);
  EXPECT_TRUE(r.docked) << episode::status_name(r);
  EXPECT_EQ(r.collisions, 0);
  EXPECT_LE(r.position_error_m, 0.01);
  // It drove on its own commands: not pure pursuit's trajectory.
  episode::EpisodeConfig rpp;
  rpp.timeout_s = 200;
  const episode::EpisodeResult base = episode::run_episode(w, *planner, rpp);
  EXPECT_NE(r.time_s, base.time_s);
  // What it weighed, for the replay: about once a second while it drove, a few samples and its
  // choice, starting where the robot was; pure pursuit samples nothing.
  EXPECT_TRUE(base.controller_sketches.empty());
  ASSERT_GE(r.controller_sketches.size(), 5u);
  EXPECT_LT(r.controller_sketches.front().t_s, 2.0);
  int chosen = 0;
  for (std::size_t k = 0; k < r.controller_sketches.size(); ++k) {
    const auto& at = r.controller_sketches[k];
    if (k > 0) {
      EXPECT_GE(at.t_s - r.controller_sketches[k - 1].t_s, 1.0 - 1e-9);
    }
    EXPECT_EQ(at.sketch.sampled.size(), 8u) << at.t_s;
    for (const auto& sample : at.sketch.sampled) {
      EXPECT_GE(sample.size(), 2u);
      EXPECT_LE(sample.size(), 15u);
    }
    if (at.sketch.chosen.empty()) continue;  // DWB found no valid trajectory and stopped
    ++chosen;
    EXPECT_LE(at.sketch.chosen.size(), 15u);
    // The choice starts at the robot (its estimate, which holds within centimetres here).
    const auto near = std::min_element(
        r.trajectory.begin(), r.trajectory.end(), [&](const auto& a, const auto& b) {
          return std::fabs(a.t_s - at.t_s) < std::fabs(b.t_s - at.t_s);
        });
    EXPECT_LT(geom::norm(at.sketch.chosen.front() - near->truth.position()), 0.1) << at.t_s;
  }
  EXPECT_GE(chosen, static_cast<int>(0.9 * static_cast<double>(r.controller_sketches.size())));
}

INSTANTIATE_TEST_SUITE_P(Nav2, SamplingControllers, ::testing::Values("mppi", "dwb"));

// Issue 87: DWB stood still 0.3 m short of the ring's first corner (its plan turns at the
// inflated margin; the goal beyond pulled every arc across the corner until none was valid)
// and, on coal_mine_roadways, touched a roadway's corner the same way. Seed 1, sensors mode.
TEST(Nav2Dwb, DocksRoundTheCableTunnelRingsSharpCorners) {
  const worlds::World w =
      worlds::load_world(test::source_file("data/worlds/plants/cable_tunnel_ring.json"));
  const episode::EpisodeConfig c =
      episode::parse_episode_config(R"({"local_controller": "dwb"})", "c.json");
  auto planner = planner::make_planner("vg", planner::planner_input(w, true));
  const episode::EpisodeResult r = episode::run_episode(w, *planner, c);
  EXPECT_TRUE(r.docked) << episode::status_name(r);
  EXPECT_EQ(r.collisions, 0);
  EXPECT_LT(r.time_s, 150.0);
}

}  // namespace
}  // namespace plantsim
