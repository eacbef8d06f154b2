// The episode's loop (see the header): the parts assembled from the plant, the map and the
// configuration, and the loop of sense, estimate, decide, actuate, step, record, able to pause.
#include "episode/episode_loop.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "controller/local_controller_registry.h"
#include "episode/episode_config_json.h"
#include "episode/episode_work.h"
#include "robot/dock_detector.h"
#include "robot/estimator_registry.h"
#include "robot/travel_registry.h"
#include "sim/kidnap_landing.h"
#include "sim/target_catch.h"
#include "util/component_failure.h"

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
  s.pads = c.tolerance;
  s.pads.travel_m = plant.charger_spec.pad_travel_m;
  s.pads.contact_width_m = plant.charger_spec.width_m;
  return s;
}

robot::PerceptionParams perception_params(const EpisodeConfig& c) {
  robot::PerceptionParams p = c.perception;
  p.field_range_m = c.field.sensor_range_m;
  p.estimator_params =
      component_values(c, robot::estimators().at(c.perception.estimator).params).named();
  p.dock_detector_params =
      component_values(c, robot::dock_detectors().at(c.perception.dock_detector).params).named();
  return p;
}

/// The facts a local controller is built for: the robot's own spec and map, never the plant's.
controller::LocalControllerContext local_context(const worlds::World& map, const EpisodeConfig& c) {
  controller::LocalControllerContext x;
  x.footprint_radius_m = map.robot.radius_m;
  x.wheel_base_m = map.robot.wheel_base_m;
  x.max_wheel_speed_mps = map.robot.max_speed_mps;
  x.max_accel_mps2 = map.robot.max_accel_mps2;
  x.control_period_s = std::max(1, c.control_period_steps) * c.step.dt_s;
  x.map_obstacles = map.obstacles;
  x.map_obstacles.push_back(worlds::charger_body(map).bounding_box());
  x.floor = map.floor;
  x.seed = c.seed;
  return x;
}

controller::TractionParams traction_params(const EpisodeConfig& c, const worlds::World& plant) {
  controller::TractionParams t = c.traction;
  t.max_accel_mps2 = std::min(t.max_accel_mps2, plant.robot.max_accel_mps2);
  // Seed 001's field drives as its document's robot does, at the motors' limit: its pursuit
  // stops and sets off in every local minimum, and a soft start there is not the method; nor is
  // slowing for what the lidar sees ahead (issue 88's stopping bound), which in a pursuit is the
  // target it must reach while it moves.
  if (robot::travel_modes().at(c.travel).can(robot::travel_capability::kStartsAtMotorLimit)) {
    t.full_grip_accel_mps2 = 0.0;
    t.stop_within_sight = false;
  }
  return t;
}

/// Where the first plan goes: the staging pose, or where a moving target will park (the
/// reference of a potential-field pursuit, the first path of a path-following one).
geom::Vec2 plan_goal(const worlds::World& map) {
  return map.target ? map.target->waypoints.back() : worlds::staging_pose(map).position();
}

/// `local` is the configuration's local controller entry, wrapped to time its calls.
std::unique_ptr<robot::Travel> make_travel(const worlds::World& map, planner::Planner& planner,
                                           const EpisodeConfig& config,
                                           const planner::PlanResult& plan,
                                           const controller::LocalControllerEntry& local,
                                           const EpisodeSteering& steering, EpisodeResult& r) {
  robot::TravelSettings settings;
  settings.tracking = config.tracking;
  settings.docking = config.docking;
  settings.field = config.field;
  settings.pursuit_replan_period_s = config.pursuit_replan_period_s;
  settings.lost_search = config.lost_search;
  settings.coastal = config.coastal;
  settings.docking.staging_distance_m = map.charger_spec.staging_distance_m;
  settings.docking.guard.footprint_radius_m = map.robot.radius_m;
  settings.map_planner = &planner;  // replans add what is sensed on top of its graph
  settings.local = &local;
  settings.local_params = component_values(config, local.params);
  settings.local_context = local_context(map, config);
  // The datasheet's range, not the plant's lidar: what the robot side may know of its sensor.
  if (config.perception.mode == robot::PerceptionMode::kSensors)
    settings.lidar_range_m = config.lidar.max_range_m;
  const std::vector<Vec2> first_path = plan.status != planner::PlanStatus::kOk
                                           ? std::vector<Vec2>{map.start.position(), plan_goal(map)}
                                       : plan.drive_path.empty() ? plan.path
                                                                 : plan.drive_path;
  const robot::TravelEntry& mode = robot::travel_modes().at(config.travel);
  std::unique_ptr<robot::Travel> travel =
      mode.make(robot::TravelContext{&map, planner.name(), &settings, first_path},
                component_values(config, mode.params));
  if (steering) {
    travel = steering.wrap(std::move(travel), map, first_path);
    r.steered_by = steering.name;
  }
  if (config.perception.mode == robot::PerceptionMode::kSensors)
    travel = hold_still_first(std::move(travel), config.perception.gyro_calibration_s);
  return travel;
}

}  // namespace

