// Reading the sensors from the physics.
#include "sim/sensor_suite.h"

#include <cmath>

namespace plantsim::sim {

using robot::OracleReadings;
using robot::SensorReadings;

namespace {

SensorParams effective(SensorParams p) {
  if (p.oracle) {
    // The comparison mode of old: no lidar, a detector that sees through everything and never errs.
    p.lidar.enabled = false;
    p.detection.occlusion = false;
    p.detection.false_negative_probability = 0;
    p.detection.outlier_probability = 0;
    p.detection.latency_s = 0;
    p.detection.rate_hz = 1e9;
  }
  return p;
}

}  // namespace

SensorSuite::SensorSuite(const worlds::World& plant, const SensorParams& params, std::uint64_t seed)
    : plant_(plant),
      p_(effective(params)),
      odometry_(plant.start, plant.robot.wheel_base_m, params.odometry, seed),
      imu_(p_.imu, seed),
      lidar_(p_.lidar, seed),
      detector_(p_.detection, seed),
      oracle_fix_(p_.oracle_fix, seed),
      pads_(p_.pads),
      noise_(seed ^ 0x2545f4914f6cdd1dULL),
      last_odom_(plant.start),
      last_yaw_(plant.start.yaw),
      charger_marker_(worlds::charger_body(plant).center) {}

void SensorSuite::count(const PhysicsWorld& physics, const ContactState& c, const WheelDrive& drive,
                        double dt_s) {
  odometry_.count(drive.motor_speeds(), dt_s);
  contact_points_.insert(contact_points_.end(), c.obstacle_points.begin(), c.obstacle_points.end());
  // The charger's own signal, from its pads: touched, then charging after the dwell.
  pads_.step(physics.robot_pose(), plant_.charger, dt_s);
  contact_ = contact_ || pads_.touched();
  charging_ = pads_.charging();
}

SensorReadings SensorSuite::read(const PhysicsWorld& physics, double t_s) {
  const geom::Pose2 truth = physics.robot_pose();
  SensorReadings r;
  r.t_s = t_s;
  r.dt_s = t_s - last_read_s_;
  last_read_s_ = t_s;
  odometry_.read();
  r.odom_pose = odometry_.pose();
  r.odom_speed_mps = odometry_.speed_mps();
  // Travel along the heading since the last reading, from the dead-reckoned poses.
  const geom::Pose2 step = geom::compose(geom::inverse(last_odom_), r.odom_pose);
  r.encoder_distance_m = step.x;
  last_odom_ = r.odom_pose;
  // The gyro's rate over the control period: its heading increment, as a MEMS gyro's driver
  // integrates it from samples at a kilohertz. Sampled once per period instead, a rate that
  // oscillates from step to step (a wheel that sticks and slips on a wet floor) would alias into
  // a steady error, which the estimator would learn as the gyro's bias.
  const double true_rate =
      r.dt_s > 0 ? geom::wrap_angle(truth.yaw - last_yaw_) / r.dt_s : physics.robot_yaw_rate();
  last_yaw_ = truth.yaw;
  r.gyro_yaw_rate_radps = imu_.read_yaw_rate(true_rate, r.dt_s);
  if (lidar_.due(t_s)) r.scan = lidar_.scan(physics, truth, t_s);
  r.charger = detector_.update(physics, truth, plant_.charger, charger_marker_, t_s);
  r.bumper = read_bumper(contact_points_, truth);
  contact_points_.clear();
  r.charger_contact = contact_;
  r.charging = charging_;
  contact_ = charging_ = false;
  if (const auto target = physics.target()) {
    const geom::Vec2 rel = geom::rotate(target->box.center() - truth.position(), -truth.yaw);
    r.target_in_robot = rel + geom::Vec2{p_.beacon.position_noise_m * noise_.gaussian(),
                                         p_.beacon.position_noise_m * noise_.gaussian()};
  }
  if (p_.oracle) {
    OracleReadings o;
    oracle_fix_.update(t_s, r.odom_pose, truth);
    o.pose_fix = oracle_fix_.map_pose(r.odom_pose);
    o.truth = truth;
    o.actors = physics.actors();
    o.target = physics.target();
    if (const auto target = physics.target())
      r.target_in_robot = geom::rotate(target->box.center() - truth.position(), -truth.yaw);
    r.oracle = std::move(o);
  }
  return r;
}

}  // namespace plantsim::sim
