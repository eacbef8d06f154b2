// The robot's battery as an equivalent circuit (issue 91, first slice): a pack of Li-ion cells
// in series whose open-circuit voltage follows the state of charge (a table of a typical NMC
// cell), behind one series resistance, so that the terminal voltage sags under load and rises
// while charging; charged constant-current then constant-voltage (CC-CV) as a charger does. The
// truth: what the robot side may see of it is the pack's voltage and current (and a coulomb
// count with its own error, battery_gauge.h), never the state of charge itself.
//
// Where it departs from a real cell: no temperature, no ageing, no relaxation (an RC pair's
// recovery after load), one resistance at every state of charge and current.
#pragma once

#include <utility>
#include <vector>

namespace plantsim::sim {

struct BatterySpec {
  double capacity_ah = 20.0;     ///< a 24 V, 20 Ah pack, as inspection robots of this size carry
  int series_cells = 7;          ///< 7S NMC: 29.4 V full, 21 V empty
  double resistance_ohm = 0.08;  ///< the pack's series resistance (cells, wiring, fuse)
  /// Open-circuit voltage of one cell by state of charge (0 to 1, rising), a typical NMC curve.
  std::vector<std::pair<double, double>> cell_ocv = {
      {0.00, 3.00}, {0.05, 3.30}, {0.10, 3.45}, {0.20, 3.55}, {0.30, 3.62}, {0.40, 3.67},
      {0.50, 3.72}, {0.60, 3.79}, {0.70, 3.88}, {0.80, 3.97}, {0.90, 4.07}, {1.00, 4.20}};
  double charge_current_a = 10.0;      ///< the charger's constant current (0.5 C)
  double charge_volts_per_cell = 4.2;  ///< its constant voltage
  double charge_end_current_a = 0.5;   ///< it stops when the CV current falls below this
};

/// What one step of the battery did.
struct BatteryStep {
  double current_a = 0;  ///< positive discharging, negative charging
  double terminal_v = 0;
  bool brownout = false;  ///< the load asked more power than the pack can give (it gave its most)
  bool charge_done = false;  ///< the CV phase tapered below the end current
};

class BatteryCell {
 public:
  explicit BatteryCell(BatterySpec spec, double state_of_charge = 1.0);

  double state_of_charge() const { return soc_; }
  /// The pack's open-circuit voltage now.
  double open_circuit_v() const;
  /// Its terminal voltage while `current_a` flows (positive discharging).
  double terminal_v(double current_a) const {
    return open_circuit_v() - current_a * spec_.resistance_ohm;
  }

  /// Delivers `power_w` (W at the terminals; 0 or more) for `dt_s`: the current that gives it
  /// (the smaller root of P = (V_oc - I R) I); a pack empty or asked more than V_oc^2 / 4R gives
  /// what it can and says brownout.
  BatteryStep discharge(double power_w, double dt_s);
  /// Charges for `dt_s` from a CC-CV charger: the constant current until the terminal voltage
  /// reaches the constant voltage, then what that voltage drives through the resistance.
  BatteryStep charge(double dt_s);

  const BatterySpec& spec() const { return spec_; }

 private:
  void pass(double current_a, double dt_s);  ///< the charge moved, coulomb by coulomb
  BatterySpec spec_;
  double soc_;
};

}  // namespace plantsim::sim
