// The motors' bound on the travel speed parameters (see the header).
#include "episode/robot_limits.h"

#include <algorithm>
#include <stdexcept>

#include "episode/episode_config_json.h"
#include "util/c_number.h"

namespace plantsim::episode {

namespace {

[[noreturn]] void refuse(const worlds::World& plant, const std::string& path, double value,
                         const std::string& what) {
  throw std::invalid_argument(path + " " + what + " " + util::c_general(value) +
                              " m/s is above the robot's motor limit of " +
                              util::c_general(plant.robot.max_speed_mps) + " m/s (" + plant.source +
                              ": robot.max_speed_mps): the robot cannot drive it; set at most " +
                              util::c_general(plant.robot.max_speed_mps));
}

}  // namespace

std::vector<std::string> motor_bounded_parameters(const EpisodeConfig& config) {
  if (config.travel == "potential-field") return {"potential_field.max_speed_mps"};
  if (config.local_controller == "pure-pursuit") return {"tracking.max_linear_speed_mps"};
  if (config.local_controller == "mppi") return {"mppi.vx_max"};
  if (config.local_controller == "dwb") return {"dwb.max_vel_x"};
  return {};  // a plugin's: its context carries the limit (LocalControllerContext)
}

void check_robot_limits(const worlds::World& plant, const EpisodeConfig& config) {
  // A default is nobody's setting: on a robot slower than it, the drive's limit caps it (the
  // motors turn no faster, and MPPI and DWB sample within it), as before. What a user set is
  // refused: a speed the robot cannot drive would mislead every output that names it.
  static const EpisodeConfig defaults;
  for (const std::string& path : motor_bounded_parameters(config)) {
    const double v = number_value(config, path);
    if (v > plant.robot.max_speed_mps && v != number_value(defaults, path))
      refuse(plant, path, v, "=");
  }
}

void check_tuning_bound(const worlds::World& plant, const EpisodeConfig& config,
                        const std::string& path, double hi) {
  const std::vector<std::string> bounded = motor_bounded_parameters(config);
  if (std::find(bounded.begin(), bounded.end(), path) != bounded.end() &&
      hi > plant.robot.max_speed_mps)
    refuse(plant, path, hi, "tuned up to");
}

}  // namespace plantsim::episode
