// `plantsim nav2-import`: a Nav2 parameter file (controller_server with Regulated Pure Pursuit,
// docking_server of opennav_docking, the costmaps' robot_radius / footprint / inflation_radius)
// read into a plantsim episode config, with an account of every parameter: what it became,
// what has no counterpart and why, which plugins plantsim does not implement. docs/nav2.md
// holds the table.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace plantsim::app {

struct Nav2Parameter {
  std::string nav2;   ///< e.g. controller_server.FollowPath.desired_linear_vel
  std::string value;  ///< as written
  std::string
      plantsim;      ///< the config key (or "world file: robot.radius_m"); empty when not mapped
  std::string note;  ///< how it was converted, or why it has no counterpart
};

struct Nav2Import {
  nlohmann::ordered_json config = nlohmann::ordered_json::object();  ///< only the keys mapped
  std::vector<Nav2Parameter> mapped, world_fields, not_mapped;
  std::vector<std::string>
      plugins_not_implemented;  ///< "FollowPath: nav2_mppi_controller::MPPIController"
};

/// Throws worlds::WorldError naming the file and the parameter on a malformed file or a value
/// that is not a finite number where one is needed; the config is checked by plantsim's own
/// config parser before it is returned.
Nav2Import import_nav2_params(const std::string& path);

/// The account printed by the command: one line per parameter.
std::string nav2_report(const Nav2Import& import);

}  // namespace plantsim::app
