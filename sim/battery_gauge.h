// What the robot side may know of its battery (issue 91, first slice): the pack's voltage and
// current as its monitor reads them, and a coulomb count integrated from that current, which
// drifts with the current sensor's gain and offset errors, as a fuel gauge's does. Never the
// state of charge: a robot that trusts its voltage alone reads a sag under load as an empty pack.
#pragma once

namespace plantsim::sim {

struct GaugeErrors {
  double current_gain = 0.01;      ///< the current sensor reads (1 + gain) times the truth
  double current_offset_a = 0.02;  ///< plus this
};

class BatteryGauge {
 public:
  BatteryGauge(double capacity_ah, double believed_state_of_charge, GaugeErrors errors)
      : capacity_ah_(capacity_ah), soc_(believed_state_of_charge), errors_(errors) {}

  /// One step's reading of the true current (positive discharging); returns the current read.
  double read(double true_current_a, double dt_s) {
    const double read_a = (1 + errors_.current_gain) * true_current_a + errors_.current_offset_a;
    soc_ -= read_a * dt_s / (3600.0 * capacity_ah_);
    return read_a;
  }
  /// The count's state of charge (may leave [0, 1]: a count does not know it drifted).
  double state_of_charge() const { return soc_; }
  /// A full charge confirmed by the charger resets the count, as gauges do at end of charge.
  void full() { soc_ = 1.0; }

 private:
  double capacity_ah_;
  double soc_;
  GaugeErrors errors_;
};

}  // namespace plantsim::sim
