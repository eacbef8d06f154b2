// Nav2 parameters onto plantsim's: Regulated Pure Pursuit onto the pure pursuit and its speed
// regulation, opennav_docking onto the docking manoeuvre, the costmap's footprint onto the
// world's robot (named, since plantsim keeps the robot in the world file).
#include "app/nav2_import.h"

#include <cmath>
#include <functional>
#include <initializer_list>
#include <map>
#include <numbers>
#include <optional>
#include <set>

#include "episode/episode_config_json.h"
#include "worlds/decimal_number.h"
#include "worlds/world_error.h"
#include "worlds/yaml_input.h"

namespace plantsim::app {
namespace {

using json = nlohmann::ordered_json;

class Importer {
 public:
  explicit Importer(std::string file) : file_(std::move(file)) {}

  /// A ros__parameters block (or the node itself when written without it).
  static YAML::Node params(const YAML::Node& node) {
    if (node && node.IsMap() && node["ros__parameters"]) return node["ros__parameters"];
    return node;
  }

  // Decimal by plantsim's one rule (worlds/decimal_number.h): yaml-cpp's as<double>() took
  // `.inf`, and its integers read `010` as 8.
  double number(const YAML::Node& n, const std::string& key) const {
    if (const auto v = worlds::decimal_number(n)) return *v;
    throw worlds::WorldError(file_, key, "expected a finite decimal number");
  }
  bool flag(const YAML::Node& n, const std::string& key) const {
    try {
      return n.as<bool>();
    } catch (const YAML::Exception&) {
      throw worlds::WorldError(file_, key, "expected true or false");
    }
  }
  static std::string text(const YAML::Node& n) {
    if (n.IsScalar()) return n.Scalar();
    YAML::Emitter e;
    e << YAML::Flow << n;
    return e.c_str();
  }

  /// `key` of `block` (named `where`) into config `path` (a.b), converted by `convert`.
  void map(const YAML::Node& block, const std::string& where, const std::string& key,
           const std::string& path, const std::string& note = "",
           const std::function<double(double)>& convert = {}) {
    const YAML::Node n = block[key];
    if (!n) return;
    seen(where, key);
    const std::string name = where + "." + key;
    double v = number(n, name);
    if (convert) v = convert(v);
    const auto dot = path.find('.');
    if (dot == std::string::npos)
      out_.config[path] = v;
    else
      out_.config[path.substr(0, dot)][path.substr(dot + 1)] = v;
    out_.mapped.push_back({name, text(n), path, note});
  }
  void map_flag(const YAML::Node& block, const std::string& where, const std::string& key,
                const std::string& path, const std::string& note) {
    const YAML::Node n = block[key];
    if (!n) return;
    seen(where, key);
    const auto dot = path.find('.');
    out_.config[path.substr(0, dot)][path.substr(dot + 1)] = flag(n, where + "." + key);
    out_.mapped.push_back({where + "." + key, text(n), path, note});
  }
  void world_field(const YAML::Node& block, const std::string& where, const std::string& key,
                   const std::string& field, const std::string& note) {
    const YAML::Node n = block[key];
    if (!n) return;
    seen(where, key);
    out_.world_fields.push_back({where + "." + key, text(n), "world file: " + field, note});
  }
  void not_mapped(const YAML::Node& block, const std::string& where, const std::string& key,
                  const std::string& why) {
    const YAML::Node n = block[key];
    if (!n) return;
    seen(where, key);
    out_.not_mapped.push_back({where + "." + key, text(n), "", why});
  }
  /// Every key of `block` not yet accounted for: listed as not mapped with `why`.
  void rest(const YAML::Node& block, const std::string& where, const std::string& why) {
    if (!block || !block.IsMap()) return;
    for (const auto& kv : block) {
      const std::string key = kv.first.Scalar();
      if (done_.count(where + "." + key) || key == "plugin") continue;
      if (kv.second.IsMap()) {
        rest(kv.second, where + "." + key, why);
        continue;
      }
      out_.not_mapped.push_back({where + "." + key, text(kv.second), "", why});
      seen(where, key);
    }
  }
  Nav2Import& out() { return out_; }
  const std::string& file() const { return file_; }

