// The differential drive's physics: two motors whose rim speeds follow the commands through
// acceleration and speed limits, and two tyres that push the body through impulses at the
// wheel contact points. Each tyre grips along and across its axis up to a friction circle
// (mu * normal load), so a hard turn at speed skids and a blocked robot spins its wheels.
#pragma once

#include "controller/diff_drive.h"
#include "sim/physics_world.h"

namespace plantsim::sim {

struct DriveParams {
  double tyre_friction = 0.8;  ///< mu between tyre and floor
  double gravity_mps2 = 9.81;
};

class WheelDrive {
 public:
  WheelDrive(const worlds::RobotSpec& spec, DriveParams params);

  /// Moves the motor speeds toward the command within the acceleration and speed limits.
  void command(controller::WheelSpeeds target, double dt_s);

  /// Applies this step's tyre impulses to the robot body (before PhysicsWorld::step).
  void apply(PhysicsWorld& world, double dt_s);

  /// Rim speeds the motors turn at: what wheel encoders measure.
  controller::WheelSpeeds motor_speeds() const { return motors_; }

  /// True when the last step needed more grip than the tyres have.
  bool slipping() const { return slipping_; }

 private:
  worlds::RobotSpec spec_;
  DriveParams params_;
  controller::WheelSpeeds motors_;
  bool slipping_ = false;
};

}  // namespace plantsim::sim
