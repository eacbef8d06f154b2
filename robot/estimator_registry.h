// The pose estimators by name (`localization.estimator`): the built-ins ("ekf", the default, and
// "particles") and whatever plugins add (plugins/plugin_loader.h). A new built-in is its files
// and one line in the .cpp. An estimator is built from the robot's map and its own parameters,
// never the simulator's truth.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "geometry/vec2.h"
#include "robot/pose_estimator.h"
#include "util/component_info.h"
#include "util/component_registry.h"

namespace plantsim::worlds {
struct World;
}

namespace plantsim::robot {

class MapRaycaster;
struct PerceptionParams;

/// What an estimator is built for: the robot's map (where it starts, the floor inside the walls,
/// the boxes it knows). The last three are the built-ins' own, opaque to a plugin (which gets its
/// parameters as ParamValues).
struct EstimatorContext {
  geom::Pose2 start;  ///< where the robot starts, known (map frame)
  geom::Rect floor;
  std::vector<geom::Rect> obstacles;  ///< the map's boxes and the charger's block
  const worlds::World* map = nullptr;
  const MapRaycaster* raycaster = nullptr;
  const PerceptionParams* perception = nullptr;
};

struct EstimatorEntry : util::ComponentInfo {
  std::function<std::unique_ptr<PoseEstimator>(const EstimatorContext&, const util::ParamValues&)>
      make;
};

using EstimatorRegistry = util::ComponentRegistry<EstimatorEntry>;

/// The registry, the built-ins added on first use.
EstimatorRegistry& estimators();

inline constexpr const char* kDefaultEstimator = "ekf";

}  // namespace plantsim::robot
