// Tyre impulses: the exact impulse to the commanded rigid motion, shared between the tyres
// and limited by each tyre's friction circle.
#include "sim/wheel_drive.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>

namespace plantsim::sim {

WheelDrive::WheelDrive(const worlds::RobotSpec& spec, DriveParams params)
    : spec_(spec), params_(params) {}

void WheelDrive::command(controller::WheelSpeeds target, double dt_s) {
  // A controller that divides by zero must not hand Box2D a NaN (it would poison the world):
  // the motors then brake.
  if (!std::isfinite(target.left_mps) || !std::isfinite(target.right_mps)) target = {0.0, 0.0};
  target = controller::saturate(target, spec_.max_speed_mps);
  const double dv = spec_.max_accel_mps2 * dt_s;
  motors_.left_mps += std::clamp(target.left_mps - motors_.left_mps, -dv, dv);
  motors_.right_mps += std::clamp(target.right_mps - motors_.right_mps, -dv, dv);
}

void WheelDrive::apply(PhysicsWorld& world, double dt_s) {
  b2Body* body = world.robot_body();
  const double m = world.robot_mass(), inertia = world.robot_inertia();
  const b2Rot& q = body->GetTransform().q;  // cos and sin of the yaw, already computed
  const Vec2 fwd{q.c, q.s}, left{-fwd.y, fwd.x};
  const b2Vec2 com = body->GetWorldCenter();
  const b2Vec2 v0 = body->GetLinearVelocity();
  const Vec2 v{v0.x, v0.y};
  const double w = body->GetAngularVelocity();

  // The two wheel speeds fix the whole rigid motion the tyres ask for: forward speed, no
  // sideways speed, and yaw rate. The impulse reaching it exactly, split between the tyres
  // (the lateral part equally: it passes through the axle), then each tyre's share clamped
  // to its friction circle, where the tyre slips.
  const double half = 0.5 * spec_.wheel_base_m;
  const double v_target = 0.5 * (motors_.left_mps + motors_.right_mps);
  const double w_target = (motors_.right_mps - motors_.left_mps) / spec_.wheel_base_m;
  const double j_fwd = m * (v_target - geom::dot(v, fwd));
  const double j_lat = m * (0.0 - geom::dot(v, left));
  const double j_turn = inertia * (w_target - w) / half;  // forward impulse pair giving the torque
  const double max_impulse = params_.tyre_friction * 0.5 * m * params_.gravity_mps2 * dt_s;
  slipping_ = false;
  struct Share {
    double fwd, lat;
    Vec2 r;
  } tyres[2] = {{0.5 * (j_fwd - j_turn), 0.5 * j_lat, half * left},
                {0.5 * (j_fwd + j_turn), 0.5 * j_lat, -half * left}};
  for (Share& t : tyres) {
    const double mag = std::sqrt(t.fwd * t.fwd + t.lat * t.lat);
    if (mag > max_impulse) {
      t.fwd *= max_impulse / mag;
      t.lat *= max_impulse / mag;
      slipping_ = true;
    }
    const Vec2 j = t.fwd * fwd + t.lat * left;
    body->ApplyLinearImpulse(
        b2Vec2(static_cast<float>(j.x), static_cast<float>(j.y)),
        b2Vec2(static_cast<float>(com.x + t.r.x), static_cast<float>(com.y + t.r.y)), true);
  }
}

}  // namespace plantsim::sim
