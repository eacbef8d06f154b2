// Dock detectors (`docking.detector`): what turns the robot's readings into a sighting of the
// charger, the docked pose in the robot frame at the moment the data was captured. The docking
// manoeuvre blends each sighting into its dock estimate (controller/dock_pose_filter.h); without
// one it docks on the map's placement and the odometry. Built-ins: "camera" (the charger camera's
// detections, `detection.*`), "none"; a plugin adds its own (e.g. one fitting the charger's face
// in the lidar scan). Installed for plugins: a detector sees readings and the map, never the
// simulator.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "geometry/vec2.h"
#include "robot/readings.h"
#include "util/component_info.h"
#include "util/component_registry.h"

namespace plantsim::robot {

/// What a detector is asked every control period.
struct DockDetectorQuery {
  const SensorReadings* readings = nullptr;  ///< this period's (a scan when one was taken)
  /// Where the robot's map puts the docked pose, seen from the estimated pose: a prior that is
  /// as wrong as the map's charger placement and the estimate.
  geom::Pose2 expected_dock_in_robot;
  geom::Pose2 estimate;  ///< the robot's estimated pose (map frame)
};

class DockDetector {
 public:
  virtual ~DockDetector() = default;
  /// A sighting (captured_s: when its data was taken, for the carry to now), or none.
  virtual std::optional<ChargerDetection> detect(const DockDetectorQuery& query) = 0;
};

/// What a detector is built for: the charger as the robot's map gives it.
struct DockDetectorContext {
  geom::Pose2 mapped_dock;        ///< the docked pose on the robot's map
  double charger_width_m = 0;     ///< the charger's face, across
  std::vector<geom::Rect> boxes;  ///< the map's boxes and the charger's block
};

struct DockDetectorEntry : util::ComponentInfo {
  std::function<std::unique_ptr<DockDetector>(const DockDetectorContext&, const util::ParamValues&)>
      make;
};

using DockDetectorRegistry = util::ComponentRegistry<DockDetectorEntry>;

/// The registry, the built-ins added on first use.
DockDetectorRegistry& dock_detectors();

inline constexpr const char* kDefaultDockDetector = "camera";

}  // namespace plantsim::robot
