// Static fixtures and the nearest-hit ray cast.
#include "sim/box2d_scene.h"

#include <cmath>

static_assert(plantsim::worlds::kContactSkinM == static_cast<double>(b2_polygonRadius),
              "worlds/surfaces.h's contact skin must be Box2D's polygon radius");

namespace plantsim::sim::detail {
namespace {

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

using worlds::SurfaceKind;

SurfaceKind kind_of(FixtureTag t) {
  switch (t) {
    case kWall:
      return SurfaceKind::kWall;
    case kCharger:
      return SurfaceKind::kCharger;
    case kMoving:
      return SurfaceKind::kMoving;
    case kTarget:
      return SurfaceKind::kTarget;
    default:
      return SurfaceKind::kObstacle;
  }
}

// Keeps the nearest fixture: returning the fraction clips the ray there (Box2D's contract).
class NearestHit : public b2RayCastCallback {
 public:
  float ReportFixture(b2Fixture* fixture, const b2Vec2& point, const b2Vec2& normal,
                      float fraction) override {
    if (tag_of(fixture) == kRobot) return -1.0f;  // the sensor sits inside the robot
    point_ = point;
    normal_ = normal;
    fraction_ = fraction;
    tag_ = tag_of(fixture);
    hit_ = true;
    return fraction;
  }
  bool hit_ = false;
  b2Vec2 point_, normal_;
  float fraction_ = 1.0f;
  FixtureTag tag_ = kObstacle;
};

}  // namespace

void add_static_scene(b2World& world, const worlds::World& plant) {
  b2BodyDef static_def;
  b2Body* statics = world.CreateBody(&static_def);
  for (const geom::Rect& r : plant.obstacles) add_box(statics, r, kObstacle);
  for (const geom::Rect& r : plant.unmapped)
    add_box(statics, r, kObstacle);  // absent from a map's World
  for (const geom::Rect& wall : geom::surrounding_walls(plant.floor, 1.0))
    add_box(statics, wall, kWall);

  // The charger's rigid face is set back by Box2D's polygon skin and by half the pads' spring
  // travel, so that the robot's centre stops half the travel past the docked pose.
  const geom::OrientedBox block = worlds::charger_block(plant);
  b2BodyDef charger_def;
  charger_def.position.Set(static_cast<float>(block.center.x), static_cast<float>(block.center.y));
  charger_def.angle = static_cast<float>(block.yaw);
  b2Body* body = world.CreateBody(&charger_def);
  b2PolygonShape plate;
  plate.SetAsBox(static_cast<float>(block.hx), static_cast<float>(block.hy));
  b2FixtureDef plate_fd;
  plate_fd.shape = &plate;
  plate_fd.friction = 0.3f;
  plate_fd.userData.pointer = kCharger;
  body->CreateFixture(&plate_fd);
}

std::optional<worlds::RayHit> cast_ray(const b2World& world, geom::Vec2 from, geom::Vec2 to) {
  const double length = geom::distance(from, to);
  if (!(length > 0)) return std::nullopt;
  NearestHit cb;
  world.RayCast(&cb, b2Vec2(static_cast<float>(from.x), static_cast<float>(from.y)),
                b2Vec2(static_cast<float>(to.x), static_cast<float>(to.y)));
  if (!cb.hit_) return std::nullopt;
  // The range from the fraction in double precision: the float hit point loses millimetres
  // far from the origin on large floors.
  const double range = cb.fraction_ * length;
  const geom::Vec2 dir = (1.0 / length) * (to - from);
  return worlds::RayHit{from + range * dir, {cb.normal_.x, cb.normal_.y}, range, kind_of(cb.tag_)};
}

}  // namespace plantsim::sim::detail
