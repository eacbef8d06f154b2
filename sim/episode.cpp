// The episode loop and its metrics.
#include "sim/episode.h"

#include <cmath>
#include <random>

#include "controller/collision_check.h"

namespace plantsim::sim {
namespace {

struct DockError {
  double position_m;
  double heading_rad;
};

DockError dock_error(const Pose2& truth, const Pose2& dock) {
  return {geom::distance(truth.position(), dock.position()),
          std::fabs(geom::wrap_angle(truth.yaw - dock.yaw))};
}

// The charger as a marker detector would report it: docked pose in the robot frame.
class ChargerDetector {
 public:
  ChargerDetector(DetectionParams p, std::uint64_t seed) : p_(p), rng_(seed ^ 0x9e3779b97f4a7c15ULL) {}
  /// `marker` is where the detected feature is (the charger body's centre), in the world.
  std::optional<Pose2> observe(const Pose2& truth, const Pose2& dock, Vec2 marker_world) {
    if (!p_.enabled) return std::nullopt;
    const Vec2 d = dock.position() - truth.position();
    if (geom::dot(d, d) > p_.range_m * p_.range_m) return std::nullopt;
    const Vec2 rel = geom::rotate(d, -truth.yaw);
    // The marker is on the charger: it must be within the sensor's field of view.
    const Vec2 marker = geom::rotate(marker_world - truth.position(), -truth.yaw);
    if (std::fabs(std::atan2(marker.y, marker.x)) > 0.5 * p_.field_of_view_rad) return std::nullopt;
    return Pose2{rel.x + p_.position_noise_m * gauss_(rng_), rel.y + p_.position_noise_m * gauss_(rng_),
                 geom::wrap_angle(dock.yaw - truth.yaw + p_.yaw_noise_rad * gauss_(rng_))};
  }

