// The battery's equivalent circuit (see the header).
#include "sim/battery_cell.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace plantsim::sim {

BatteryCell::BatteryCell(BatterySpec spec, double state_of_charge)
    : spec_(std::move(spec)), soc_(std::clamp(state_of_charge, 0.0, 1.0)) {
  if (spec_.cell_ocv.size() < 2 || spec_.capacity_ah <= 0 || spec_.series_cells < 1 ||
      spec_.resistance_ohm <= 0)
    throw std::invalid_argument("battery: a capacity, cells, a resistance and an OCV table");
  for (std::size_t i = 1; i < spec_.cell_ocv.size(); ++i)
    if (spec_.cell_ocv[i].first <= spec_.cell_ocv[i - 1].first ||
        spec_.cell_ocv[i].second < spec_.cell_ocv[i - 1].second)
      throw std::invalid_argument("battery: the OCV table must rise with the state of charge");
}

double BatteryCell::open_circuit_v() const {
  const auto& t = spec_.cell_ocv;
  const auto hi = std::upper_bound(t.begin(), t.end(), soc_,
                                   [](double s, const auto& row) { return s < row.first; });
  double cell = 0;
  if (hi == t.begin()) {
    cell = t.front().second;
  } else if (hi == t.end()) {
    cell = t.back().second;
  } else {
    const auto lo = hi - 1;
    const double f = (soc_ - lo->first) / (hi->first - lo->first);
    cell = lo->second + f * (hi->second - lo->second);
  }
  return cell * spec_.series_cells;
}

void BatteryCell::pass(double current_a, double dt_s) {
  soc_ = std::clamp(soc_ - current_a * dt_s / (3600.0 * spec_.capacity_ah), 0.0, 1.0);
}

BatteryStep BatteryCell::discharge(double power_w, double dt_s) {
  BatteryStep s;
  const double v_oc = open_circuit_v();
  const double r = spec_.resistance_ohm;
  const double most = v_oc * v_oc / (4 * r);  // at I = V_oc / 2R, the terminals at V_oc / 2
  const double p = std::max(0.0, power_w);
  if (soc_ <= 0 || p > most) s.brownout = true;
  if (soc_ <= 0) {
    s.terminal_v = v_oc;
    return s;
  }
  const double delivered = std::min(p, most);
  s.current_a = (v_oc - std::sqrt(std::max(0.0, v_oc * v_oc - 4 * r * delivered))) / (2 * r);
  s.terminal_v = v_oc - s.current_a * r;
  pass(s.current_a, dt_s);
  return s;
}

BatteryStep BatteryCell::charge(double dt_s) {
  BatteryStep s;
  const double v_oc = open_circuit_v();
  const double v_cv = spec_.charge_volts_per_cell * spec_.series_cells;
  // CC while the terminals stay below the CV voltage at that current, then CV.
  const double into =
      std::min(spec_.charge_current_a, std::max(0.0, (v_cv - v_oc) / spec_.resistance_ohm));
  s.current_a = -into;
  s.terminal_v = v_oc + into * spec_.resistance_ohm;
  s.charge_done = into < spec_.charge_end_current_a;
  if (!s.charge_done) pass(s.current_a, dt_s);
  return s;
}

}  // namespace plantsim::sim
