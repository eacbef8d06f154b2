// Episode metrics as JSON.
#include "episode/episode_json.h"

namespace plantsim::episode {

void add_episode_metrics(nlohmann::ordered_json& j, const EpisodeOutcome& r) {
  j["status"] = status_name(r);
  if (r.failure) {
    j["failure"] = std::string(to_string(r.failure->reason));
    j["failure_time_s"] = r.failure->time_s;
    j["failure_pose"] = {r.failure->pose.x, r.failure->pose.y, r.failure->pose.yaw};
    j["failure_detail"] = r.failure->detail;
  } else {
    j["failure"] = nullptr;
  }
  j["docked"] = r.docked;
  j["charging"] = r.charging;
  j["undocked"] = r.undocked;
  j["caught"] = r.caught;
  j["travel"] = r.travel;
  if (!r.steered_by.empty())
    j["steered_by"] = r.steered_by;  // an outside controller drove the travel
  j["local_minima"] = r.local_minima;
  j["wall_follows"] = r.wall_follows;
  j["position_error_m"] = r.position_error_m;
  j["heading_error_deg"] = r.heading_error_deg;
  j["error_measured"] = r.error_measured;  // false: a pursuit, or a run that never set off (errors
                                           // are 0, not measured)
  j["collisions"] = r.collisions;
  j["collisions_robot_moving"] = r.collisions_robot_moving;
  j["retries"] = r.retries;
  j["stops"] = r.stops;
  j["replans"] = r.replans;
  j["recoveries"] = r.recoveries;
  j["slips"] = r.slips;
  j["time_s"] = r.time_s;
  j["path_length_m"] = r.path_length_m;
  j["driven_length_m"] = r.driven_length_m;
  j["max_cross_track_m"] = r.max_cross_track_m;
  j["perception_mode"] = r.perception_mode;
  j["localization_error_max_m"] = r.localization_error_max_m;
  j["localization_status"] = r.localization_status;
  j["relocalizations"] = r.relocalizations;
  j["worst_moving_error_m"] = r.integrity.worst_moving_error_m;
  j["driven_off_estimate_s"] = r.integrity.driven_off_s;
  j["driven_off_estimate_m"] = r.integrity.driven_off_m;
  j["ok_while_off_s"] = r.integrity.ok_while_off_s;
  j["localization_not_ok_s"] = r.integrity.not_ok_s;
  j["unmapped_seen"] = r.unmapped_seen;
  // Navigation-benchmark metrics (NaN, written null, where not measured: no travel).
  j["min_clearance_m"] = r.min_clearance_m;
  j["mean_clearance_m"] = r.mean_clearance_m;
  j["near_obstacle_share"] = r.near_obstacle_share;
  j["rms_jerk_mps3"] = r.rms_jerk_mps3;
  j["rms_angular_accel_radps2"] = r.rms_angular_accel_radps2;
  j["controller_cycles"] = r.controller_cycles;
  j["controller_ms_median"] = r.controller_ms_median;  // wall time: kWallTimeFields
  j["controller_ms_p99"] = r.controller_ms_p99;
}

}  // namespace plantsim::episode
