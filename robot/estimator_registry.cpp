// The built-in estimators, one entry each. Their parameters keep the sections they always had
// ("ekf", "particles", "perception"'s global match) and are read there, typed, by the
// configuration; a plugin's come as ParamValues from its own section.
#include "robot/estimator_registry.h"

#include "robot/ekf_estimator.h"
#include "robot/particle_localizer.h"
#include "robot/robot_param_rows.h"

namespace plantsim::robot {

namespace {

EstimatorEntry ekf_entry() {
  EstimatorEntry e;
  e.name = "ekf";
  e.summary =
      "extended Kalman filter on odometry, gyro and scan matching, with global scan "
      "matching to recover";
  e.params = util::specs_of(ekf_param_rows());
  e.make = [](const EstimatorContext& c,
              const util::ParamValues&) -> std::unique_ptr<PoseEstimator> {
    return std::make_unique<EkfEstimator>(*c.map, *c.raycaster, c.perception->ekf,
                                          c.perception->global);
  };
  return e;
}

EstimatorEntry particles_entry() {
  EstimatorEntry e;
  e.name = "particles";
  e.summary = "adaptive (KLD) Monte Carlo localisation as AMCL does it, likelihood-field model";
  e.params = util::specs_of(particle_param_rows());
  e.capabilities = {"multi-hypothesis"};
  e.make = [](const EstimatorContext& c,
              const util::ParamValues&) -> std::unique_ptr<PoseEstimator> {
    return std::make_unique<ParticleLocalizer>(*c.map, *c.raycaster, c.perception->ekf,
                                               c.perception->global, c.perception->particles);
  };
  return e;
}

}  // namespace

EstimatorRegistry& estimators() {
  static EstimatorRegistry* registry = [] {
    auto* r = new EstimatorRegistry("estimator");  // never destroyed: plugins' entries outlive main
    r->add(ekf_entry(), "built-in");
    r->add(particles_entry(), "built-in");
    return r;
  }();
  return *registry;
}

}  // namespace plantsim::robot
