// The built-in dock detectors (see the header).
#include "robot/dock_detector.h"

namespace plantsim::robot {

namespace {

/// The charger camera's detections as they arrive (their latency already passed).
class CameraDetector : public DockDetector {
 public:
  std::optional<ChargerDetection> detect(const DockDetectorQuery& q) override {
    return q.readings->charger;
  }
};

/// Never sees the charger: the docking goes on the map's placement and the odometry alone.
class NoDetector : public DockDetector {
 public:
  std::optional<ChargerDetection> detect(const DockDetectorQuery&) override { return {}; }
};

template <typename D>
DockDetectorEntry entry(const char* name, const char* summary) {
  DockDetectorEntry e;
  e.name = name;
  e.summary = summary;
  e.make = [](const DockDetectorContext&, const util::ParamValues&) {
    return std::unique_ptr<DockDetector>(std::make_unique<D>());
  };
  return e;
}

}  // namespace

DockDetectorRegistry& dock_detectors() {
  static DockDetectorRegistry* registry = [] {
    auto* r = new DockDetectorRegistry("dock detector");
    r->add(entry<CameraDetector>("camera",
                                 "the charger camera's detections (its noise, range and rate: "
                                 "`detection.*`)"),
           "built-in");
    r->add(entry<NoDetector>("none", "no sighting: docks on the map's charger and the odometry"),
           "built-in");
    return r;
  }();
  return *registry;
}

}  // namespace plantsim::robot
