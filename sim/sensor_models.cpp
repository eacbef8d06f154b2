// The built-in sensor models (sim/sensor_model.h): each an adapter from the truth to its part of
// the readings, in the order the registry reads them.
#include "sim/bumper.h"
#include "sim/sensor_model.h"
#include "util/random_stream.h"

namespace plantsim::sim {

namespace {

/// The wheel encoders: travel counted every physics step, integrated into the dead-reckoned pose
/// at each reading; the travel along the heading since the last reading.
class OdometryModel : public SensorModel {
 public:
  explicit OdometryModel(const SensorContext& c)
      : odometry_(c.plant->start, c.plant->robot.wheel_base_m, c.params->odometry, c.seed),
        last_(c.plant->start) {}
  void count(const PhysicsWorld&, const ContactState&, const WheelDrive& drive,
             double dt_s) override {
    odometry_.count(drive.motor_speeds(), dt_s);
  }
  void read(const SensorTruth&, robot::SensorReadings& r) override {
    odometry_.read();
    r.odom_pose = odometry_.pose();
    r.odom_speed_mps = odometry_.speed_mps();
    r.encoder_distance_m = geom::compose(geom::inverse(last_), r.odom_pose).x;
    last_ = r.odom_pose;
  }

 private:
  Odometry odometry_;
  geom::Pose2 last_;
};

/// The gyro's rate over the control period: its heading increment, as a MEMS gyro's driver
/// integrates it from samples at a kilohertz. Sampled once per period instead, a rate that
/// oscillates from step to step (a wheel that sticks and slips on a wet floor) would alias into
/// a steady error, which the estimator would learn as the gyro's bias.
class GyroModel : public SensorModel {
 public:
  explicit GyroModel(const SensorContext& c)
      : imu_(c.params->imu, c.seed), last_yaw_(c.plant->start.yaw) {}
  void placed(const geom::Pose2& pose) override { last_yaw_ = pose.yaw; }  // it felt no turn
  void read(const SensorTruth& t, robot::SensorReadings& r) override {
    const double true_rate = t.dt_s > 0 ? geom::wrap_angle(t.robot.yaw - last_yaw_) / t.dt_s
                                        : t.physics->robot_yaw_rate();
    last_yaw_ = t.robot.yaw;
    r.gyro_yaw_rate_radps = imu_.read_yaw_rate(true_rate, t.dt_s);
  }

 private:
  Imu imu_;
  double last_yaw_;  // the body's true heading at the last reading
};

class LidarModel : public SensorModel {
 public:
  explicit LidarModel(const SensorContext& c) : lidar_(c.params->lidar, c.seed) {}
  void read(const SensorTruth& t, robot::SensorReadings& r) override {
    if (lidar_.due(t.t_s)) r.scan = lidar_.scan(*t.physics, t.robot, t.t_s);
  }

 private:
  Lidar lidar_;
};

class ChargerCameraModel : public SensorModel {
 public:
  explicit ChargerCameraModel(const SensorContext& c)
      : detector_(c.params->detection, c.seed),
        docked_(c.plant->charger),
        marker_(worlds::charger_body(*c.plant).center) {}
  void read(const SensorTruth& t, robot::SensorReadings& r) override {
    r.charger = detector_.update(*t.physics, t.robot, docked_, marker_, t.t_s);
  }

 private:
  ChargerDetector detector_;
  geom::Pose2 docked_;  // the real charger's docked pose
  geom::Vec2 marker_;
};

/// The bumper strip: where the robot touched something since the last reading.
class BumperModel : public SensorModel {
 public:
  explicit BumperModel(const SensorContext&) {}
  void count(const PhysicsWorld&, const ContactState& c, const WheelDrive&, double) override {
    points_.insert(points_.end(), c.obstacle_points.begin(), c.obstacle_points.end());
  }
  void read(const SensorTruth& t, robot::SensorReadings& r) override {
    r.bumper = read_bumper(points_, t.robot);
    points_.clear();
  }

