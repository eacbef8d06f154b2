// The names of the estimator's health and of the estimator kinds, as records and configs spell
// them.
#include "robot/pose_estimator.h"

namespace plantsim::robot {

std::string_view to_string(LocalizationHealth h) {
  switch (h) {
    case LocalizationHealth::kOk:
      return "ok";
    case LocalizationHealth::kDegraded:
      return "degraded";
    case LocalizationHealth::kLost:
      return "lost";
  }
  return "unknown";
}

std::string_view to_string(EstimatorKind k) {
  // A switch, not a ternary: a third kind without its name does not compile (-Wswitch, -Werror).
  switch (k) {
    case EstimatorKind::kEkf:
      return "ekf";
    case EstimatorKind::kParticles:
      return "particles";
  }
  return "unknown";
}

}  // namespace plantsim::robot