/// The parts of one episode, from the plant (physics, drive, sensors) to the robot's side
/// (perceiver, travel, traction), run step by step: physics, tyres, encoders and contacts every
/// step; sensing, estimation, control and the trajectory log every control period, seeing the
/// contacts latched since the last one.
class EpisodeRun::Loop {
 public:
  Loop(const worlds::World& plant, const worlds::World& map, const EpisodeConfig& config,
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
        contact_(physics_.contacts()),
        max_steps_(static_cast<std::int64_t>(std::ceil(config.timeout_s / config.step.dt_s))),
        period_(std::max(1, config.control_period_steps)) {}

  Stop advance(const std::function<bool()>& interrupted,
               const std::function<bool()>& wants_command) {
    if (closed_) return Stop::kEnded;
    const double dt = config_.step.dt_s;
    Stop stop = Stop::kEnded;
    try {
      if (awaiting_) {  // the paused control period goes on with the outside's command
        awaiting_ = false;
        if (finish_control(period_ * dt)) return close(Stop::kEnded);
        apply_faults(k_ * dt);
        step(dt);
        ++k_;
      }
      for (; k_ <= max_steps_; ++k_) {
        time_s_ = k_ * dt;
        const bool control_tick = k_ % period_ == 0;
        if (control_tick && interrupted && interrupted()) {
          stop = Stop::kInterrupted;
          break;
        }
        recorder_.before_step(physics_, contact_);
        if (control_tick) {
          if (begin_control(k_ * dt)) break;
          if (wants_command && wants_command()) {
            awaiting_ = true;
            return Stop::kAwaitingCommand;
          }
          if (finish_control(period_ * dt)) break;
        }
        apply_faults(k_ * dt);
        step(dt);
      }
    } catch (...) {
      close(stop);
      throw;
    }
    return close(stop);
  }

  void command(controller::Twist twist) {
    if (!awaiting_) throw std::logic_error("no decision awaits a command");
    decision_.twist = twist;
  }
  double time_s() const { return time_s_; }
  const robot::Perception* last_perception() const { return perception_; }

 private:
  Stop close(Stop stop) {
    if (!closed_) recorder_.close(physics_, *travel_, governor_, perceiver_, pursuit_);
    closed_ = true;
    return stop;
  }

  /// Sense, estimate, decide; true when the episode has ended.
  bool begin_control(double t_s) {
    t_s_ = t_s;
    const robot::SensorReadings readings = sensors_.read(physics_, t_s);  // sense
    try {
      perception_ = &perceiver_.update(readings);  // estimate
    } catch (const util::ComponentFailure& e) {  // a plugin's estimator or detector threw: it ends
      perception_ = &perceiver_.current();
      decision_ = plugin_failed(e);
      return false;
    }
    recorder_.perceived(t_s, physics_, *perception_, readings);
    if (sim::target_caught(physics_, plant_.robot.radius_m, config_.catch_distance_m)) {
      recorder_.caught(t_s, physics_, *perception_);
      return true;
    }
    recorder_.snapshot(t_s, *perception_, perceiver_);
    try {
      decision_ = travel_->decide(*perception_);  // decide
    } catch (const util::ComponentFailure& e) {   // a plugin's controller threw: the episode ends
      decision_ = plugin_failed(e);
    }
    return false;
  }

  /// The decision that ends the episode when a plugin's component threw.
  static robot::Decision plugin_failed(const util::ComponentFailure& e) {
    robot::Decision d;
    d.finished = robot::TravelEnd::kFailed;
    d.give_up = robot::GiveUp{robot::FailureReason::kPluginError, e.what()};
    return d;
  }

  /// Record the decision, actuate; true when the decision ended the episode.
  bool finish_control(double period_s) {
    recorder_.decided(t_s_, physics_, *perception_, decision_);
    if (decision_.finished != robot::TravelEnd::kNone) {
      recorder_.finished(physics_, decision_);
      return true;
    }
    const controller::Twist twist =
        governor_.limit(decision_.twist, perception_->slipping, period_s,
                        perception_->free_ahead_m);  // actuate
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
    recorder_.carried(t_s, was, physics_.robot_pose());
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
  std::int64_t max_steps_;
  int period_;
  std::int64_t k_ = 0;  // the next physics step
  bool awaiting_ = false, closed_ = false;
  double t_s_ = 0;  // of the control period at hand
  const robot::Perception* perception_ = nullptr;
  robot::Decision decision_;
};

EpisodeRun::EpisodeRun(const worlds::World& plant, planner::Planner& planner,
                       const EpisodeConfig& config, const EpisodeSteering& steering)
    : map_copy_(worlds::differs_from_map(plant) ? worlds::robot_map(plant) : worlds::World{}),
      map_(worlds::differs_from_map(plant) ? map_copy_ : plant) {
  check_episode_work(plant, config);  // the commands check it earlier; this holds for every caller
  result_.planner = planner.name();
  result_.travel = config.travel;
  result_.perception_mode = std::string(to_string(config.perception.mode));
  recorder_ = std::make_unique<EpisodeRecorder>(plant, config, result_);
  planner::PlanResult plan;
  try {
    plan = planner.plan(map_.start.position(), plan_goal(map_));
  } catch (const util::ComponentFailure& e) {  // a plugin's planner threw: the episode ends
    recorder_->not_started(
        robot::Failure{robot::FailureReason::kPluginError, 0.0, map_.start, e.what()});
    return;
  }
  // A mode that needs no plan (the potential field) drives without its reference.
  const bool needs_plan =
      robot::travel_modes().at(config.travel).can(robot::travel_capability::kNeedsAPlan);
  if (needs_plan && plan.status != planner::PlanStatus::kOk) {
    recorder_->no_way(plan, map_.start);  // the episode ends before it begins
    return;
  }
  recorder_->first_plan(plan);
  timed_local_ = std::make_unique<controller::LocalControllerEntry>(timed_entry(
      controller::local_controllers().at(config.local_controller), recorder_->controller_clock()));
  try {
    loop_ = std::make_unique<Loop>(
        plant, map_, config,
        make_travel(map_, planner, config, plan, *timed_local_, steering, result_), *recorder_);
  } catch (const util::ComponentFailure& e) {  // a plugin's factory threw for this episode
    recorder_->not_started(
        robot::Failure{robot::FailureReason::kPluginError, 0.0, map_.start, e.what()});
  }
}

EpisodeRun::~EpisodeRun() = default;

EpisodeRun::Stop EpisodeRun::advance(const std::function<bool()>& interrupted,
                                     const std::function<bool()>& wants_command) {
  return loop_ ? loop_->advance(interrupted, wants_command) : Stop::kEnded;
}

void EpisodeRun::command(controller::Twist twist) {
  if (!loop_) throw std::logic_error("the episode has ended");
  loop_->command(twist);
}

double EpisodeRun::time_s() const { return loop_ ? loop_->time_s() : 0.0; }

const robot::Perception* EpisodeRun::last_perception() const {
  return loop_ ? loop_->last_perception() : nullptr;
}

}  // namespace plantsim::episode