 private:
  std::vector<geom::Vec2> points_;
};

/// The charger's own signal, from its pads: touched, then charging after the dwell (latched
/// between readings).
class ChargerPadsModel : public SensorModel {
 public:
  explicit ChargerPadsModel(const SensorContext& c)
      : pads_(c.params->pads), docked_(c.plant->charger) {}
  void count(const PhysicsWorld& physics, const ContactState&, const WheelDrive&,
             double dt_s) override {
    pads_.step(physics.robot_pose(), docked_, dt_s);
    contact_ = contact_ || pads_.touched();
    charging_ = pads_.charging();
  }
  void read(const SensorTruth&, robot::SensorReadings& r) override {
    r.charger_contact = contact_;
    r.charging = charging_;
    contact_ = charging_ = false;
  }

 private:
  ChargerPads pads_;
  geom::Pose2 docked_;
  bool contact_ = false, charging_ = false;
};

class BeaconModel : public SensorModel {
 public:
  explicit BeaconModel(const SensorContext& c)
      : p_(c.params->beacon), noise_(c.seed ^ 0x2545f4914f6cdd1dULL) {}
  void read(const SensorTruth& t, robot::SensorReadings& r) override {
    if (const auto target = t.physics->target()) {
      const geom::Vec2 rel = geom::rotate(target->box.center() - t.robot.position(), -t.robot.yaw);
      r.target_in_robot = rel + geom::Vec2{p_.position_noise_m * noise_.gaussian(),
                                           p_.position_noise_m * noise_.gaussian()};
    }
  }

 private:
  BeaconParams p_;
  util::RandomStream noise_;
};

/// Oracle mode's hand-over of the truth (the comparison mode of old), after the odometry it
/// fixes: the noisy truth fix, the actors, the target exactly.
class OracleModel : public SensorModel {
 public:
  explicit OracleModel(const SensorContext& c) : fix_(c.params->oracle_fix, c.seed) {}
  void read(const SensorTruth& t, robot::SensorReadings& r) override {
    robot::OracleReadings o;
    fix_.update(t.t_s, r.odom_pose, t.robot);
    o.pose_fix = fix_.map_pose(r.odom_pose);
    o.truth = t.robot;
    o.actors = t.physics->actors();
    o.target = t.physics->target();
    if (o.target)
      r.target_in_robot = geom::rotate(o.target->box.center() - t.robot.position(), -t.robot.yaw);
    r.oracle = std::move(o);
  }

 private:
  Localization fix_;
};

template <typename M>
SensorModelEntry model(const char* name, const char* summary) {
  SensorModelEntry e;
  e.name = name;
  e.summary = summary;
  e.make = [](const SensorContext& c) {
    return std::unique_ptr<SensorModel>(std::make_unique<M>(c));
  };
  return e;
}

}  // namespace

SensorModelRegistry& sensor_models() {
  static SensorModelRegistry* registry = [] {
    auto* r = new SensorModelRegistry("sensor model");
    const std::string b = "built-in";
    r->add(model<OdometryModel>("odometry", "wheel encoders, dead reckoning (odometry.*)"), b);
    r->add(model<GyroModel>("gyro", "yaw rate with noise, bias and its walk (imu.*)"), b);
    r->add(model<LidarModel>("lidar", "2D scan cast against the physics' shapes (lidar.*)"), b);
    r->add(model<ChargerCameraModel>("charger-camera",
                                     "the charger's docked pose, seen (detection.*)"),
           b);
    r->add(model<BumperModel>("bumper", "front and rear contact strips"), b);
    r->add(model<ChargerPadsModel>("charger-pads", "contact and charging signal (tolerance.*)"), b);
    r->add(model<BeaconModel>("beacon", "a moving target's UWB tag (beacon.*)"), b);
    SensorModelEntry oracle = model<OracleModel>("oracle", "perception mode oracle's truth fix");
    oracle.make = [](const SensorContext& c) {
      return c.params->oracle ? std::unique_ptr<SensorModel>(std::make_unique<OracleModel>(c))
                              : nullptr;
    };
    r->add(std::move(oracle), b);
    return r;
  }();
  return *registry;
}

}  // namespace plantsim::sim
