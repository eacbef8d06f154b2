// The charger's own signal. Its contact pads sit on springs in front of the charger's rigid
// face: they touch the robot's contacts once its centre comes within half the spring travel of
// the docked pose, and report charging only after being pressed (at least `min_press_m`) with
// the robot within the pads' tolerance, without a break, for the dwell time. This is the only
// "docked" signal the robot gets; it reads the plant's truth because it is the plant's hardware.
#pragma once

#include "geometry/vec2.h"

namespace plantsim::sim {

struct ChargerPadParams {
  double travel_m = 0.005;  ///< spring travel; the rigid face sits half of it past the docked pose
  double min_press_m = 0.001;         ///< pressed at least this far to count
  double lateral_tolerance_m = 0.02;  ///< robot centre this close to the approach axis ...
  double heading_tolerance_rad =
      2.0 * M_PI / 180.0;        ///< ... and heading this close to the charger's
  double dwell_s = 0.5;          ///< pressed within tolerance this long before charging
  double contact_width_m = 0.2;  ///< the pads' width: off-axis farther than half of it, no touch
  /// The pads are a thin slab in front of the rigid face: a robot whose centre lies farther past
  /// the face than this is not pressing them but standing behind the charger (in the next
  /// corridor, across the wall), where it must never charge. Box2D lets a body sink a few mm.
  double max_overtravel_m = 0.02;
};

class ChargerPads {
 public:
  explicit ChargerPads(ChargerPadParams p) : p_(p) {}
  /// One physics step: where the robot's centre is, and the docked pose of the real charger.
  void step(const geom::Pose2& robot, const geom::Pose2& docked, double dt_s);
  bool touched() const { return touched_; }    ///< the pads touch the robot's contacts
  bool charging() const { return charging_; }  ///< the charger reports charging
  const ChargerPadParams& params() const { return p_; }

 private:
  ChargerPadParams p_;
  bool touched_ = false;
  bool charging_ = false;
  double pressed_for_s_ = 0;
};

}  // namespace plantsim::sim
