// Building and stepping the Box2D world.
#include "sim/physics_world.h"

#include <box2d/box2d.h>

#include <cmath>
#include <limits>

#include "sim/box2d_scene.h"
#include "sim/box2d_step_timers.h"

namespace plantsim::sim {

using robot::ActorState;

using detail::FixtureTag;
using detail::kCharger;
using detail::kMoving;
using detail::kObstacle;
using detail::kRobot;
using detail::kTarget;
using detail::kWall;
using detail::tag_of;

PhysicsWorld::PhysicsWorld(const worlds::World& w)
    : world_(std::make_unique<b2World>(b2Vec2(0, 0))),
      surfaces_(w),
      robot_radius_m_(w.robot.radius_m) {
  // Names the timers' file, so that every program stepping a world links plantsim's b2Timer.
  static_cast<void>(box2d_step_timers());
  detail::add_static_scene(*world_, w);

  for (const worlds::MovingObstacle& m : w.moving) moving_.push_back(make_actor(m, false));
  if (w.target) target_ = make_actor(*w.target, true);

  b2BodyDef robot_def;
  robot_def.type = b2_dynamicBody;
  robot_def.position.Set(static_cast<float>(w.start.x), static_cast<float>(w.start.y));
  robot_def.angle = static_cast<float>(w.start.yaw);
  robot_def.bullet = false;
  robot_ = world_->CreateBody(&robot_def);
  b2CircleShape disk;
  disk.m_radius = static_cast<float>(w.robot.radius_m);
  b2PolygonShape box;
  // The box is shrunk by Box2D's polygon skin so that its contact surface is the footprint.
  box.SetAsBox(static_cast<float>(0.5 * w.robot.length_m - b2_polygonRadius),
               static_cast<float>(0.5 * w.robot.width_m - b2_polygonRadius));
  b2FixtureDef robot_fd;
  robot_fd.shape = w.robot.rectangular() ? static_cast<b2Shape*>(&box) : &disk;
  const double area = w.robot.rectangular() ? w.robot.length_m * w.robot.width_m
                                            : M_PI * w.robot.radius_m * w.robot.radius_m;
  robot_fd.density = static_cast<float>(w.robot.mass_kg / area);
  robot_fd.friction = 0.3f;
  robot_fd.userData.pointer = kRobot;
  robot_->CreateFixture(&robot_fd);
}

PhysicsWorld::~PhysicsWorld() = default;

PhysicsWorld::Actor PhysicsWorld::make_actor(const worlds::MovingObstacle& m, bool sensor) {
  b2BodyDef def;
  def.type = b2_kinematicBody;
  const geom::Vec2 p = m.position_at(0.0);
  def.position.Set(static_cast<float>(p.x), static_cast<float>(p.y));
  b2Body* body = world_->CreateBody(&def);
  b2PolygonShape box;
  box.SetAsBox(static_cast<float>(0.5 * m.width_m), static_cast<float>(0.5 * m.height_m));
  b2FixtureDef fd;
  fd.shape = &box;
  fd.isSensor = sensor;  // the target is reached, not bumped into
  fd.userData.pointer = sensor ? kTarget : kMoving;
  body->CreateFixture(&fd);
  return {body, m, 0.0, {}};
}

void PhysicsWorld::advance(Actor& a, double dt_s) const {
  const b2Vec2 now = a.body->GetPosition();
  const Vec2 here{now.x, now.y};
  double next_time = a.script_time_s + dt_s;
  Vec2 next = a.script.position_at(next_time);
  if (a.script.yields_to_robot) {
    // In its way: ahead along its motion, within its width plus the robot and a margin.
    const Vec2 robot = robot_position();
    const Vec2 motion = next - here;
    const double len = geom::norm(motion);
    if (len > 0) {
      const Vec2 dir = (1.0 / len) * motion, rel = robot - here;
      // The box's half extents along and across its motion.
      const double hw = 0.5 * a.script.width_m, hh = 0.5 * a.script.height_m;
      const double half_along = std::fabs(dir.x) * hw + std::fabs(dir.y) * hh;
      const double half_across = std::fabs(dir.y) * hw + std::fabs(dir.x) * hh;
      const double along = geom::dot(rel, dir), lateral = std::fabs(geom::cross(dir, rel));
      if (along > 0 && along < half_along + robot_radius_m_ + a.script.yield_distance_m &&
          lateral < half_across + robot_radius_m_ + 0.1) {
        next_time = a.script_time_s;  // wait
        next = here;
      }
    }
  }
  a.script_time_s = next_time;
  a.velocity = (1.0 / dt_s) * (next - here);
  a.body->SetLinearVelocity(
      b2Vec2(static_cast<float>(a.velocity.x), static_cast<float>(a.velocity.y)));
}

ActorState PhysicsWorld::state_of(const Actor& a) {
  const b2Vec2 p = a.body->GetPosition();
  const double hw = 0.5 * a.script.width_m, hh = 0.5 * a.script.height_m;
  return {{p.x - hw, p.y - hh, p.x + hw, p.y + hh}, a.velocity};
}

std::optional<ActorState> PhysicsWorld::target() const {
  if (!target_) return std::nullopt;
  return state_of(*target_);
}

void PhysicsWorld::step(const StepSettings& s) {
  for (Actor& a : moving_) advance(a, s.dt_s);
  if (target_) advance(*target_, s.dt_s);
  world_->Step(static_cast<float>(s.dt_s), s.velocity_iterations, s.position_iterations);
}

std::vector<ActorState> PhysicsWorld::actors() const {
  std::vector<ActorState> out;
  for (const Actor& a : moving_) out.push_back(state_of(a));
  return out;
}

Pose2 PhysicsWorld::robot_pose() const {
  const b2Vec2 p = robot_->GetPosition();
  return {p.x, p.y, geom::wrap_angle(robot_->GetAngle())};
}

Vec2 PhysicsWorld::robot_position() const {
  const b2Vec2 p = robot_->GetPosition();
  return {p.x, p.y};
}

Vec2 PhysicsWorld::robot_velocity() const {
  const b2Vec2 v = robot_->GetLinearVelocity();
  return {v.x, v.y};
}

void PhysicsWorld::set_robot_velocity(Vec2 v, double w) {
  robot_->SetLinearVelocity(b2Vec2(static_cast<float>(v.x), static_cast<float>(v.y)));
  robot_->SetAngularVelocity(static_cast<float>(w));
}

void PhysicsWorld::place_robot(const Pose2& pose) {
  robot_->SetTransform(b2Vec2(static_cast<float>(pose.x), static_cast<float>(pose.y)),
                       static_cast<float>(pose.yaw));
  robot_->SetLinearVelocity(b2Vec2(0, 0));
  robot_->SetAngularVelocity(0);
}

double PhysicsWorld::robot_yaw_rate() const { return robot_->GetAngularVelocity(); }
double PhysicsWorld::robot_mass() const { return robot_->GetMass(); }
double PhysicsWorld::robot_inertia() const { return robot_->GetInertia(); }

ContactState PhysicsWorld::contacts() const {
  ContactState s;
  for (const b2ContactEdge* e = robot_->GetContactList(); e; e = e->next) {
    if (!e->contact->IsTouching()) continue;
    b2Fixture* a = e->contact->GetFixtureA();
    b2Fixture* b = e->contact->GetFixtureB();
    const FixtureTag other = tag_of(a) == kRobot ? tag_of(b) : tag_of(a);
    if (other == kCharger) s.charger = true;
    if (other == kObstacle || other == kWall || other == kMoving) {
      s.obstacle = true;
      b2WorldManifold m;
      e->contact->GetWorldManifold(&m);
      const int points = e->contact->GetManifold()->pointCount;
      for (int i = 0; i < points; ++i) s.obstacle_points.push_back({m.points[i].x, m.points[i].y});
    }
  }
  return s;
}

}  // namespace plantsim::sim

