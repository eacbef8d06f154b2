// Every field that changes what an episode meets, in a fixed order.
#include "worlds/world_fingerprint.h"

#include "util/fingerprint.h"

namespace plantsim::worlds {
namespace {

void add(util::Fingerprint& f, const Rect& r) { f.add(r.xmin).add(r.ymin).add(r.xmax).add(r.ymax); }
void add(util::Fingerprint& f, const Pose2& p) { f.add(p.x).add(p.y).add(p.yaw); }
void add(util::Fingerprint& f, const MovingObstacle& m) {
  f.add(m.width_m).add(m.height_m).add(m.speed_mps).add(m.start_time_s).add(m.yield_distance_m);
  f.add(static_cast<std::uint64_t>(m.loop) * 2 + m.yields_to_robot)
      .add(static_cast<std::uint64_t>(m.waypoints.size()));
  for (const Vec2& p : m.waypoints) f.add(p.x).add(p.y);
}

}  // namespace

std::uint64_t world_fingerprint(const World& w) {
  util::Fingerprint f;
  f.add(std::string_view("plantsim world v1"));
  add(f, w.floor);
  f.add(static_cast<std::uint64_t>(w.obstacles.size()));
  for (const Rect& r : w.obstacles) add(f, r);
  const RobotSpec& r = w.robot;
  f.add(r.radius_m)
      .add(r.wheel_base_m)
      .add(r.wheel_radius_m)
      .add(r.max_speed_mps)
      .add(r.max_accel_mps2)
      .add(r.mass_kg);
  f.add(r.length_m).add(r.width_m);
  const ChargerSpec& c = w.charger_spec;
  f.add(c.width_m).add(c.depth_m).add(c.staging_distance_m).add(c.pad_travel_m);
  add(f, w.start);
  add(f, w.charger);
  f.add(w.inflation_margin_m);
  f.add(static_cast<std::uint64_t>(w.moving.size()));
  for (const MovingObstacle& m : w.moving) add(f, m);
  f.add(static_cast<std::uint64_t>(w.unmapped.size()));
  for (const Rect& u : w.unmapped) add(f, u);
  add(f, w.charger_map_offset);
  f.add(static_cast<std::uint64_t>(w.target.has_value()));
  if (w.target) add(f, *w.target);
  return f.value();
}

}  // namespace plantsim::worlds
