// Building the perception from readings: the EKF and the tracker (sensors), or the simulator's
// knowledge as the readings hand it over (oracle).
#include "robot/perception.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geometry/predicates.h"
#include "robot/ekf_estimator.h"
#include "robot/estimator_registry.h"
#include "robot/free_range.h"

namespace plantsim::robot {
namespace {

// Oracle mode: moving obstacles within range, as boxes in the map frame, placed with the
// robot's own (possibly wrong) pose estimate, with their scripted velocity.
std::vector<controller::MovingBox> known_actors(const OracleReadings& o,
                                                const geom::Pose2& estimate, double range_m) {
  std::vector<controller::MovingBox> out;
  const geom::Pose2 estimate_from_truth = geom::compose(estimate, geom::inverse(o.truth));
  for (const ActorState& a : o.actors) {
    const geom::Rect& b = a.box;
    if (controller::distance_to_box(o.truth.position(), b) > range_m) continue;
    geom::Rect seen{INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (geom::Vec2 c : {geom::Vec2{b.xmin, b.ymin}, geom::Vec2{b.xmax, b.ymin},
                         geom::Vec2{b.xmax, b.ymax}, geom::Vec2{b.xmin, b.ymax}}) {
      const geom::Vec2 q = geom::compose(estimate_from_truth, geom::Pose2{c.x, c.y, 0}).position();
      seen = {std::min(seen.xmin, q.x), std::min(seen.ymin, q.y), std::max(seen.xmax, q.x),
              std::max(seen.ymax, q.y)};
    }
    out.push_back({seen, geom::rotate(a.velocity, estimate_from_truth.yaw)});
  }
  return out;
}

// Oracle mode: the map's rectangles and walls within range, and the charger block.
std::vector<controller::FieldObstacle> map_near(const worlds::World& map, geom::Vec2 x,
                                                double range_m) {
  std::vector<controller::FieldObstacle> out;
  auto add_if_near = [&](const geom::Rect& r) {
    if (geom::distance(x, geom::closest_point(r, x)) <= range_m) out.push_back({r, {0, 0}});
  };
  for (const geom::Rect& r : map.obstacles) add_if_near(r);
  for (const geom::Rect& r : geom::surrounding_walls(map.floor, 1.0)) add_if_near(r);
  add_if_near(worlds::charger_body(map).bounding_box());
  return out;
}

std::unique_ptr<PoseEstimator> make_estimator(const worlds::World& map,
                                              const MapRaycaster& raycaster,
                                              const PerceptionParams& p) {
  const EstimatorEntry& e = estimators().at(p.estimator);
  EstimatorContext context;
  context.start = map.start;
  context.floor = map.floor;
  context.obstacles = map.obstacles;
  context.obstacles.push_back(worlds::charger_body(map).bounding_box());
  context.map = &map;
  context.raycaster = &raycaster;
  context.perception = &p;
  std::unique_ptr<PoseEstimator> made = e.make(context, util::ParamValues(p.estimator_params));
  if (!made)
    throw std::runtime_error("estimator \"" + e.name + "\" (" + e.origin + ") made nothing");
  return made;
}

std::unique_ptr<DockDetector> make_dock_detector(const worlds::World& map,
                                                 const PerceptionParams& p) {
  const DockDetectorEntry& e = dock_detectors().at(p.dock_detector);
  DockDetectorContext context;
  context.mapped_dock = map.charger;
  context.charger_width_m = map.charger_spec.width_m;
  context.boxes = map.obstacles;
  context.boxes.push_back(worlds::charger_body(map).bounding_box());
  std::unique_ptr<DockDetector> made = e.make(context, util::ParamValues(p.dock_detector_params));
  if (!made)
    throw std::runtime_error("dock detector \"" + e.name + "\" (" + e.origin + ") made nothing");
  return made;
}

}  // namespace

std::string_view to_string(PerceptionMode m) {
  switch (m) {  // a new mode without its name does not compile (-Wswitch, -Werror)
    case PerceptionMode::kSensors:
      return "sensors";
    case PerceptionMode::kOracle:
      return "oracle";
  }
  return "unknown";
}

Perceiver::Perceiver(const worlds::World& map, const PerceptionParams& params)
    : map_(map),
      p_(params),
      raycaster_(map),
      estimator_(make_estimator(map, raycaster_, params)),
      dock_detector_(make_dock_detector(map, params)),
      tracker_(params.tracker),
      layer_(params.layer) {
  now_.pose = map.start;
  now_.odom_pose = map.start;
  odom_yaw_before_ = map.start.yaw;
}

std::optional<geom::Pose2> Perceiver::carry_to_now(const ChargerDetection& d) const {
  // The odometry pose when the image was taken: the newest recorded at or before it.
  const geom::Pose2* then = nullptr;
  for (const auto& [t, pose] : odom_history_)
    if (t <= d.captured_s + 1e-9) then = &pose;
  if (!then) return std::nullopt;  // older than the history: too late to use
  return geom::compose(geom::compose(geom::inverse(now_.odom_pose), *then), d.dock_in_robot);
}

std::optional<ChargerDetection> Perceiver::sight_dock(const SensorReadings& r) {
  DockDetectorQuery q;
  q.readings = &r;
  q.estimate = now_.pose;
  q.expected_dock_in_robot = geom::compose(geom::inverse(now_.pose), map_.charger);
  return dock_detector_->detect(q);
}

void Perceiver::interpret_scan(const LidarScan& scan) {
  const geom::Pose2 sensor = geom::compose(now_.pose, scan.mount);
  scan_view_.pose = now_.pose;
  scan_view_.explained.clear();
  scan_view_.unexplained.clear();
  std::vector<geom::Vec2>& unexplained = unexplained_;
  std::vector<geom::Vec2>& near_static = near_static_;
  unexplained.clear();
  near_static.clear();
  const BeamDirections::Turned directions = directions_.turned(scan, sensor.yaw);
  // In whole centimetres: the map's nearness raster is built for one margin, and the learnt
  // noise moves a little with every scan.
  const double explained_margin =
      std::max(p_.tracker.unexplained_margin_m,
               0.01 * std::ceil(100.0 * p_.explained_sigmas * estimator_->range_sigma_m()));
  const MapRaycaster::SurfaceNear surface_near = raycaster_.surface_near(explained_margin);
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    if (!scan.valid(i)) continue;
    const double r = scan.ranges[i];
    const geom::Vec2 point = sensor.position() + r * directions[i];
    if (now_.target && geom::distance(point, *now_.target) < p_.target_exclusion_m) continue;
    // The map explains a return when one of its surfaces lies that close to it. A return short
    // of the map's surface, or one that passes a mapped surface and meets something beyond it,
    // is a thing the map does not have, and is tracked. (No ray cast needed: the nearness test
    // is a broad-phase box query.)
    const bool explained = surface_near(point);
    (explained ? scan_view_.explained : scan_view_.unexplained).push_back(point);
    if (!explained && r <= p_.tracker.range_m) unexplained.push_back(point);
    if (explained && r <= p_.field_range_m) near_static.push_back(point);
  }
  tracker_.update(unexplained, sensor.position(), scan.t_s);
  // The layer remembers what stands: returns on a track that moves are left out of it.
  std::vector<geom::Vec2>& marks = marks_;
  marks.clear();
  const std::vector<controller::MovingBox> tracked = tracker_.boxes(scan.t_s);
  for (const geom::Vec2& q : unexplained) {
    bool on_mover = false;
    for (const auto& b : tracked)
      on_mover |= geom::norm(b.velocity) > p_.moving_speed_mps &&
                  geom::in_closed_rect(b.box.inflated(p_.layer.cell_m), q);
    if (!on_mover) marks.push_back(q);
  }
  layer_.update(scan, sensor, marks);
  layer_rects_ = layer_.occupied();
  // The field feels each connected stretch of the map's surfaces at its nearest point, as it
  // felt each rectangle at its nearest point in oracle mode.
  static_field_.clear();
  for (const auto& cluster : cluster_in_order(near_static, p_.field_cluster_gap_m)) {
    const geom::Vec2* nearest = &cluster[0];
    double nearest_m = geom::distance(*nearest, now_.pose.position());
    for (const geom::Vec2& q : cluster)
      if (const double d = geom::distance(q, now_.pose.position()); d < nearest_m)
        nearest = &q, nearest_m = d;
    static_field_.push_back({{nearest->x, nearest->y, nearest->x, nearest->y}, {0, 0}});
  }
}

void Perceiver::take_readings(const SensorReadings& r) {
  now_.t_s = r.t_s;
  now_.dt_s = r.dt_s;
  now_.odom_pose = r.odom_pose;
  now_.speed_mps = r.odom_speed_mps;
  now_.yaw_rate_radps = r.gyro_yaw_rate_radps;
  now_.charger_contact = r.charger_contact;
  now_.charging = r.charging;
  now_.bumper = r.bumper;
  if (r.scan) now_.scan = r.scan;
  see_free_range(r);
  odom_history_.emplace_back(r.t_s, r.odom_pose);
  while (!odom_history_.empty() && odom_history_.front().first < r.t_s - 2.0)
    odom_history_.pop_front();
}

void Perceiver::see_free_range(const SensorReadings& r) {
  if (r.scan) free_at_scan_m_ = free_range_ahead_m(*r.scan, map_.robot);
  if (!now_.scan) return;
  // The scan is as old as the lidar's period at most; the robot has driven on since.
  const double driven = std::fabs(r.odom_speed_mps) * std::max(0.0, r.t_s - now_.scan->t_s);
  now_.free_ahead_m = std::max(0.0, free_at_scan_m_ - driven);
}

const Perception& Perceiver::update_oracle(const SensorReadings& r) {
  now_.pose = r.oracle->pose_fix.value_or(r.odom_pose);
  now_.obstacles = known_actors(*r.oracle, now_.pose, p_.range_m);
  now_.field = map_near(map_, now_.pose.position(), p_.field_range_m);
  for (const auto& m : now_.obstacles) now_.field.push_back({m.box, m.velocity});
  const std::optional<ChargerDetection> sighted = sight_dock(r);
  now_.charger_in_robot = sighted ? std::optional(sighted->dock_in_robot) : std::nullopt;
  if (r.oracle->target) {
    now_.target = r.oracle->target->box.center();
    now_.target_velocity = r.oracle->target->velocity;
  }
  return now_;
}

bool Perceiver::turn_slipped(const SensorReadings& r) {
  // Slip: the encoders' turn against the gyro's, averaged over a window so that the encoders'
  // noise does not pass for it; or a scan correction beyond what the prediction allows.
  const double encoder_turn = geom::wrap_angle(r.odom_pose.yaw - odom_yaw_before_);
  odom_yaw_before_ = r.odom_pose.yaw;
  if (r.dt_s > 0) {
    const double gap =
        encoder_turn - (r.gyro_yaw_rate_radps - estimator_->gyro_bias_radps()) * r.dt_s;
    turn_gap_.emplace_back(r.dt_s, gap);
    turn_gap_sum_ += gap;
    turn_gap_time_ += r.dt_s;
    while (turn_gap_time_ > p_.slip_window_s + 1e-9 && turn_gap_.size() > 1) {
      turn_gap_sum_ -= turn_gap_.front().second;
      turn_gap_time_ -= turn_gap_.front().first;
      turn_gap_.pop_front();
    }
  }
  return turn_gap_time_ >= 0.5 * p_.slip_window_s &&
         std::fabs(turn_gap_sum_) > p_.slip_turn_radps * turn_gap_time_;
}

void Perceiver::localize(const SensorReadings& r) {
  // Wheels that did not turn at all: the robot stands still and the gyro reads its own bias.
  const bool wheels_still =
      r.dt_s > 0 && r.encoder_distance_m == 0 && r.odom_pose.yaw == odom_yaw_before_;
  if (wheels_still)
    estimator_->standstill(r.gyro_yaw_rate_radps, r.dt_s);
  else
    estimator_->predict(r.encoder_distance_m, r.gyro_yaw_rate_radps, r.dt_s);
  // Moved without the wheels: a contact (the robot never touches anything but the charger's
  // pads, which are not on the bumper), or a scan that pulls the estimate further than its
  // spread allows, or scans the map stops explaining. Widen the estimate so that the next
  // scans can find where it went.
  const geom::Pose2 predicted = estimator_->pose();
  const double predicted_sigma = estimator_->position_sigma_m();
  const int failed_before = estimator_->failed_matches();
  if (r.scan) estimator_->observe(*r.scan);
  const double correction = geom::distance(predicted.position(), estimator_->pose().position());
  // A correction within three sigmas of the prediction is the filter doing its work.
  const bool jumped = correction > std::max(p_.displaced_jump_m, 3.0 * predicted_sigma);
  const bool turn_slip = turn_slipped(r);
  now_.slipping = correction > std::max(p_.slip_jump_m, 3.0 * predicted_sigma) || turn_slip;
  const bool unexplained = estimator_->failed_matches() >= 2;
  const bool became_unexplained = unexplained && failed_before < 2;
  const bool touched = r.bumper.front || r.bumper.rear;
  // Widened once per event (a contact lasting a second must not make the estimate lost).
  if ((touched && !touched_before_) || became_unexplained)
    estimator_->widen(p_.relocalize_sigma_m * (became_unexplained ? 1.0 : 0.3), 0.1);
  touched_before_ = touched;
  // Lost where the scans see the plant but fit it nowhere: stop, look round, match again. (Lost
  // on open ground, with nothing in range, it goes on slowly on odometry towards what it will see.)
  now_.displaced = touched || jumped || unexplained || estimator_->lost_in_view();
}

void Perceiver::publish_estimate() {
  now_.pose = estimator_->pose();
  now_.position_sigma_m = estimator_->position_sigma_m();
  now_.yaw_sigma_rad = estimator_->yaw_sigma_rad();
  now_.health = estimator_->health();
  const Eigen::Matrix3d covariance = estimator_->pose_covariance();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      now_.pose_covariance[static_cast<std::size_t>(3 * i + j)] = covariance(i, j);
}

void Perceiver::follow_target(const SensorReadings& r) {
  // The beacon's fixes, smoothed; the velocity from their change (alpha-beta, as the tracker).
  const geom::Vec2 seen =
      geom::compose(now_.pose, geom::Pose2{r.target_in_robot->x, r.target_in_robot->y, 0})
          .position();
  if (!now_.target || r.dt_s <= 0) {
    now_.target = seen;
  } else {
    const geom::Vec2 predicted = *now_.target + r.dt_s * now_.target_velocity;
    const geom::Vec2 innovation = seen - predicted;
    now_.target = predicted + 0.5 * innovation;
    now_.target_velocity = now_.target_velocity + (0.1 / r.dt_s) * innovation;
  }
}

void Perceiver::publish_obstacles(const SensorReadings& r) {
  if (r.scan) interpret_scan(*r.scan);
  // What stands is the layer's (tight to the returns, remembered); what moves is the tracks'
  // (a standing track's box is a guess about depth and jitters with the face it sees).
  now_.obstacles.clear();
  for (const auto& b : tracker_.boxes(r.t_s))
    if (!p_.layer.enabled || geom::norm(b.velocity) > 0) now_.obstacles.push_back(b);
  now_.layer = layer_rects_;
  for (const geom::Rect& c : layer_rects_) now_.obstacles.push_back({c, {0, 0}});
  // The static returns of the last scan, and the tracked obstacles with their velocities.
  now_.field = static_field_;
  for (const auto& m : now_.obstacles) now_.field.push_back({m.box, m.velocity});
  const std::optional<ChargerDetection> sighted = sight_dock(r);
  now_.charger_in_robot = sighted ? carry_to_now(*sighted) : std::nullopt;
}

const Perception& Perceiver::update(const SensorReadings& r) {
  take_readings(r);
  if (r.oracle) return update_oracle(r);
  localize(r);
  publish_estimate();
  if (r.target_in_robot) follow_target(r);
  publish_obstacles(r);
  return now_;
}

}  // namespace plantsim::robot
