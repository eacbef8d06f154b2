// Reading the sensors from the physics: every registered model, in the registry's order.
#include "sim/sensor_suite.h"

namespace plantsim::sim {

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
    : p_(effective(params)) {
  const SensorContext context{&plant, &p_, seed};
  for (const SensorModelEntry* e : sensor_models().entries())
    if (std::unique_ptr<SensorModel> m = e->make(context)) models_.push_back(std::move(m));
}

void SensorSuite::robot_placed(const geom::Pose2& pose) {
  for (auto& m : models_) m->placed(pose);
}

void SensorSuite::count(const PhysicsWorld& physics, const ContactState& c, const WheelDrive& drive,
                        double dt_s) {
  for (auto& m : models_) m->count(physics, c, drive, dt_s);
}

SensorReadings SensorSuite::read(const PhysicsWorld& physics, double t_s) {
  SensorReadings r;
  r.t_s = t_s;
  r.dt_s = t_s - last_read_s_;
  last_read_s_ = t_s;
  const SensorTruth truth{&physics, physics.robot_pose(), t_s, r.dt_s};
  for (auto& m : models_) m->read(truth, r);
  return r;
}

}  // namespace plantsim::sim
