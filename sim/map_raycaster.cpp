// A static-only Box2D scene for expected ranges.
#include "sim/map_raycaster.h"

#include "sim/box2d_scene.h"

namespace plantsim::sim {

MapRaycaster::MapRaycaster(const worlds::World& map) : world_(std::make_unique<b2World>(b2Vec2(0, 0))) {
  detail::add_static_scene(*world_, map);
}

MapRaycaster::~MapRaycaster() = default;

std::optional<RayHit> MapRaycaster::cast(geom::Vec2 from, double angle_rad, double max_range_m) const {
  return detail::cast_ray(*world_, from, from + max_range_m * geom::unit_from_angle(angle_rad));
}

namespace {
class AnyFixture : public b2QueryCallback {
 public:
  bool ReportFixture(b2Fixture*) override {
    found = true;
    return false;  // one is enough
  }
  bool found = false;
};
}  // namespace

bool MapRaycaster::surface_near(geom::Vec2 point, double margin_m) const {
  // Fixture boxes are the rectangles themselves (axis-aligned), so overlap of the query box
  // is nearness per axis; the charger's box is its oriented block's bounding box.
  b2AABB box;
  box.lowerBound.Set(static_cast<float>(point.x - margin_m), static_cast<float>(point.y - margin_m));
  box.upperBound.Set(static_cast<float>(point.x + margin_m), static_cast<float>(point.y + margin_m));
  AnyFixture cb;
  world_->QueryAABB(&cb, box);
  return cb.found;
}

}  // namespace plantsim::sim
