// Tyre impulses by sequential impulses on the body's velocity, the way Box2D's own contact
// solver works: each pass drives one wheel's longitudinal slip and lateral velocity to zero
// through its effective mass, with the accumulated impulse clamped to the friction circle.
#include "sim/wheel_drive.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>

namespace plantsim::sim {

WheelDrive::WheelDrive(const worlds::RobotSpec& spec, DriveParams params)
    : spec_(spec), params_(params) {}

void WheelDrive::command(controller::WheelSpeeds target, double dt_s) {
  target = controller::saturate(target, spec_.max_speed_mps);
  const double dv = spec_.max_accel_mps2 * dt_s;
  motors_.left_mps += std::clamp(target.left_mps - motors_.left_mps, -dv, dv);
  motors_.right_mps += std::clamp(target.right_mps - motors_.right_mps, -dv, dv);
}

void WheelDrive::apply(PhysicsWorld& world, double dt_s) {
  b2Body* body = world.robot_body();
  const double m = world.robot_mass(), inertia = world.robot_inertia();
  const double yaw = body->GetAngle();
  const Vec2 fwd{std::cos(yaw), std::sin(yaw)}, left{-fwd.y, fwd.x};
  const b2Vec2 com = body->GetWorldCenter();
  const b2Vec2 v0 = body->GetLinearVelocity();
  Vec2 v{v0.x, v0.y};
  double w = body->GetAngularVelocity();

  struct Tyre {
    Vec2 r;          // from the centre of mass to the contact point
    double target;   // motor rim speed
    Vec2 impulse;    // accumulated this step
  };
  const double half = 0.5 * spec_.wheel_base_m;
  Tyre tyres[2] = {{half * left, motors_.left_mps, {}}, {-half * left, motors_.right_mps, {}}};
  const double max_impulse = params_.tyre_friction * 0.5 * m * params_.gravity_mps2 * dt_s;
  auto effective_mass = [&](Vec2 r, Vec2 dir) {
    const double rn = geom::cross(r, dir);
    return 1.0 / (1.0 / m + rn * rn / inertia);
  };
  slipping_ = false;
  for (int it = 0; it < params_.solver_iterations; ++it) {
    for (Tyre& t : tyres) {
      const Vec2 vp = v + Vec2{-w * t.r.y, w * t.r.x};
      const double dl = effective_mass(t.r, fwd) * (t.target - geom::dot(vp, fwd));
      const double dn = effective_mass(t.r, left) * (-geom::dot(vp, left));
      Vec2 total = t.impulse + dl * fwd + dn * left;
      const double mag = geom::norm(total);
      if (mag > max_impulse) {
        total = (max_impulse / mag) * total;
        slipping_ = true;
      }
      const Vec2 delta = total - t.impulse;
      t.impulse = total;
      v = v + (1.0 / m) * delta;
      w += geom::cross(t.r, delta) / inertia;
    }
  }
  for (const Tyre& t : tyres)
    body->ApplyLinearImpulse(b2Vec2(static_cast<float>(t.impulse.x), static_cast<float>(t.impulse.y)),
                             b2Vec2(static_cast<float>(com.x + t.r.x), static_cast<float>(com.y + t.r.y)),
                             true);
}

}  // namespace plantsim::sim
