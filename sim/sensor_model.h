// Sensor models: each turns the simulator's truth into its part of the readings the robot gets
// (robot/readings.h), and the registry lists them in the order the suite reads them. A new sensor
// (an ultrasonic ring) is its model here, one entry in sim/sensor_models.cpp, its field in
// robot/readings.h and the one consumer on the robot's side that reads it. The truth a model is
// handed never leaves sim/ but as a reading.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>

#include "robot/readings.h"
#include "sim/charger_detector.h"
#include "sim/charger_pads.h"
#include "sim/imu.h"
#include "sim/lidar.h"
#include "sim/localization.h"
#include "sim/odometry.h"
#include "sim/physics_world.h"
#include "sim/wheel_drive.h"
#include "util/component_info.h"
#include "util/component_registry.h"
#include "worlds/world.h"

namespace plantsim::sim {

/// The moving target's beacon (a UWB tag it carries): its centre relative to the robot.
struct BeaconParams {
  double position_noise_m = 0.05;  ///< std-dev per axis
};

/// Every sensor's datasheet and noise, as the configuration sets them (lidar.*, imu.*, ...).
struct SensorParams {
  bool oracle = false;  ///< perception mode "oracle"
  LidarParams lidar;
  ImuParams imu;
  DetectionParams detection;
  OdometryNoise odometry;
  LocalizationParams oracle_fix;  ///< oracle mode's noisy truth fixes
  BeaconParams beacon;
  ChargerPadParams pads;  ///< travel set from the plant's charger
};

/// What a model reads at a control step: the physics and the robot's true pose now.
struct SensorTruth {
  const PhysicsWorld* physics = nullptr;
  geom::Pose2 robot;
  double t_s = 0;
  double dt_s = 0;  ///< since the previous reading
};

class SensorModel {
 public:
  virtual ~SensorModel() = default;
  /// One physics step (encoders count, contacts latch); most models need nothing.
  virtual void count(const PhysicsWorld&, const ContactState&, const WheelDrive&, double) {}
  /// The robot was put elsewhere by a fault (a kidnap is a teleport, no motion).
  virtual void placed(const geom::Pose2&) {}
  /// Writes its part of `out` (models earlier in the registry have written theirs).
  virtual void read(const SensorTruth& truth, robot::SensorReadings& out) = 0;
};

/// What a model is built from: the plant, the sensors' parameters (oracle mode's already
/// applied) and the episode's seed (each model draws from its own stream of it).
struct SensorContext {
  const worlds::World* plant = nullptr;
  const SensorParams* params = nullptr;
  std::uint64_t seed = 0;
};

/// A model; `make` returns null when the configuration fits no such sensor (oracle mode's fix
/// in sensors mode).
struct SensorModelEntry : util::ComponentInfo {
  std::function<std::unique_ptr<SensorModel>(const SensorContext&)> make;
};

using SensorModelRegistry = util::ComponentRegistry<SensorModelEntry>;

/// The built-in models in reading order: odometry, gyro, lidar, charger camera, bumper, charger
/// pads, beacon, oracle fix.
SensorModelRegistry& sensor_models();

}  // namespace plantsim::sim
