// The static boxes in the physics' order, and casts that name what they hit.
#include "worlds/surfaces.h"

namespace plantsim::worlds {
namespace {

std::vector<geom::Rect> static_rects(const World& plant) {
  std::vector<geom::Rect> rects = plant.obstacles;
  rects.insert(rects.end(), plant.unmapped.begin(), plant.unmapped.end());
  for (const geom::Rect& wall : geom::surrounding_walls(plant.floor, 1.0)) rects.push_back(wall);
  return rects;
}

}  // namespace

geom::OrientedBox charger_block(const World& plant) {
  const ChargerBody cb = charger_body(plant);
  const geom::Vec2 center =
      cb.center + (kContactSkinM + 0.5 * plant.charger_spec.pad_travel_m) * plant.charger.heading();
  return {center, cb.half_depth_m, cb.half_width_m, cb.yaw};
}

SurfaceGrid::SurfaceGrid(const World& plant) : grid_(static_rects(plant), {charger_block(plant)}) {
  kinds_.assign(plant.obstacles.size() + plant.unmapped.size(), SurfaceKind::kObstacle);
  kinds_.insert(kinds_.end(), 4, SurfaceKind::kWall);
  kinds_.push_back(SurfaceKind::kCharger);
}

std::optional<RayHit> SurfaceGrid::cast(geom::Vec2 from, geom::Vec2 direction,
                                        double max_range_m) const {
  const auto hit = grid_.cast(from, direction, max_range_m);
  if (!hit) return std::nullopt;
  return RayHit{from + hit->range_m * direction, hit->normal, hit->range_m,
                kinds_[static_cast<std::size_t>(hit->box)]};
}

void SurfaceGrid::cast_fan(geom::Vec2 from, std::span<const geom::Vec2> directions,
                           double first_angle, double increment, double max_range_m,
                           std::vector<std::optional<RayHit>>& hits) const {
  grid_.cast_fan(from, directions, first_angle, increment, max_range_m, scratch_);
  hits.resize(directions.size());
  // Field by field into place: a RayHit built aside and copied in stalled on store forwarding.
  for (std::size_t k = 0; k < directions.size(); ++k) {
    auto& out = hits[k];
    if (!scratch_.hit(k)) {
      out.reset();
      continue;
    }
    if (!out) out.emplace();
    const double range = scratch_.range_m[k];
    out->point = from + range * directions[k];
    out->normal = scratch_.normal[k];
    out->range_m = range;
    out->kind = kinds_[static_cast<std::size_t>(scratch_.box[k])];
  }
}

}  // namespace plantsim::worlds
