// The episode loop: sense, estimate, decide, actuate, step, record. The stages are the parts'
// own (sensor suite, perceiver, travel, drive, physics); the recorder writes the result.
#include "episode/run_episode.h"

#include <algorithm>
#include <cmath>

#include "episode/episode_recorder.h"
#include "sim/kidnap_landing.h"

namespace plantsim::episode {

using namespace plantsim::sim;  // the simulator's parts and the episode's types

namespace {

SensorParams sensor_params(const EpisodeConfig& c, const worlds::World& plant) {
  SensorParams s;
  s.oracle = c.perception.mode == robot::PerceptionMode::kOracle;
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
  s.pads.travel_m = plant.charger_spec.pad_travel_m;
  s.pads.contact_width_m = plant.charger_spec.width_m;
  return s;
}

robot::PerceptionParams perception_params(const EpisodeConfig& c) {
  robot::PerceptionParams p = c.perception;
  p.field_range_m = c.field.sensor_range_m;
  return p;
}

controller::TractionParams traction_params(const EpisodeConfig& c, const worlds::World& plant) {
  controller::TractionParams t = c.traction;
  t.max_accel_mps2 = std::min(t.max_accel_mps2, plant.robot.max_accel_mps2);
  return t;
}

/// The robot's map: the plant without its unmapped obstacles, the charger where the map says.
/// Only perception, the travel and the planner see it; the physics and sensors hold the plant.
class RobotMap {
 public:
  explicit RobotMap(const worlds::World& plant)
      : differs_(worlds::differs_from_map(plant)),
        copy_(differs_ ? worlds::robot_map(plant) : worlds::World{}),
        map_(differs_ ? copy_ : plant) {}
  const worlds::World& get() const { return map_; }

 private:
  bool differs_;
  worlds::World copy_;
  const worlds::World& map_;
};

/// Where the first plan goes: the staging pose, or where a moving target will park (the
/// reference of a potential-field pursuit, the first path of a path-following one).
geom::Vec2 plan_goal(const worlds::World& map) {
  return map.target ? map.target->waypoints.back() : worlds::staging_pose(map).position();
}

std::unique_ptr<robot::Travel> make_travel(const worlds::World& map, planner::Planner& planner,
                                           const EpisodeConfig& config,
                                           const planner::PlanResult& plan,
                                           const EpisodeSteering& steering, EpisodeResult& r) {
  robot::TravelSettings settings{config.tracking, config.docking, config.field,
                                 config.pursuit_replan_period_s};
  settings.docking.staging_distance_m = map.charger_spec.staging_distance_m;
  settings.docking.footprint_radius_m = map.robot.radius_m;
  settings.map_planner = &planner;  // replans add what is sensed on top of its graph
  const std::vector<Vec2> first_path = plan.status != planner::PlanStatus::kOk
                                           ? std::vector<Vec2>{map.start.position(), plan_goal(map)}
                                       : plan.drive_path.empty() ? plan.path
                                                                 : plan.drive_path;
  const bool pursuit = map.target.has_value();
  std::unique_ptr<robot::Travel> travel =
      config.travel == TravelMode::kPotentialField
          ? make_field_travel(map, planner.name(), settings, pursuit, map.robot.radius_m)
      : pursuit ? make_pursuit_travel(map, planner.name(), settings, first_path)
                : make_path_travel(map, planner.name(), settings, first_path);
  if (steering) {
    travel = steering.wrap(std::move(travel), map, first_path);
    r.steered_by = steering.name;
  }
  if (config.perception.mode == robot::PerceptionMode::kSensors)
    travel = hold_still_first(std::move(travel), config.perception.gyro_calibration_s);
  return travel;
}

/// One episode's parts, from the plant (physics, drive, sensors) to the robot's side
/// (perceiver, travel, traction), and the recorder beside them.
class Episode {
 public:
  Episode(const worlds::World& plant, const worlds::World& map, const EpisodeConfig& config,
          std::unique_ptr<robot::Travel> travel, EpisodeRecorder& recorder)
      : plant_(plant),
        config_(config),
        pursuit_(map.target.has_value()),
        physics_(plant),
        drive_(plant.robot, config.drive),
        sensors_(plant, sensor_params(config, plant), config.seed),
        perceiver_(map, perception_params(config)),
        travel_(std::move(travel)),
        governor_(traction_params(config, plant)),
        recorder_(recorder),
        contact_(physics_.contacts()) {}

