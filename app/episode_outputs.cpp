// Serialising an episode's metrics and trajectory.
#include "app/episode_outputs.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <sstream>

namespace plantsim::app {

std::string summary_json(const sim::EpisodeResult& r, const std::string& world_name,
                         const std::string& command_line) {
  nlohmann::ordered_json j;
  j["world"] = world_name;
  j["planner"] = r.planner;
  j["status"] = r.status;
  j["docked"] = r.docked;
  j["position_error_m"] = r.position_error_m;
  j["heading_error_deg"] = r.heading_error_deg;
  j["collisions"] = r.collisions;
  j["retries"] = r.retries;
  j["stops"] = r.stops;
  j["replans"] = r.replans;
  j["time_s"] = r.time_s;
  j["path_length_m"] = r.path_length_m;
  j["driven_length_m"] = r.driven_length_m;
  j["max_cross_track_m"] = r.max_cross_track_m;
  j["command"] = command_line;
  auto plan = nlohmann::ordered_json::array();
  for (const auto& v : r.plan) plan.push_back({v.x, v.y});
  j["plan"] = plan;
  return j.dump(2) + "\n";
}

std::string trajectory_csv(const sim::EpisodeResult& r) {
  std::string out = "t_s,x_m,y_m,yaw_rad,est_x_m,est_y_m,est_yaw_rad,speed_mps,cross_track_m,phase\n";
  char line[256];
  for (const auto& s : r.trajectory) {
    std::snprintf(line, sizeof line, "%.4f,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f,%.4f,%.4f,%s\n", s.t_s,
                  s.truth.x, s.truth.y, s.truth.yaw, s.estimate.x, s.estimate.y, s.estimate.yaw,
                  s.speed_mps, s.cross_track_m, std::string(controller::to_string(s.phase)).c_str());
    out += line;
  }
  return out;
}

}  // namespace plantsim::app
