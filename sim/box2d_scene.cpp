// Static fixtures and the nearest-hit ray cast.
#include "sim/box2d_scene.h"

#include <cmath>

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

SurfaceKind kind_of(FixtureTag t) {
  switch (t) {
    case kWall: return SurfaceKind::kWall;
    case kCharger: return SurfaceKind::kCharger;
    case kMoving: return SurfaceKind::kMoving;
    case kTarget: return SurfaceKind::kTarget;
    default: return SurfaceKind::kObstacle;
  }
}

// Keeps the nearest fixture: returning the fraction clips the ray there (Box2D's contract).
class NearestHit : public b2RayCastCallback {
 public:
  float ReportFixture(b2Fixture* fixture, const b2Vec2& point, const b2Vec2& normal, float fraction) override {
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

namespace {

// The charger's rigid face is set back by Box2D's polygon skin and by half the pads' spring
// travel, so that the robot's centre stops half the travel past the docked pose.
geom::OrientedBox charger_block(const worlds::World& plant) {
  const worlds::ChargerBody cb = worlds::charger_body(plant);
  const geom::Vec2 center = cb.center + (b2_polygonRadius + 0.5 * plant.charger_spec.pad_travel_m) * plant.charger.heading();
  return {center, cb.half_depth_m, cb.half_width_m, cb.yaw};
}

std::vector<geom::Rect> static_rects(const worlds::World& plant) {
  std::vector<geom::Rect> rects = plant.obstacles;
  rects.insert(rects.end(), plant.unmapped.begin(), plant.unmapped.end());
  for (const geom::Rect& wall : geom::surrounding_walls(plant.floor, 1.0)) rects.push_back(wall);
  return rects;
}

}  // namespace

StaticScene::StaticScene(const worlds::World& plant) : grid(static_rects(plant), {charger_block(plant)}) {
  kinds.assign(plant.obstacles.size() + plant.unmapped.size(), SurfaceKind::kObstacle);
  kinds.insert(kinds.end(), 4, SurfaceKind::kWall);
  kinds.push_back(SurfaceKind::kCharger);
}

std::optional<RayHit> StaticScene::cast(geom::Vec2 from, geom::Vec2 direction, double max_range_m) const {
  const auto hit = grid.cast(from, direction, max_range_m);
  if (!hit) return std::nullopt;
  return RayHit{from + hit->range_m * direction, hit->normal, hit->range_m, kinds[static_cast<std::size_t>(hit->box)]};
}

void StaticScene::cast_fan(geom::Vec2 from, std::span<const geom::Vec2> directions, double first_angle, double increment,
                           double max_range_m, std::vector<std::optional<RayHit>>& hits) const {
  thread_local std::vector<std::optional<geom::RayGridHit>> grid_hits;
  grid.cast_fan(from, directions, first_angle, increment, max_range_m, grid_hits);
  hits.assign(directions.size(), std::nullopt);
  for (std::size_t k = 0; k < directions.size(); ++k)
    if (const auto& h = grid_hits[k])
      hits[k] = RayHit{from + h->range_m * directions[k], h->normal, h->range_m, kinds[static_cast<std::size_t>(h->box)]};
}

void add_static_scene(b2World& world, const worlds::World& plant) {
  b2BodyDef static_def;
  b2Body* statics = world.CreateBody(&static_def);
  for (const geom::Rect& r : plant.obstacles) add_box(statics, r, kObstacle);
  for (const geom::Rect& r : plant.unmapped) add_box(statics, r, kObstacle);  // absent from a map's World
  for (const geom::Rect& wall : geom::surrounding_walls(plant.floor, 1.0)) add_box(statics, wall, kWall);

  const geom::OrientedBox block = charger_block(plant);
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

std::optional<RayHit> cast_ray(const b2World& world, geom::Vec2 from, geom::Vec2 to) {
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
  return RayHit{from + range * dir, {cb.normal_.x, cb.normal_.y}, range, kind_of(cb.tag_)};
}

}  // namespace plantsim::sim::detail
