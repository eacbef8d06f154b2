// The local controller's compute time per control cycle, a referee's metric: the wall time of
// the controller's own step call alone (not the path follower's checks around it, nor
// perception), taken with std::chrono::steady_clock by a wrapper the episode puts around every
// controller the registry entry makes. The wrapper only forwards: the times go to the clock,
// which nothing that decides reads, so a slow or busy machine never changes the trajectory.
// Wall times differ from run to run: records carry them under kWallTimeFields, which every
// comparison of two runs leaves out (episode_json.h).
//
// The same wrapper hands over, when the recorder asks (once a second), what a controller that
// samples trajectories (controller::SketchesTrajectories) weighed at the step just taken, for the
// replay: a copy made after the step, so the controller's own work is unchanged.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "controller/local_controller.h"

namespace plantsim::episode {

class ControllerClock {
 public:
  void add(double seconds) { seconds_.push_back(seconds); }
  /// Asks for a sketch of the next step's trajectories.
  void want_sketch() { sketch_wanted_ = true; }
  bool sketch_wanted() const { return sketch_wanted_; }
  void keep_sketch(controller::TrajectorySketch sketch) {
    sketch_ = std::move(sketch);
    sketch_wanted_ = false;
  }
  /// The sketch kept since the last call, if any.
  std::optional<controller::TrajectorySketch> take_sketch() {
    std::optional<controller::TrajectorySketch> out = std::move(sketch_);
    sketch_.reset();
    return out;
  }
  std::int64_t cycles() const { return static_cast<std::int64_t>(seconds_.size()); }
  /// The nearest-rank q-quantile (0 < q <= 1) of the cycles' times in milliseconds; NaN of none.
  double quantile_ms(double q) const;

 private:
  std::vector<double> seconds_;
  bool sketch_wanted_ = false;
  std::optional<controller::TrajectorySketch> sketch_;
};

/// How much of a sketch is kept: samples, and points along each (the replay's scale).
inline constexpr int kSketchSamples = 8;
inline constexpr int kSketchPoints = 15;

/// `entry` with its factory wrapped: each controller it makes has every step timed on `clock`
/// (which must outlive them). Whatever else the controller is asked is forwarded unchanged.
controller::LocalControllerEntry timed_entry(const controller::LocalControllerEntry& entry,
                                             ControllerClock& clock);

}  // namespace plantsim::episode
