// The episode loop: sense, estimate, decide, actuate, step, log.
#include "sim/episode.h"

#include <algorithm>
#include <cmath>

#include "robot/travel.h"
#include "sim/episode_metrics.h"
#include "sim/failure_watch.h"

namespace plantsim::sim {

using robot::ActorState;
using robot::Decision;
using robot::Failure;
using robot::FailureReason;
using robot::GiveUp;
using robot::LocalizationHealth;
using robot::Perceiver;
using robot::Perception;
using robot::PerceptionMode;
using robot::PerceptionParams;
using robot::SensorReadings;
using robot::Travel;
using robot::TravelCounts;
using robot::TravelSettings;

namespace {

SensorParams sensor_params(const EpisodeConfig& c) {
  SensorParams s;
  s.oracle = c.perception.mode == PerceptionMode::kOracle;
  s.lidar = c.lidar;
  s.imu = c.imu;
  s.detection = c.detection;
  s.odometry = c.odometry;
  s.oracle_fix = c.localization;
  s.beacon = c.beacon;
  s.pads.lateral_tolerance_m = c.tolerance.position_m;
  s.pads.heading_tolerance_rad = c.tolerance.heading_rad;
  s.pads.dwell_s = c.tolerance.dwell_s;
  s.pads.min_press_m = c.tolerance.min_press_m;
  return s;
}

}  // namespace

std::string_view to_string(TravelMode m) {
  return m == TravelMode::kPath ? "path" : "potential-field";
}

EpisodeResult run_episode(const worlds::World& world, planner::Planner& planner,
                          const EpisodeConfig& config, const EpisodeSteering& steering) {
  EpisodeResult result;
  result.planner = planner.name();
  result.travel = std::string(to_string(config.travel));
  result.perception_mode = std::string(to_string(config.perception.mode));
  // `world` is the plant the physics and the sensors hold; the robot's map leaves out the
  // unmapped obstacles and puts the charger where the map says. Only perception, the travel
  // modes and the planner see the map.
  const worlds::World& plant = world;
  const bool mismatch = worlds::differs_from_map(plant);
  const worlds::World map_copy = mismatch ? worlds::robot_map(plant) : worlds::World{};
  const worlds::World& map = mismatch ? map_copy : plant;
  const Pose2 staging = worlds::staging_pose(map);
  // A pursuit plans to where the target parks (the world file says where): the reference for
  // a potential-field run, the first path for a path-following one.
  const Vec2 goal = map.target ? map.target->waypoints.back() : staging.position();
  const planner::PlanResult plan = planner.plan(map.start.position(), goal);
  result.plan_stats = plan.stats;
  result.explored = plan.explored;
  result.explored_label = plan.explored_label;
  result.tried = plan.tried;
  result.marks = plan.marks;
  result.plan_note = plan.note;
  const bool planned = plan.status == planner::PlanStatus::kOk;
  if (!planned) {
    // The potential field needs no plan: without its reference it still drives.
    if (config.travel != TravelMode::kPotentialField) {
      result.status = std::string(planner::to_string(plan.status));
      result.failure = Failure{
          FailureReason::kNoPath, 0.0, map.start,
          "the planner: " + result.status + (plan.note.empty() ? "" : " (" + plan.note + ")")};
      result.events.push_back({EpisodeResult::Event::Kind::kFailure, 0.0, map.start.position()});
      return result;
    }
    result.plan_note =
        "no reference plan (" + std::string(planner::to_string(plan.status)) + "): " + plan.note;
  }
  result.plan = plan.path;
  result.first_plan = plan.path;
  result.path_length_m = plan.length;
  const std::vector<Vec2> first_path = planned
                                           ? (plan.drive_path.empty() ? plan.path : plan.drive_path)
                                           : std::vector<Vec2>{map.start.position(), goal};

  TravelSettings settings{config.tracking, config.docking, config.field,
                          config.pursuit_replan_period_s};
  settings.docking.staging_distance_m = map.charger_spec.staging_distance_m;
  settings.docking.footprint_radius_m = map.robot.radius_m;
  settings.map_planner = &planner;  // replans add what is sensed on top of its graph
  const bool pursuit = map.target.has_value();
  std::unique_ptr<Travel> travel =
      config.travel == TravelMode::kPotentialField
          ? make_field_travel(map, planner.name(), settings, pursuit, map.robot.radius_m)
      : pursuit ? make_pursuit_travel(map, planner.name(), settings, first_path)
                : make_path_travel(map, planner.name(), settings, first_path);
  if (steering) {
    travel = steering.wrap(std::move(travel), map, first_path);
    result.steered_by = steering.name;
  }
  if (config.perception.mode == PerceptionMode::kSensors)
    travel = hold_still_first(std::move(travel), config.perception.gyro_calibration_s);

  PhysicsWorld physics(plant);
  WheelDrive drive(plant.robot, config.drive);
  SensorParams sensing = sensor_params(config);
  sensing.pads.travel_m = plant.charger_spec.pad_travel_m;
  sensing.pads.contact_width_m = plant.charger_spec.width_m;
  SensorSuite sensors(plant, sensing, config.seed);
  PerceptionParams perception_params = config.perception;
  perception_params.field_range_m = config.field.sensor_range_m;
  Perceiver perceiver(map, perception_params);
  EpisodeMetrics metrics(plant, result, config.catch_distance_m, config.step.dt_s);

  controller::TractionParams traction = config.traction;
  traction.max_accel_mps2 = std::min(traction.max_accel_mps2, plant.robot.max_accel_mps2);
  controller::TractionGovernor governor(traction);
  const double dt = config.step.dt_s;
  const auto max_steps = static_cast<std::int64_t>(std::ceil(config.timeout_s / dt));
  const int period = std::max(1, config.control_period_steps);
  result.status = "timeout";
  double next_snapshot_s = 0;
  double next_track_s = 0;
  constexpr double kMovingTrackPeriod_s = 0.25;
  LocalizationHealth worst_health = LocalizationHealth::kOk;
  FailureWatch watch;
  bool kidnapped = false;
  std::optional<GiveUp> give_up;
  result.trajectory.reserve(
      static_cast<std::size_t>(std::min<std::int64_t>(max_steps / period + 1, 1 << 20)));
  // Physics, tyres, encoders and contacts run every step; sensing, estimation, control and
  // logging every control period, seeing the contacts latched since the last one.
  ContactState contact = physics.contacts();  // read once per step, by sensors and metrics alike
  for (std::int64_t k = 0; k <= max_steps; ++k) {
    metrics.before_step(physics, contact);
    if (k % period == 0) {
      const double t = k * dt;
      const SensorReadings readings = sensors.read(physics, t);  // sense
      const Perception& p = perceiver.update(readings);          // estimate
      metrics.compare_estimate(physics, p.pose);
      metrics.compare_obstacles(p.obstacles);
      metrics.charging(physics, readings.charging);
      worst_health = std::max(worst_health, p.health);  // ok < degraded < lost
      const Pose2 truth = physics.robot_pose();
      const double speed = geom::dot(physics.robot_velocity(), truth.heading());
      const std::optional<ActorState> target = physics.target();
      const Vec2 target_at = target ? target->box.center() : Vec2{};
      result.time_s = t;
      if (metrics.target_caught(physics)) {
        result.caught = true;
        result.status = "caught";
        result.trajectory.push_back({t, truth, p.pose, p.position_sigma_m, speed, 0,
                                     controller::DockPhase::kTravel, false, target_at});
        break;
      }
      if (config.scan_log_period_s > 0 && t >= next_snapshot_s) {
        next_snapshot_s = t + config.scan_log_period_s;
        result.perception_log.push_back(
            {t, perceiver.last_scan(), perceiver.tracker().boxes(t), p.layer});
      }
      const TravelCounts before = travel->counts();
      const Decision d = travel->decide(p);  // decide
      watch.observe(t, truth, p.pose, p.health, d.blocked);
      const TravelCounts after = travel->counts();
      using Kind = EpisodeResult::Event::Kind;
      if (after.stops > before.stops) result.events.push_back({Kind::kStop, t, truth.position()});
      if (after.replans > before.replans)
        result.events.push_back({Kind::kReplan, t, truth.position()});
      if (after.recoveries > before.recoveries)
        result.events.push_back({Kind::kRecovery, t, truth.position()});
      if (after.retries > before.retries)
        result.events.push_back({Kind::kRetry, t, truth.position()});
      if (t >= next_track_s) {
        next_track_s = t + kMovingTrackPeriod_s;
        const std::vector<ActorState> actors = physics.actors();
        result.moving_tracks.resize(actors.size());
        for (std::size_t i = 0; i < actors.size(); ++i) {
          result.moving_tracks[i].t_s.push_back(t);
          result.moving_tracks[i].boxes.push_back(actors[i].box);
        }
      }
      result.max_cross_track_m = std::max(result.max_cross_track_m, d.cross_track_m);
      result.trajectory.push_back({t, truth, p.pose, p.position_sigma_m, speed, d.cross_track_m,
                                   d.phase, d.wall_following, target_at});
      if (!d.finished.empty()) {
        // Success is the charger's signal with no collision on the way (and, undocking, the
        // staging pose reached again).
        const bool charged = d.finished == "docked" || d.finished == "undocked";
        result.docked = charged && result.collisions == 0;
        result.undocked = d.finished == "undocked";
        result.status = charged && !result.docked ? "docked_with_collision" : d.finished;
        if (!charged) metrics.measure_final_error(physics);
        give_up = d.give_up;
        break;
      }
      const controller::Twist twist = governor.limit(d.twist, p.slipping, period * dt);
      drive.command(controller::to_wheels(twist, plant.robot.wheel_base_m),
                    period * dt);  // actuate
    }
    if (config.kidnap.enabled() && !kidnapped && k * dt >= config.kidnap.at_s) {
      kidnapped = true;
      const Pose2 was = physics.robot_pose();
      physics.place_robot({was.x + config.kidnap.dx_m, was.y + config.kidnap.dy_m,
                           geom::wrap_angle(was.yaw + config.kidnap.dyaw_rad)});
    }
    drive.apply(physics, dt);
    physics.step(config.step);  // step
    contact = physics.contacts();
    sensors.count(physics, contact, drive, dt);
    metrics.after_step(physics);
  }
  for (const ActorState& a : physics.actors()) result.moving_final.push_back(a.box);
  if (result.status == "timeout") metrics.measure_final_error(physics);
  result.localization_status = std::string(to_string(worst_health));
  const TravelCounts counts = travel->counts();
  result.retries = counts.retries;
  result.stops = counts.stops;
  result.replans = counts.replans;
  result.local_minima = counts.local_minima;
  result.wall_follows = counts.wall_follows;
  result.recoveries = counts.recoveries;
  result.slips = governor.slips();
  if (auto final_plan = travel->final_plan()) result.plan = *final_plan;
  result.last_scan = perceiver.last_scan();
  result.relocalizations = perceiver.relocalizations();
  result.tracked_final = perceiver.tracker().boxes(result.time_s);
  result.layer_final = perceiver.current().layer;
  if (!result.succeeded()) {
    std::optional<std::pair<double, Pose2>> first_collision;
    for (const EpisodeResult::Event& e : result.events) {
      if (e.kind != EpisodeResult::Event::Kind::kCollision || first_collision) continue;
      // The heading from the last logged sample at or before the contact (the event keeps a
      // position).
      double yaw = physics.robot_pose().yaw;
      for (const TrajectorySample& s : result.trajectory)
        if (s.t_s <= e.t_s) yaw = s.truth.yaw;
      first_collision = {e.t_s, Pose2{e.at.x, e.at.y, yaw}};
    }
    result.failure =
        watch.judge(result.time_s, physics.robot_pose(), give_up, first_collision, pursuit);
    result.events.push_back({EpisodeResult::Event::Kind::kFailure, result.failure->time_s,
                             result.failure->pose.position()});
  }
  return result;
}

}  // namespace plantsim::sim