namespace plantsim::sim {

std::optional<RayHit> PhysicsWorld::ray_cast(Vec2 from, Vec2 to) const {
  const double length = geom::distance(from, to);
  if (!(length > 0)) return std::nullopt;
  const Vec2 direction = (1.0 / length) * (to - from);
  std::optional<RayHit> best = surfaces_.cast(from, direction, length);
  auto consider = [&](const Actor& a, SurfaceKind kind) {
    const auto e = geom::ray_enters_rect(state_of(a).box, from, direction);
    if (e && e->first <= length && (!best || e->first < best->range_m))
      best = RayHit{from + e->first * direction, e->second, e->first, kind};
  };
  for (const Actor& a : moving_) consider(a, SurfaceKind::kMoving);
  if (target_) consider(*target_, SurfaceKind::kTarget);
  return best;
}

std::optional<RayHit> PhysicsWorld::box2d_ray_cast(Vec2 from, Vec2 to) const {
  return detail::cast_ray(*world_, from, to);
}

void PhysicsWorld::ray_fan(Vec2 from, std::span<const Vec2> directions, double first_angle,
                           double increment, double max_range_m,
                           std::vector<double>& ranges) const {
  const geom::FanHits& hits = surfaces_.fan(from, directions, first_angle, increment, max_range_m);
  const std::size_t n = directions.size();
  ranges.resize(n);
  const double none = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < n; ++k) ranges[k] = hits.hit(k) ? hits.range_m[k] : none;
  auto consider = [&](const Actor& a) {
    const geom::Rect box = state_of(a).box;
    for (std::size_t k = 0; k < n; ++k) {
      double t;
      Vec2 normal;
      if (geom::ray_enters_rect(box, from, directions[k], t, normal) && t <= max_range_m &&
          t < ranges[k])
        ranges[k] = t;
    }
  };
  for (const Actor& a : moving_) consider(a);
  if (target_) consider(*target_);
}

}  // namespace plantsim::sim
