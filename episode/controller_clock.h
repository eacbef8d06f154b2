// The local controller's compute time per control cycle, a referee's metric: the wall time of
// the controller's own step call alone (not the path follower's checks around it, nor
// perception), taken with std::chrono::steady_clock by a wrapper the episode puts around every
// controller the registry entry makes. The wrapper only forwards: the times go to the clock,
// which nothing that decides reads, so a slow or busy machine never changes the trajectory.
// Wall times differ from run to run: records carry them under kWallTimeFields, which every
// comparison of two runs leaves out (episode_json.h).
#pragma once

#include <cstdint>
#include <vector>

#include "controller/local_controller.h"

namespace plantsim::episode {

class ControllerClock {
 public:
  void add(double seconds) { seconds_.push_back(seconds); }
  std::int64_t cycles() const { return static_cast<std::int64_t>(seconds_.size()); }
  /// The nearest-rank q-quantile (0 < q <= 1) of the cycles' times in milliseconds; NaN of none.
  double quantile_ms(double q) const;

 private:
  std::vector<double> seconds_;
};

/// `entry` with its factory wrapped: each controller it makes has every step timed on `clock`
/// (which must outlive them). Whatever else the controller is asked is forwarded unchanged.
controller::LocalControllerEntry timed_entry(const controller::LocalControllerEntry& entry,
                                             ControllerClock& clock);

}  // namespace plantsim::episode