 private:
  void seen(const std::string& where, const std::string& key) { done_.insert(where + "." + key); }
  std::string file_;
  Nav2Import out_;
  std::set<std::string> done_;
};

constexpr const char* kRpp =
    "nav2_regulated_pure_pursuit_controller::RegulatedPurePursuitController";

void regulated_pure_pursuit(Importer& im, const YAML::Node& c, const std::string& w) {
  // Without velocity-scaled lookahead RPP uses the fixed lookahead_dist: plantsim's band closes on
  // it.
  const bool scaled =
      !c["use_velocity_scaled_lookahead_dist"] ||
      im.flag(c["use_velocity_scaled_lookahead_dist"], w + ".use_velocity_scaled_lookahead_dist");
  // Today's RPP names the cruise speed max_linear_vel (earlier releases desired_linear_vel); the
  // newer wins when a file holds both.
  if (c["max_linear_vel"]) {
    im.map(c, w, "max_linear_vel", "tracking.max_linear_speed_mps");
    im.not_mapped(c, w, "desired_linear_vel", "superseded by max_linear_vel (its newer name)");
  } else {
    im.map(c, w, "desired_linear_vel", "tracking.max_linear_speed_mps",
           "the older name of max_linear_vel");
  }
  im.map(c, w, "max_angular_vel", "tracking.max_angular_speed_radps");
  if (scaled) {
    im.map(c, w, "lookahead_time", "tracking.lookahead_time_s");
    im.map(c, w, "min_lookahead_dist", "tracking.lookahead_min_m");
    im.map(c, w, "max_lookahead_dist", "tracking.lookahead_max_m");
    im.not_mapped(c, w, "lookahead_dist",
                  "velocity-scaled lookahead is on: the band min..max is used");
  } else {
    im.map(c, w, "lookahead_dist", "tracking.lookahead_min_m", "fixed lookahead: min = max");
    im.map(c, w, "lookahead_dist", "tracking.lookahead_max_m", "fixed lookahead: min = max");
    im.not_mapped(c, w, "lookahead_time", "velocity-scaled lookahead is off");
    im.not_mapped(c, w, "min_lookahead_dist", "velocity-scaled lookahead is off");
    im.not_mapped(c, w, "max_lookahead_dist", "velocity-scaled lookahead is off");
  }
  im.not_mapped(c, w, "use_velocity_scaled_lookahead_dist",
                "decides which lookahead keys are used (above)");
  im.map(c, w, "min_approach_linear_velocity", "tracking.min_approach_speed_mps");
  im.map(c, w, "approach_velocity_scaling_dist", "tracking.approach_slowdown_distance_m");
  const bool regulated = !c["use_regulated_linear_velocity_scaling"] ||
                         im.flag(c["use_regulated_linear_velocity_scaling"],
                                 w + ".use_regulated_linear_velocity_scaling");
  if (regulated)
    im.map(c, w, "regulated_linear_scaling_min_radius", "tracking.regulated_min_radius_m");
  else
    im.out().config["tracking"]["regulated_min_radius_m"] = 0.0;
  im.not_mapped(c, w, "use_regulated_linear_velocity_scaling",
                regulated ? "on: regulated_linear_scaling_min_radius is used"
                          : "off: tracking.regulated_min_radius_m set to 0");
  im.not_mapped(c, w, "regulated_linear_scaling_min_speed",
                "plantsim's curvature regulation has no speed floor (min_approach_linear_velocity "
                "bounds the approach)");
  const bool rotate = !c["use_rotate_to_heading"] ||
                      im.flag(c["use_rotate_to_heading"], w + ".use_rotate_to_heading");
  if (rotate)
    im.map(c, w, "rotate_to_heading_min_angle", "tracking.rotate_in_place_threshold_rad");
  else
    im.out().config["tracking"]["rotate_in_place_threshold_rad"] = std::numbers::pi;
  im.not_mapped(c, w, "use_rotate_to_heading",
                rotate ? "on: rotate_to_heading_min_angle is used"
                       : "off: the threshold is set to pi (never rotates in place)");
  im.map(c, w, "rotate_to_heading_angular_vel", "tracking.rotate_in_place_speed_radps");
  im.map(c, w, "max_angular_accel", "traction.max_angular_accel_radps2",
         "meaning changed: plantsim limits turn-rate growth only while it slows after a slip");
  im.map(c, w, "max_robot_pose_search_dist", "tracking.progress_window_m");
  for (const char* k : {"use_cost_regulated_linear_velocity_scaling", "cost_scaling_dist",
                        "cost_scaling_gain", "inflation_cost_scaling_factor"})
    im.not_mapped(
        c, w, k,
        "plantsim has no costmap costs: it slows with curvature, uncertainty and the arc check");
  for (const char* k : {"use_collision_detection", "max_allowed_time_to_collision_up_to_carrot"})
    im.not_mapped(
        c, w, k,
        "plantsim's arc check is always on (docking.check_extra_m, docking.max_decel_mps2)");
  im.not_mapped(
      c, w, "allow_reversing",
      "plantsim's path following drives forwards (it reverses only to back off in docking)");
  im.not_mapped(c, w, "transform_tolerance", "no transforms in the simulation");
  im.rest(c, w, "no counterpart in plantsim's pure pursuit");
}

constexpr const char* kMppi = "nav2_mppi_controller::MPPIController";
constexpr const char* kDwb = "dwb_core::DWBLocalPlanner";

/// `keys` of `block` (named `where`) into `section`.<the same key>.
void map_same(Importer& im, const YAML::Node& block, const std::string& where,
              const std::string& section, std::initializer_list<const char*> keys) {
  for (const char* key : keys) im.map(block, where, key, section + "." + key);
}

/// One critic's block: each {Nav2 key, plantsim key in `section`}.
void map_critic(Importer& im, const YAML::Node& c, const std::string& w, const char* critic,
                const std::string& section,
                std::initializer_list<std::pair<const char*, const char*>> keys) {
  // ROS 2 files write a critic's parameters as a block or flat ("BaseObstacle.scale: 0.02", as
  // nav2_bringup does).
  const YAML::Node block = c[critic];
  for (const auto& [nav2, own] : keys) {
    if (block && block.IsMap()) im.map(block, w + "." + critic, nav2, section + "." + own);
    im.map(c, w, std::string(critic) + "." + nav2, section + "." + own);
  }
}

/// nav2_mppi_controller's parameters by today's names (docs/controllers.md).
void mppi_controller(Importer& im, const YAML::Node& c, const std::string& w) {
  im.out().config["local_controller"] = "mppi";
  map_same(
      im, c, w, "mppi",
      {"batch_size", "time_steps", "model_dt", "iteration_count", "temperature", "gamma", "vx_std",
       "wz_std", "vx_max", "vx_min", "wz_max", "ax_max", "ax_min", "az_max", "prune_distance"});
  map_critic(im, c, w, "ConstraintCritic", "mppi", {{"cost_weight", "constraint_weight"}});
  map_critic(im, c, w, "ObstaclesCritic", "mppi",
             {{"critical_weight", "critical_weight"},
              {"repulsion_weight", "repulsion_weight"},
              {"collision_cost", "collision_cost"},
              {"collision_margin_distance", "collision_margin_distance"},
              {"inflation_radius", "inflation_radius"},
              {"near_goal_distance", "obstacles_near_goal_distance"}});
  map_critic(
      im, c, w, "GoalCritic", "mppi",
      {{"cost_weight", "goal_weight"}, {"threshold_to_consider", "goal_threshold_to_consider"}});
  map_critic(im, c, w, "GoalAngleCritic", "mppi",
             {{"cost_weight", "goal_angle_weight"},
              {"threshold_to_consider", "goal_angle_threshold_to_consider"}});
  map_critic(im, c, w, "PathAlignCritic", "mppi",
             {{"cost_weight", "path_align_weight"},
              {"trajectory_point_step", "path_align_trajectory_point_step"},
              {"threshold_to_consider", "path_align_threshold_to_consider"},
              {"max_path_occupancy_ratio", "max_path_occupancy_ratio"}});
  map_critic(im, c, w, "PathFollowCritic", "mppi",
             {{"cost_weight", "path_follow_weight"},
              {"offset_from_furthest", "path_follow_offset_from_furthest"},
              {"threshold_to_consider", "path_follow_threshold_to_consider"}});
  map_critic(im, c, w, "PathAngleCritic", "mppi",
             {{"cost_weight", "path_angle_weight"},
              {"offset_from_furthest", "path_angle_offset_from_furthest"},
              {"threshold_to_consider", "path_angle_threshold_to_consider"},
              {"max_angle_to_furthest", "max_angle_to_furthest"}});
  map_critic(im, c, w, "PreferForwardCritic", "mppi",
             {{"cost_weight", "prefer_forward_weight"},
              {"threshold_to_consider", "prefer_forward_threshold_to_consider"}});
  im.not_mapped(c, w, "critics",
                "plantsim's MPPI always runs its eight critics (constraint, obstacles on its "
                "local distance field in place of CostCritic's costmap, goal, goal angle, path "
                "align, path follow, path angle, prefer forward): docs/controllers.md");
  im.rest(c, w, "a parameter of " + std::string(kMppi) + " plantsim's MPPI does not have");
}

/// nav2_dwb_controller's parameters by today's names (docs/controllers.md).
void dwb_controller(Importer& im, const YAML::Node& c, const std::string& w) {
  im.out().config["local_controller"] = "dwb";
  map_same(im, c, w, "dwb",
           {"min_vel_x", "max_vel_x", "max_vel_theta", "min_speed_theta", "acc_lim_x",
            "decel_lim_x", "acc_lim_theta", "decel_lim_theta", "vx_samples", "vtheta_samples",
            "sim_time", "xy_goal_tolerance", "forward_prune_distance"});
  map_critic(im, c, w, "BaseObstacle", "dwb", {{"scale", "base_obstacle_scale"}});
  map_critic(im, c, w, "PathAlign", "dwb",
             {{"scale", "path_align_scale"}, {"forward_point_distance", "forward_point_distance"}});
  map_critic(im, c, w, "GoalAlign", "dwb", {{"scale", "goal_align_scale"}});
  map_critic(im, c, w, "PathDist", "dwb", {{"scale", "path_dist_scale"}});
  map_critic(im, c, w, "GoalDist", "dwb", {{"scale", "goal_dist_scale"}});
  map_critic(im, c, w, "RotateToGoal", "dwb",
             {{"scale", "rotate_to_goal_scale"}, {"slowing_factor", "slowing_factor"}});
  map_critic(im, c, w, "Oscillation", "dwb",
             {{"oscillation_reset_dist", "oscillation_reset_dist"},
              {"oscillation_reset_angle", "oscillation_reset_angle"},
              {"x_only_threshold", "x_only_threshold"}});
  im.not_mapped(c, w, "critics",
                "plantsim's DWB always runs its seven critics (BaseObstacle, Oscillation, "
                "RotateToGoal, PathAlign, GoalAlign, PathDist, GoalDist): docs/controllers.md");
  im.rest(c, w, "a parameter of " + std::string(kDwb) + " plantsim's DWB does not have");
}

void controller_server(Importer& im, const YAML::Node& root) {
  const YAML::Node s = Importer::params(root["controller_server"]);
  if (!s) return;
  const std::string w = "controller_server";
  im.map(s, w, "controller_frequency", "step.control_period_steps",
         "plantsim steps physics at 60 Hz: every round(60 / f) steps",
         [](double f) { return f > 0 ? std::max(1.0, std::round(60.0 / f)) : 0.0; });
  std::vector<std::string> ids = {"FollowPath"};
  if (s["controller_plugins"]) {
    ids.clear();
    for (const auto& id : s["controller_plugins"]) ids.push_back(id.Scalar());
  }
  im.not_mapped(s, w, "controller_plugins", "lists the controller ids read below");
  for (const std::string& id : ids) {
    const YAML::Node c = s[id];
    if (!c) continue;
    const std::string plugin = c["plugin"] ? c["plugin"].Scalar() : "";
    if (plugin == kRpp)
      regulated_pure_pursuit(im, c, w + "." + id);
    else if (plugin == kMppi)
      mppi_controller(im, c, w + "." + id);
    else if (plugin == kDwb)
      dwb_controller(im, c, w + "." + id);
    else {
      im.out().plugins_not_implemented.push_back(id + ": " + plugin);
      im.rest(c, w + "." + id,
              "a parameter of " + plugin +
                  ", which plantsim does not implement (its pure pursuit drives)");
    }
  }
  for (const char* checker : {"general_goal_checker", "goal_checker"}) {
    const YAML::Node g = s[checker];
    if (!g) continue;
    const std::string gw = w + "." + checker;
    // The goal checker serves whichever controller drives: its tolerance is that one's.
    const nlohmann::ordered_json& config = im.out().config;
    const std::string local =
        config.contains("local_controller") ? config["local_controller"].get<std::string>() : "";
    im.map(g, gw, "xy_goal_tolerance",
           local.empty() ? "tracking.goal_tolerance_m" : local + ".goal_tolerance_m",
           "the tolerance at the staging pose, where docking begins");
    im.not_mapped(g, gw, "yaw_goal_tolerance",
                  "plantsim aligns at the staging pose to docking.align_tolerance_rad");
    im.not_mapped(g, gw, "stateful", "plantsim's goal check is stateless");
  }
  if (const YAML::Node p = s["progress_checker"]) {
    const std::string pw = w + ".progress_checker";
    im.map(p, pw, "movement_time_allowance", "docking.stuck_timeout_s",
           "the time without progress before a failure (stuck)");
    im.not_mapped(p, pw, "required_movement_radius",
                  "plantsim measures progress along the plan, not a radius");
  }
  im.rest(s, w, "a controller_server setting plantsim does not model");
}

void docking_server(Importer& im, const YAML::Node& root) {
  const YAML::Node s = Importer::params(root["docking_server"]);
  if (!s) return;
  const std::string w = "docking_server";
  im.map(s, w, "dock_approach_timeout", "docking.approach_timeout_s");
  im.map(s, w, "max_retries", "docking.max_retries");
  im.map(s, w, "wait_charge_timeout", "docking.press_timeout_s",
         "how long it presses on the pads for the charger's signal");
  if (s["dock_backwards"] && im.flag(s["dock_backwards"], w + ".dock_backwards"))
    im.not_mapped(s, w, "dock_backwards",
                  "true is not supported: plantsim docks facing the charger");
  else
    im.not_mapped(s, w, "dock_backwards", "false: plantsim docks facing the charger, as here");
  for (const char* k :
       {"base_frame", "fixed_frame", "controller_frequency", "initial_perception_timeout",
        "undock_linear_tolerance", "undock_angular_tolerance", "dock_prestaging_tolerance",
        "dock_plugins", "docks", "dock_database"})
    im.not_mapped(s, w, k,
                  "no counterpart (frames, timing and undock tolerances are fixed in plantsim)");
  if (const YAML::Node c = s["controller"]) {
    const std::string cw = w + ".controller";
    im.map(c, cw, "v_linear_max", "docking.approach_speed_mps", "the approach speed onto the pads");
    im.map(c, cw, "v_angular_max", "docking.align_speed_radps");
    im.rest(c, cw,
            "plantsim's approach is pure pursuit along the dock axis, not the graceful "
            "controller's law");
  }
  std::vector<std::string> docks;
  if (s["dock_plugins"])
    for (const auto& id : s["dock_plugins"]) docks.push_back(id.Scalar());
  for (const std::string& id : docks) {
    const YAML::Node d = s[id];
    if (!d) continue;
    const std::string dw = w + "." + id;
    im.map(d, dw, "docking_threshold", "tolerance.position_m",
           "docked when the pose is within this of the docked pose");
    im.world_field(d, dw, "staging_x_offset", "charger.staging_distance_m",
                   "its magnitude: the staging pose this far in front of the dock");
    im.map_flag(d, dw, "use_external_detection_pose", "detection.enabled",
                "the charger detector on or off");
    im.rest(d, dw, "no counterpart in plantsim's charger model");
  }
  im.rest(s, w, "a docking_server setting plantsim does not model");
}

// The velocity smoother's caps bound what reaches the wheels: its forward speed and
// acceleration are the robot's own limits in plantsim (the world file), its turn rate caps the
// controller's.
void velocity_smoother(Importer& im, const YAML::Node& root) {
  const YAML::Node s = Importer::params(root["velocity_smoother"]);
  if (!s) return;
  const std::string w = "velocity_smoother";
  auto component = [&](const char* key, std::size_t i) -> std::optional<double> {
    const YAML::Node v = s[key];
    if (!v || !v.IsSequence() || v.size() != 3) return std::nullopt;
    return im.number(v[i], w + "." + key + "[" + std::to_string(i) + "]");
  };
  if (const auto wz = component("max_velocity", 2)) {
    if (!im.out().config.contains("tracking") ||
        !im.out().config["tracking"].contains("max_angular_speed_radps") ||
        *wz < im.out().config["tracking"]["max_angular_speed_radps"].get<double>())
      im.out().config["tracking"]["max_angular_speed_radps"] = *wz;
  }
  im.world_field(
      s, w, "max_velocity", "robot.max_speed_mps",
      "its x: the robot's top speed (plantsim keeps it in the world file); its theta "
      "caps tracking.max_angular_speed_radps (the lower of it and RPP's max_angular_vel)");
  im.world_field(
      s, w, "max_accel", "robot.max_accel_mps2",
      "its x: the robot's acceleration (world file); braking is never limited in plantsim");
  im.rest(s, w,
          "a velocity_smoother setting plantsim does not model (it commands the wheels directly)");
}

// Sections plantsim reads nothing from, each parameter listed with why.
void unmodelled_sections(Importer& im, const YAML::Node& root) {
  static const std::map<std::string, std::string> why = {
      {"amcl", "plantsim localises with its own EKF against its map (ekf.* in docs/config.md)"},
      {"planner_server", "plantsim plans with its own planners (--planner; vg by default)"},
      {"collision_monitor", "plantsim's arc check and bumper guard stop the robot (docking.*)"},
      {"behavior_server", "plantsim's recoveries are its back-off, replans and settling"},
      {"bt_navigator", "plantsim's travel and docking sequence is fixed (no behaviour tree)"},
      {"smoother_server", "plantsim follows its planner's path as planned"},
      {"waypoint_follower", "an episode drives to one charger"},
      {"map_server", "worlds load maps with plantsim run WORLD.yaml (docs/world_format.md)"}};
  const std::set<std::string> read = {"controller_server", "docking_server", "velocity_smoother",
                                      "local_costmap", "global_costmap"};
  for (const auto& kv : root) {
    const std::string name = kv.first.Scalar();
    if (read.count(name)) continue;
    const auto it = why.find(name);
    im.rest(Importer::params(kv.second), name,
            it != why.end() ? it->second : "a node plantsim does not model");
  }
}

void costmaps(Importer& im, const YAML::Node& root) {
  for (const char* name : {"local_costmap", "global_costmap"}) {
    YAML::Node node = root[name];
    if (node && node[name]) node = node[name];  // local_costmap: local_costmap: ros__parameters
    const YAML::Node s = Importer::params(node);
    if (!s) continue;
    const std::string w = std::string(name);
    im.world_field(s, w, "robot_radius", "robot.radius_m",
                   "plantsim keeps the robot in the world file");
    im.world_field(
        s, w, "footprint", "robot.length_m / robot.width_m",
        "a rectangle's length and width (plantsim's footprints are disks or rectangles)");
    if (const YAML::Node inflation = s["inflation_layer"])
      im.world_field(
          inflation, w + ".inflation_layer", "inflation_radius", "inflation_margin_m",
          "minus the robot radius: the clearance plantsim plans with beyond the footprint");
  }
}

}  // namespace

Nav2Import import_nav2_params(const std::string& path) {
  const YAML::Node root = worlds::load_yaml_input(path);
  if (!root.IsMap())
    throw worlds::WorldError(path, "", "expected a Nav2 parameter file (a mapping of node names)");
  Importer im(path);
  if (!root["controller_server"] && !root["docking_server"] && !root["local_costmap"] &&
      !root["global_costmap"])
    throw worlds::WorldError(
        path, "", "no controller_server, docking_server, local_costmap or global_costmap section");
  try {
    controller_server(im, root);
    docking_server(im, root);
    velocity_smoother(im, root);
    costmaps(im, root);
    unmodelled_sections(im, root);
  } catch (const YAML::Exception& e) {
    throw worlds::WorldError(path, "", std::string("unexpected structure: ") + e.what());
  }
  Nav2Import out = im.out();
  // Whole-number parameters written as whole numbers (mapped values arrive as reals).
  for (auto& [section, keys] : out.config.items()) {
    if (!keys.is_object()) continue;
    for (auto& [key, value] : keys.items())
      if (value.is_number_float() && episode::number_parameter(section + "." + key).whole)
        value = static_cast<long long>(value.get<double>());
  }
  episode::parse_episode_config(out.config.dump(),
                                path + " (as a plantsim config)");  // throws naming the field
  return out;
}

std::string nav2_report(const Nav2Import& im) {
  std::string s;
  auto line = [&s](const Nav2Parameter& p, const std::string& arrow) {
    s += "  " + p.nav2 + " = " + p.value + arrow + (p.note.empty() ? "" : "  (" + p.note + ")") +
         "\n";
  };
  s += "mapped (" + std::to_string(im.mapped.size()) + "):\n";
  for (const auto& p : im.mapped) line(p, " -> " + p.plantsim);
  s += "world file fields (" + std::to_string(im.world_fields.size()) +
       "; plantsim keeps these in the world, not the config):\n";
  for (const auto& p : im.world_fields) line(p, " -> " + p.plantsim);
  s += "not mapped (" + std::to_string(im.not_mapped.size()) + "):\n";
  for (const auto& p : im.not_mapped) line(p, "");
  for (const auto& p : im.plugins_not_implemented) s += "plugin not implemented: " + p + "\n";
  return s;
}

}  // namespace plantsim::app
