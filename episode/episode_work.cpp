// The episode's work bound (see the header).
#include "episode/episode_work.h"

#include <cmath>
#include <locale>
#include <sstream>
#include <stdexcept>
#include <string>

#include "episode/robot_limits.h"

namespace plantsim::episode {
namespace {

std::string shortest(double v) {
  std::ostringstream s;
  s.imbue(std::locale::classic());
  s << v;
  return s.str();
}

}  // namespace

void check_episode_work(const worlds::World& plant, const EpisodeConfig& config) {
  check_robot_limits(plant, config);
  const double steps = std::ceil(config.timeout_s / config.step.dt_s);
  const double movers = static_cast<double>(plant.moving.size()) + (plant.target ? 1.0 : 0.0);
  const double work = steps * movers;
  if (work <= kMaxEpisodeMoverSteps) return;
  const long long minutes = std::llround(work * 0.7e-6 / 60.0);
  throw std::invalid_argument(
      plant.source + " with timeout_s " + shortest(config.timeout_s) + ": an episode of " +
      std::to_string(static_cast<long long>(steps)) + " steps with " +
      std::to_string(static_cast<long long>(movers)) + " moving obstacles asks for about " +
      std::to_string(minutes) + " minutes of computing, more than one run accepts (" +
      std::to_string(static_cast<long long>(kMaxEpisodeMoverSteps)) +
      " mover-steps; docs/config.md): shorten timeout_s or use fewer movers");
}

}  // namespace plantsim::episode