  /// Physics, tyres, encoders and contacts every step; sensing, estimation, control and the
  /// trajectory log every control period, seeing the contacts latched since the last one.
  /// Returns false when `interrupted` stopped it; an exception from the loop (an outside
  /// controller's) leaves after the recorder has closed the episode so far.
  bool run(const std::function<bool()>& interrupted) {
    const double dt = config_.step.dt_s;
    const auto max_steps = static_cast<std::int64_t>(std::ceil(config_.timeout_s / dt));
    const int period = std::max(1, config_.control_period_steps);
    bool finished = true;
    std::exception_ptr thrown;
    try {
      for (std::int64_t k = 0; k <= max_steps; ++k) {
        time_s_ = k * dt;
        if (k % period == 0 && interrupted && interrupted()) {
          finished = false;
          break;
        }
        recorder_.before_step(physics_, contact_);
        if (k % period == 0 && control(k * dt, period * dt)) break;
        apply_faults(k * dt);
        step(dt);
      }
    } catch (...) {
      thrown = std::current_exception();
    }
    recorder_.close(physics_, *travel_, governor_, perceiver_, pursuit_);
    if (thrown) std::rethrow_exception(thrown);
    return finished;
  }
  double time_s() const { return time_s_; }

 private:
  /// One control period; true when the episode has ended.
  bool control(double t_s, double period_s) {
    const robot::SensorReadings readings = sensors_.read(physics_, t_s);  // sense
    const robot::Perception& p = perceiver_.update(readings);             // estimate
    if (recorder_.perceived(t_s, physics_, readings, p, perceiver_)) return true;
    const robot::Decision d = travel_->decide(p);  // decide
    if (recorder_.decided(t_s, physics_, p, d)) return true;
    const controller::Twist twist = governor_.limit(d.twist, p.slipping, period_s);  // actuate
    drive_.command(controller::to_wheels(twist, plant_.robot.wheel_base_m), period_s);
    return false;
  }

  /// The faults the configuration injects into the physics (a kidnap).
  void apply_faults(double t_s) {
    const KidnapFault& kidnap = config_.kidnap;
    if (!kidnap.enabled() || kidnapped_ || t_s < kidnap.at_s) return;
    kidnapped_ = true;
    const Pose2 was = physics_.robot_pose();
    if (kidnap.drawn()) {
      // No free floor that far (a narrow plant): the robot stays where it was.
      const std::optional<Pose2> to = kidnap_landing(plant_, was.position(), kidnap.distance_min_m,
                                                     kidnap.distance_max_m, config_.seed);
      if (!to) return;
      physics_.place_robot(*to);
    } else {
      physics_.place_robot(
          {was.x + kidnap.dx_m, was.y + kidnap.dy_m, geom::wrap_angle(was.yaw + kidnap.dyaw_rad)});
    }
    sensors_.robot_placed(physics_.robot_pose());
  }

  void step(double dt_s) {
    drive_.apply(physics_, dt_s);
    physics_.step(config_.step);
    contact_ = physics_.contacts();  // read once per step, by sensors and metrics alike
    sensors_.count(physics_, contact_, drive_, dt_s);
    recorder_.after_step(physics_);
  }

  const worlds::World& plant_;
  const EpisodeConfig& config_;
  bool pursuit_;
  PhysicsWorld physics_;
  WheelDrive drive_;
  SensorSuite sensors_;
  robot::Perceiver perceiver_;
  std::unique_ptr<robot::Travel> travel_;
  controller::TractionGovernor governor_;
  EpisodeRecorder& recorder_;
  ContactState contact_;
  bool kidnapped_ = false;
  double time_s_ = 0;
};

}  // namespace

EpisodeResult run_episode(const worlds::World& plant, planner::Planner& planner,
                          const EpisodeConfig& config, const EpisodeSteering& steering) {
  EpisodeResult result;
  result.planner = planner.name();
  result.travel = std::string(to_string(config.travel));
  result.perception_mode = std::string(to_string(config.perception.mode));
  const RobotMap map(plant);
  EpisodeRecorder recorder(plant, config, result);
  const planner::PlanResult plan = planner.plan(map.get().start.position(), plan_goal(map.get()));
  // The potential field needs no plan: without its reference it still drives.
  const bool needs_plan = config.travel != TravelMode::kPotentialField;
  if (!recorder.first_plan(plan, needs_plan, map.get().start)) return result;
  Episode episode(plant, map.get(), config,
                  make_travel(map.get(), planner, config, plan, steering, result), recorder);
  bool finished = false;
  try {
    finished = episode.run(steering.interrupted);
  } catch (...) {
    throw EpisodeStopped(std::move(result), episode.time_s(), std::current_exception());
  }
  if (!finished) {
    result.status = "interrupted";
    throw EpisodeStopped(std::move(result), episode.time_s(), nullptr);
  }
  return result;
}

}  // namespace plantsim::episode
