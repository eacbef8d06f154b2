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

}  // namespace plantsim::robot