 private:
  DetectionParams p_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> gauss_{0.0, 1.0};
};

// Moving obstacles within range, as boxes in the map frame: what a lidar and a tracker see
// relative to the robot, placed with the robot's own (possibly wrong) pose estimate.
std::vector<controller::MovingBox> sense_moving(const std::vector<ActorState>& actors, const Pose2& truth,
                                                const Pose2& estimate, double range_m) {
  std::vector<controller::MovingBox> out;
  const Pose2 estimate_from_truth = geom::compose(estimate, geom::inverse(truth));
  for (const ActorState& a : actors) {
    const geom::Rect& b = a.box;
    if (controller::distance_to_box(truth.position(), b) > range_m) continue;
    geom::Rect seen{INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (Vec2 c : {Vec2{b.xmin, b.ymin}, Vec2{b.xmax, b.ymin}, Vec2{b.xmax, b.ymax}, Vec2{b.xmin, b.ymax}}) {
      const Vec2 q = geom::compose(estimate_from_truth, Pose2{c.x, c.y, 0}).position();
      seen = {std::min(seen.xmin, q.x), std::min(seen.ymin, q.y), std::max(seen.xmax, q.x), std::max(seen.ymax, q.y)};
    }
    out.push_back({seen, geom::rotate(a.velocity, estimate_from_truth.yaw)});
  }
  return out;
}

// What the potential field feels: the map's rectangles and walls within sensor range, the
// charger block, and the moving obstacles as sensed (with their velocities).
std::vector<controller::FieldObstacle> field_obstacles(const worlds::World& world, const Pose2& estimate, double range_m,
                                                       const std::vector<controller::MovingBox>& moving) {
  std::vector<controller::FieldObstacle> out;
  const Vec2 x = estimate.position();
  auto add_if_near = [&](const geom::Rect& r) {
    if (geom::distance(x, geom::closest_point(r, x)) <= range_m) out.push_back({r, {0, 0}});
  };
  for (const geom::Rect& r : world.obstacles) add_if_near(r);
  for (const geom::Rect& r : geom::surrounding_walls(world.floor, 1.0)) add_if_near(r);
  add_if_near(worlds::charger_body(world).bounding_box());
  for (const auto& m : moving) out.push_back({m.box, m.velocity});
  return out;
}

}  // namespace

std::string_view to_string(TravelMode m) { return m == TravelMode::kPath ? "path" : "potential-field"; }

EpisodeResult run_episode(const worlds::World& world, planner::Planner& planner,
                          const EpisodeConfig& config) {
  EpisodeResult result;
  result.planner = planner.name();
  result.travel = std::string(to_string(config.travel));
  const Pose2 staging = worlds::staging_pose(world);
  // A pursuit plans to where the target parks: the reference for a potential-field run, the
  // first path for a path-following one (replanned to the target as it moves).
  const Vec2 goal = world.target ? world.target->waypoints.back() : staging.position();
  const planner::PlanResult plan = planner.plan(world.start.position(), goal);
  result.plan_stats = plan.stats;
  result.explored = plan.explored;
  result.plan_note = plan.note;
  const bool planned = plan.status == planner::PlanStatus::kOk;
  if (!planned) {
    // The potential field needs no plan: without its reference it still drives.
    if (config.travel != TravelMode::kPotentialField) {
      result.status = std::string(planner::to_string(plan.status));
      return result;
    }
    result.plan_note = "no reference plan (" + std::string(planner::to_string(plan.status)) + "): " + plan.note;
  }
  result.plan = plan.path;
  result.path_length_m = plan.length;
  // Until the field hands over, the docking controller's path is only a placeholder.
  const std::vector<Vec2> first_path = planned ? plan.path : std::vector<Vec2>{world.start.position(), goal};

  PhysicsWorld physics(world);
  WheelDrive drive(world.robot, config.drive);
  Odometry odometry(world.start, world.robot.wheel_base_m, config.odometry, config.seed);
  Localization localization(config.localization, config.seed);
  ChargerDetector detector(config.detection, config.seed);
  controller::DockingParams docking = config.docking;
  docking.staging_distance_m = world.charger_spec.staging_distance_m;
  docking.footprint_radius_m = world.robot.radius_m;
  controller::DockingController control(config.tracking, docking, first_path, world.charger);
  const Vec2 charger_marker = worlds::charger_body(world).center;
  std::optional<controller::PotentialFieldController> field;
  if (config.travel == TravelMode::kPotentialField) field.emplace(config.field, world.robot.radius_m);
  double next_chase_plan_s = config.pursuit_replan_period_s;  // path travel after a moving target
  // A plan from where the robot believes it is, around the moving obstacles it sees (grown by
  // the arc check's extra clearance, so that the new path is one it will accept).
  auto plan_around = [&](const Pose2& estimate, Vec2 to, const std::vector<controller::MovingBox>& seen)
      -> std::optional<std::vector<Vec2>> {
    planner::PlannerInput again = planner::planner_input(world, true);
    const double extra = std::max(0.0, config.docking.safety_margin_m - world.inflation_margin_m) + 0.05;
    for (const auto& b : seen) again.obstacles.push_back(b.box.inflated(extra));
    again.snap_to_free = true;
    const planner::PlanResult re = planner::make_planner(planner.name(), again)->plan(estimate.position(), to);
    if (re.status != planner::PlanStatus::kOk) return std::nullopt;
    std::vector<Vec2> path = re.path;
    if (re.start_snapped) path.insert(path.begin(), estimate.position());
    return path;
  };

  const double dt = config.step.dt_s;
  const auto max_steps = static_cast<std::int64_t>(std::ceil(config.timeout_s / dt));
  bool was_touching_obstacle = false;
  bool contact_measured = false;
  Vec2 previous = physics.robot_position();
  result.status = "timeout";
  // Physics, tyres, odometry and contacts run every step; sensing, control and logging run
  // every control period, seeing the contacts latched since the last one.
  const int period = std::max(1, config.control_period_steps);
  const double control_dt = period * dt;
  controller::DockingCommand cmd;
  bool charger_contact = false, charging = false;
  result.trajectory.reserve(static_cast<std::size_t>(std::min<std::int64_t>(max_steps / period + 1, 1 << 20)));
  for (std::int64_t k = 0; k <= max_steps; ++k) {
    const ContactState contact = physics.contacts();
    if (contact.obstacle && !was_touching_obstacle) ++result.collisions;
    was_touching_obstacle = contact.obstacle;
    if (contact.charger) {
      const DockError err = dock_error(physics.robot_pose(), world.charger);
      charger_contact = true;
      charging = charging || (err.position_m <= config.tolerance.position_m &&
                              err.heading_rad <= config.tolerance.heading_rad);
      if (!contact_measured) {
        result.position_error_m = err.position_m;
        result.heading_error_deg = err.heading_rad * 180.0 / M_PI;
        contact_measured = true;
      }
    } else {
      contact_measured = false;
    }

    if (k % period == 0) {
      odometry.read();
      const Pose2 truth = physics.robot_pose();
      localization.update(k * dt, odometry.pose(), truth);
      const Pose2 estimate = localization.map_pose(odometry.pose());
      controller::DockingInput in;
      in.pose = estimate;
      in.odom_pose = odometry.pose();
      in.speed_mps = odometry.speed_mps();
      in.dt_s = control_dt;
      in.charger_contact = charger_contact;
      in.charging = charging;
      charger_contact = charging = false;
      in.charger_in_robot = detector.observe(truth, world.charger, charger_marker);
      if (!world.moving.empty())
        in.nearby_obstacles = sense_moving(physics.actors(), truth, estimate, config.perception.range_m);
      const std::optional<ActorState> target = physics.target();
      if (target && controller::distance_to_box(truth.position(), target->box) - world.robot.radius_m <=
                        config.catch_distance_m) {
        result.caught = true;
        result.status = "caught";
        result.time_s = k * dt;
        result.trajectory.push_back({k * dt, truth, estimate, geom::dot(physics.robot_velocity(), truth.heading()), 0,
                                     controller::DockPhase::kTravel, false, target->box.center()});
        break;
      }
      bool wall_following = false;
      if (field) {
        const Vec2 velocity = in.speed_mps * estimate.heading();
        const controller::FieldCommand fc = field->step(
            {estimate, velocity, target ? target->box.center() : staging.position(), target ? target->velocity : Vec2{0, 0},
             control_dt, field_obstacles(world, estimate, config.field.sensor_range_m, in.nearby_obstacles)});
        result.local_minima = field->local_minima();
        result.wall_follows = field->wall_follow_episodes();
        wall_following = fc.state == controller::FieldState::kWallFollowing;
        if (fc.trapped) {
          result.status = "trapped";
          result.time_s = k * dt;
          break;
        }
        if (fc.arrived && !target) {
          // At the staging area: the docking manoeuvre takes over from here.
          field.reset();
          control.replace_path({estimate.position(), staging.position()});
          cmd = control.step(in);
        } else {
          cmd = {};
          cmd.twist = fc.twist;
        }
      } else if (target) {
        // Travel as to a charger, but the path's end follows the target; never dock.
        if (k * dt >= next_chase_plan_s || control.phase() != controller::DockPhase::kTravel) {
          next_chase_plan_s = k * dt + config.pursuit_replan_period_s;
          if (auto path = plan_around(estimate, target->box.center(), in.nearby_obstacles)) {
            if (control.phase() == controller::DockPhase::kTravel) control.replace_path(*path);
            else control = controller::DockingController(config.tracking, docking, *path, world.charger);
            ++result.replans;
          }
        }
        cmd = control.step(in);
        if (cmd.phase != controller::DockPhase::kTravel) cmd.twist = {};
      } else {
        cmd = control.step(in);
        if (cmd.replan_requested) {
          // Plan again with what blocks the way as extra obstacles, from the nearest free
          // point if the robot stands inside their margin.
          if (auto path = plan_around(estimate, staging.position(), in.nearby_obstacles)) {
            control.replace_path(*path);
            result.plan = *path;  // the figure shows the plan finally followed
            ++result.replans;
          }
        }
      }
      result.max_cross_track_m = std::max(result.max_cross_track_m, cmd.cross_track_error_m);
      result.trajectory.push_back({k * dt, truth, estimate, geom::dot(physics.robot_velocity(), truth.heading()),
                                   cmd.cross_track_error_m, cmd.phase, wall_following,
                                   target ? target->box.center() : Vec2{}});
      result.time_s = k * dt;
      if (cmd.phase == controller::DockPhase::kDocked || cmd.phase == controller::DockPhase::kFailed) {
        result.docked = cmd.phase == controller::DockPhase::kDocked;
        result.status = result.docked ? "docked" : "failed";
        if (!result.docked) {
          const DockError err = dock_error(truth, world.charger);
          result.position_error_m = err.position_m;
          result.heading_error_deg = err.heading_rad * 180.0 / M_PI;
        }
        break;
      }
      drive.command(controller::to_wheels(cmd.twist, world.robot.wheel_base_m), control_dt);
    }
    drive.apply(physics, dt);
    physics.step(config.step);
    ++result.physics_steps;
    odometry.count(drive.motor_speeds(), dt);
    const Vec2 now = physics.robot_position();
    result.driven_length_m += geom::distance(previous, now);
    previous = now;
  }
  for (const ActorState& a : physics.actors()) result.moving_final.push_back(a.box);
  if (result.status == "timeout" || result.status == "trapped") {
    const DockError err = dock_error(physics.robot_pose(), world.charger);
    result.position_error_m = err.position_m;
    result.heading_error_deg = err.heading_rad * 180.0 / M_PI;
  }
  result.retries = control.retries();
  result.stops = control.stops();
  return result;
}

}  // namespace plantsim::sim
