// The battery's equivalent circuit, the drive's power and the gauge (issue 91, first slice),
// checked against hand calculations: the voltage sags by I R under load, a constant power drains
// the charge the current integrates, CC-CV charging holds its current then tapers at the CV
// voltage, a stalled motor draws its copper loss, and a coulomb count drifts with its sensor.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/battery_cell.h"
#include "sim/battery_gauge.h"
#include "sim/drive_power.h"

namespace plantsim::sim {
namespace {

TEST(BatteryCell, TheVoltageFollowsTheChargeAndSagsByIRUnderLoad) {
  BatterySpec spec;
  BatteryCell full(spec, 1.0), half(spec, 0.5), low(spec, 0.05);
  EXPECT_NEAR(full.open_circuit_v(), 7 * 4.20, 1e-12);
  EXPECT_NEAR(half.open_circuit_v(), 7 * 3.72, 1e-12);
  EXPECT_NEAR(BatteryCell(spec, 0.55).open_circuit_v(), 7 * (3.72 + 3.79) / 2, 1e-12);
  EXPECT_GT(full.open_circuit_v(), half.open_circuit_v());
  EXPECT_GT(half.open_circuit_v(), low.open_circuit_v());
  // 240 W from the half-full pack: I solves P = (V - I R) I; the terminals sag by I R.
  const double v = half.open_circuit_v(), r = spec.resistance_ohm;
  const BatteryStep s = half.discharge(240.0, 0.01);
  const double i = (v - std::sqrt(v * v - 4 * r * 240.0)) / (2 * r);
  EXPECT_NEAR(s.current_a, i, 1e-9);
  EXPECT_NEAR(s.terminal_v * s.current_a, 240.0, 1e-6);
  EXPECT_NEAR(v - s.terminal_v, i * r, 1e-9);
  EXPECT_FALSE(s.brownout);
  // More than V^2 / 4R is beyond the pack: it gives its most, and says so.
  BatteryCell asked(spec, 0.5);
  const BatteryStep over = asked.discharge(v * v / (4 * r) * 1.5, 0.01);
  EXPECT_TRUE(over.brownout);
  EXPECT_NEAR(over.current_a, v / (2 * r), 1e-9);
}

TEST(BatteryCell, AConstantPowerDrainsTheChargeItsCurrentCarries) {
  BatterySpec spec;
  BatteryCell cell(spec, 0.9);
  double coulombs = 0;
  for (int k = 0; k < 36000; ++k) coulombs += cell.discharge(120.0, 0.1).current_a * 0.1;  // 1 h
  EXPECT_NEAR(cell.state_of_charge(), 0.9 - coulombs / (3600.0 * spec.capacity_ah), 1e-9);
  // 120 W for an hour from a 24 V-class pack: about 4.5 to 5.5 Ah, a quarter of its charge.
  EXPECT_GT(coulombs / 3600.0, 4.3);
  EXPECT_LT(coulombs / 3600.0, 5.8);
  // Run flat, it browns out and delivers nothing.
  BatteryCell empty(spec, 0.0);
  const BatteryStep s = empty.discharge(50.0, 0.1);
  EXPECT_TRUE(s.brownout);
  EXPECT_EQ(s.current_a, 0.0);
}

TEST(BatteryCell, ChargesAtItsConstantCurrentThenTapersAtTheConstantVoltage) {
  BatterySpec spec;
  BatteryCell cell(spec, 0.2);
  const double v_cv = spec.charge_volts_per_cell * spec.series_cells;
  bool saw_cv = false;
  double t = 0;
  for (; t < 6 * 3600; t += 1.0) {
    const BatteryStep s = cell.charge(1.0);
    ASSERT_LE(s.terminal_v, v_cv + 1e-9);
    ASSERT_LE(-s.current_a, spec.charge_current_a + 1e-12);
    if (-s.current_a < spec.charge_current_a - 1e-9) {
      saw_cv = true;
      EXPECT_NEAR(s.terminal_v, v_cv, 1e-9);  // the CV phase holds the voltage
    } else {
      EXPECT_FALSE(saw_cv) << "the current rose again after the taper began, at " << t;
    }
    if (s.charge_done) break;
  }
  EXPECT_TRUE(saw_cv);
  EXPECT_GT(cell.state_of_charge(), 0.97);
  // 16 Ah at 10 A is 1.6 h of CC; the taper adds less than as much again.
  EXPECT_GT(t, 1.4 * 3600);
  EXPECT_LT(t, 3.2 * 3600);
}

TEST(DrivePower, MotoringDrawsThroughTheEfficienciesAndAStallDrawsItsCopperLoss) {
  DrivePowerSpec spec;
  const double i = 40.0 * spec.wheel_radius_m / spec.torque_constant_nm_per_a;  // 40 N at the rim
  const double copper = i * i * spec.winding_resistance_ohm;
  EXPECT_NEAR(wheel_power_w(spec, 40.0, 0.5),
              40.0 * 0.5 / (spec.motor_efficiency * spec.driver_efficiency) + copper, 1e-12);
  EXPECT_NEAR(wheel_power_w(spec, 40.0, 0.0), copper, 1e-12);   // pushing a wall: heat only
  EXPECT_NEAR(wheel_power_w(spec, -40.0, 0.5), copper, 1e-12);  // braking: no regeneration
  EXPECT_NEAR(robot_power_w(spec, 0, 0, 0, 0), spec.idle_w, 1e-12);
}

TEST(BatteryGauge, ACoulombCountDriftsWithItsCurrentSensor) {
  BatteryCell cell(BatterySpec{}, 1.0);
  BatteryGauge gauge(cell.spec().capacity_ah, 1.0, GaugeErrors{0.02, 0.05});
  for (int k = 0; k < 7200; ++k) gauge.read(cell.discharge(150.0, 1.0).current_a, 1.0);  // 2 h
  const double drift = cell.state_of_charge() - gauge.state_of_charge();
  // It counts 2 % more than flowed plus 0.05 A for 2 h: over-reads the use, under-reads the charge.
  const double used = 1.0 - cell.state_of_charge();
  EXPECT_NEAR(drift, 0.02 * used + 0.05 * 2.0 / cell.spec().capacity_ah, 1e-9);
  gauge.full();
  EXPECT_EQ(gauge.state_of_charge(), 1.0);
}

}  // namespace
}  // namespace plantsim::sim
