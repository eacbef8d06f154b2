// Building and stepping the Box2D world.
#include "sim/physics_world.h"

#include <box2d/box2d.h>

#include <cmath>

namespace plantsim::sim {
namespace {

enum FixtureTag : std::uintptr_t { kObstacle = 1, kWall = 2, kCharger = 3, kRobot = 4, kMoving = 5 };

void add_box(b2Body* body, const geom::Rect& r, FixtureTag tag) {
  b2PolygonShape box;
  const geom::Vec2 c = r.center();
  box.SetAsBox(static_cast<float>(0.5 * r.width()), static_cast<float>(0.5 * r.height()),
               b2Vec2(static_cast<float>(c.x), static_cast<float>(c.y)), 0.0f);
  b2FixtureDef fd;
  fd.shape = &box;
  fd.friction = 0.3f;
  fd.userData.pointer = tag;
  body->CreateFixture(&fd);
}

FixtureTag tag_of(b2Fixture* f) { return static_cast<FixtureTag>(f->GetUserData().pointer); }

}  // namespace

PhysicsWorld::PhysicsWorld(const worlds::World& w) : world_(std::make_unique<b2World>(b2Vec2(0, 0))) {
  b2BodyDef static_def;
  b2Body* statics = world_->CreateBody(&static_def);
  for (const geom::Rect& r : w.obstacles) add_box(statics, r, kObstacle);
  const geom::Rect& f = w.floor;
  const double t = 1.0;
  add_box(statics, {f.xmin - t, f.ymin - t, f.xmin, f.ymax + t}, kWall);
  add_box(statics, {f.xmax, f.ymin - t, f.xmax + t, f.ymax + t}, kWall);
  add_box(statics, {f.xmin, f.ymin - t, f.xmax, f.ymin}, kWall);
  add_box(statics, {f.xmin, f.ymax, f.xmax, f.ymax + t}, kWall);

  // The charger's face is set back by Box2D's polygon skin so that contact begins exactly
  // when the robot's centre reaches the docked pose.
  const worlds::ChargerBody cb = worlds::charger_body(w);
  const geom::Vec2 center = cb.center + b2_polygonRadius * w.charger.heading();
  b2BodyDef charger_def;
  charger_def.position.Set(static_cast<float>(center.x), static_cast<float>(center.y));
  charger_def.angle = static_cast<float>(cb.yaw);
  b2Body* charger = world_->CreateBody(&charger_def);
  b2PolygonShape plate;
  plate.SetAsBox(static_cast<float>(cb.half_depth_m), static_cast<float>(cb.half_width_m));
  b2FixtureDef plate_fd;
  plate_fd.shape = &plate;
  plate_fd.friction = 0.3f;
  plate_fd.userData.pointer = kCharger;
  charger->CreateFixture(&plate_fd);

  for (const worlds::MovingObstacle& m : w.moving) {
    b2BodyDef def;
    def.type = b2_kinematicBody;
    const geom::Vec2 p = m.position_at(0.0);
    def.position.Set(static_cast<float>(p.x), static_cast<float>(p.y));
    b2Body* body = world_->CreateBody(&def);
    b2PolygonShape box;
    box.SetAsBox(static_cast<float>(0.5 * m.width_m), static_cast<float>(0.5 * m.height_m));
    b2FixtureDef fd;
    fd.shape = &box;
    fd.userData.pointer = kMoving;
    body->CreateFixture(&fd);
    moving_.emplace_back(body, m);
  }

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
  const double area = w.robot.rectangular() ? w.robot.length_m * w.robot.width_m : M_PI * w.robot.radius_m * w.robot.radius_m;
  robot_fd.density = static_cast<float>(w.robot.mass_kg / area);
  robot_fd.friction = 0.3f;
  robot_fd.userData.pointer = kRobot;
  robot_->CreateFixture(&robot_fd);
}

PhysicsWorld::~PhysicsWorld() = default;

void PhysicsWorld::step(const StepSettings& s, double t_s) {
  for (auto& [body, m] : moving_) {
    const geom::Vec2 next = m.position_at(t_s + s.dt_s);
    const b2Vec2 now = body->GetPosition();
    body->SetLinearVelocity(b2Vec2(static_cast<float>((next.x - now.x) / s.dt_s),
                                   static_cast<float>((next.y - now.y) / s.dt_s)));
  }
  world_->Step(static_cast<float>(s.dt_s), s.velocity_iterations, s.position_iterations);
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
    if (other == kObstacle || other == kWall || other == kMoving) s.obstacle = true;
  }
  return s;
}

}  // namespace plantsim::sim
