// A reference episode's trajectory against a hash checked into the repository: any change that
// moves the robot by one bit on this episode, in any commit, fails here until the hash is
// updated on purpose (with the reason in the commit). Two runs in one process agreeing
// (test_perception's Determinism tests) cannot see drift across commits; this can.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "episode/episode_config.h"
#include "episode/episode_result.h"
#include "episode/run_episode.h"
#include "planner/planner.h"
#include "planner/registry.h"
#include "tests/test_paths.h"
#include "worlds/world_loader.h"

namespace plantsim::sim {
using namespace plantsim::episode;  // the episode's config and result
using episode::run_episode;
namespace {

// FNV-1a over the bytes of every sample's time, true pose and estimated pose.
std::uint64_t trajectory_hash(const EpisodeResult& e) {
  std::uint64_t h = 1469598103934665603ULL;
  auto mix = [&](double v) {
    unsigned char bytes[sizeof v];
    std::memcpy(bytes, &v, sizeof v);
    for (unsigned char b : bytes) h = (h ^ b) * 1099511628211ULL;
  };
  for (const TrajectorySample& s : e.trajectory)
    for (double v :
         {s.t_s, s.truth.x, s.truth.y, s.truth.yaw, s.estimate.x, s.estimate.y, s.estimate.yaw})
      mix(v);
  return h;
}

TEST(Determinism, TheReferenceEpisodeMatchesItsCheckedInHash) {
  std::ifstream in(test::source_file("tests/fixtures/determinism_hash.json"));
  ASSERT_TRUE(in) << "tests/fixtures/determinism_hash.json is missing";
  const nlohmann::json reference = nlohmann::json::parse(in);
  const worlds::World w =
      worlds::load_world(test::source_file(reference.at("world").get<std::string>()));
  EpisodeConfig c;
  c.seed = reference.at("seed").get<std::uint64_t>();
  auto planner = planner::make_planner("vg", planner::planner_input(w, true));
  const EpisodeResult e = run_episode(w, *planner, c);
  std::ostringstream got;
  got << std::hex << trajectory_hash(e);
  EXPECT_EQ(got.str(), reference.at("trajectory_fnv1a64").get<std::string>())
      << "the reference episode's trajectory changed (" << e.trajectory.size()
      << " samples, status " << episode::status_name(e)
      << "). If an algorithm changed on purpose, set trajectory_fnv1a64 in "
         "tests/fixtures/determinism_hash.json to "
      << got.str() << " and say why in the commit.";
}

}  // namespace
}  // namespace plantsim::sim
