// Plant faults: crossing people and unmapped boxes.
#include "batch/plant_faults.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "geometry/predicates.h"
#include "planner/planner.h"
#include "planner/registry.h"
#include "worlds/charger_placement.h"

namespace plantsim::batch {
namespace {

// The point at arc length s along the polyline, and the direction there.
std::pair<geom::Vec2, geom::Vec2> point_along(const std::vector<geom::Vec2>& plan, double s) {
  for (std::size_t i = 1; i < plan.size(); ++i) {
    const double seg = geom::distance(plan[i - 1], plan[i]);
    if (seg > 0 && (s <= seg || i + 1 == plan.size())) {
      const geom::Vec2 dir = (1.0 / seg) * (plan[i] - plan[i - 1]);
      return {plan[i - 1] + std::min(s, seg) * dir, dir};
    }
    s -= seg;
  }
  return {plan.back(), {1, 0}};
}

double length_of(const std::vector<geom::Vec2>& plan) {
  double total = 0;
  for (std::size_t i = 1; i < plan.size(); ++i) total += geom::distance(plan[i - 1], plan[i]);
  return total;
}

// The plant with these unmapped boxes still lets a robot that knows them reach the staging
// pose from the start, keeping the clearance its replanning keeps, and dock.
bool still_dockable(const worlds::World& w, const std::vector<geom::Rect>& boxes,
                    double clearance_m) {
  worlds::World plant = w;
  plant.obstacles.insert(plant.obstacles.end(), boxes.begin(), boxes.end());
  if (!worlds::docking_area_clear(plant)) return false;
  planner::PlannerInput in = planner::planner_input(plant, true);
  in.inflation_m += clearance_m;
  in.snap_to_free = true;  // the start may sit within the extra clearance, not in the box
  const auto vg = planner::make_planner("vg", in);
  return vg->plan(w.start.position(), worlds::staging_pose(w).position()).status ==
         planner::PlanStatus::kOk;
}

bool leaves_poses_free(const worlds::World& w, const geom::Rect& box) {
  const double r = w.robot.radius_m + 0.3;  // not right against the start or the docked pose
  for (const geom::Pose2& p : {w.start, w.charger})
    if (std::hypot(std::max({box.xmin - p.x, 0.0, p.x - box.xmax}),
                   std::max({box.ymin - p.y, 0.0, p.y - box.ymax})) < r)
      return false;
  return geom::in_closed_rect(w.floor, {box.xmin, box.ymin}) &&
         geom::in_closed_rect(w.floor, {box.xmax, box.ymax});
}

}  // namespace

worlds::MovingObstacle crossing_person(const worlds::World& w,
                                       const std::vector<geom::Vec2>& plan) {
  double total = 0;
  for (std::size_t i = 1; i < plan.size(); ++i) total += geom::distance(plan[i - 1], plan[i]);
  double left = 0.5 * total;
  geom::Vec2 at = plan.front(), dir{1, 0};
  for (std::size_t i = 1; i < plan.size(); ++i) {
    const double seg = geom::distance(plan[i - 1], plan[i]);
    if (seg >= left && seg > 0) {
      dir = (1.0 / seg) * (plan[i] - plan[i - 1]);
      at = plan[i - 1] + left * dir;
      break;
    }
    left -= seg;
  }
  const geom::Vec2 across{-dir.y, dir.x};
  auto clamp = [&](geom::Vec2 p) {
    return geom::Vec2{std::clamp(p.x, w.floor.xmin + 0.3, w.floor.xmax - 0.3),
                      std::clamp(p.y, w.floor.ymin + 0.3, w.floor.ymax - 0.3)};
  };
  worlds::MovingObstacle m;
  m.name = "crossing person";
  m.width_m = m.height_m = 0.6;
  // Up to 3 m each side of the path, but never through an obstacle: people walk round walls
  // (a person stepping out of a solid block would be a sensing test no robot can pass).
  auto free_at = [&](geom::Vec2 c) {
    for (const geom::Rect& r : w.obstacles)
      if (geom::in_open_rect(r.inflated(0.5 * m.width_m), c)) return false;
    return true;
  };
  auto reach = [&](double side) {
    double s = 0;
    while (s < 3.0 && free_at(clamp(at + (side * (s + 0.05)) * across))) s += 0.05;
    return clamp(at + (side * s) * across);
  };
  const geom::Vec2 from = reach(-1.0), to = reach(1.0);
  m.waypoints = {from, to};
  m.speed_mps = 0.8;
  // Timed to reach the path as the robot does.
  const double to_path = geom::distance(from, at) / m.speed_mps;
  m.start_time_s = std::max(0.0, 0.5 * total / 0.6 - to_path);
  return m;
}

namespace {

// Where a person meets the final approach (halfway between the staging pose and the charger),
// and the farthest free points up to 3 m to either side of it, across the approach.
struct AcrossFinalApproach {
  geom::Vec2 at, left, right;
};

AcrossFinalApproach across_final_approach(const worlds::World& w, double person_size_m) {
  const geom::Pose2 staging = worlds::staging_pose(w);
  const geom::Vec2 at =
      staging.position() + (0.5 * w.charger_spec.staging_distance_m) * staging.heading();
  const geom::Vec2 across{-staging.heading().y, staging.heading().x};
  auto free_at = [&](geom::Vec2 c) {
    if (!geom::in_closed_rect(w.floor.inflated(-0.5 * person_size_m), c)) return false;
    for (const geom::Rect& r : w.obstacles)
      if (geom::in_open_rect(r.inflated(0.5 * person_size_m), c)) return false;
    return true;
  };
  auto reach = [&](double side) {
    double s = 0;
    while (s < 3.0 && free_at(at + (side * (s + 0.05)) * across)) s += 0.05;
    return at + (side * s) * across;
  };
  return {at, reach(-1.0), reach(1.0)};
}

// When a robot driving the plan at a steady 0.5 m/s reaches the staging pose and has turned.
double robot_at_staging_s(double plan_length_m) { return plan_length_m / 0.5 + 3.0; }

}  // namespace

worlds::MovingObstacle final_approach_crosser(const worlds::World& w, double plan_length_m) {
  worlds::MovingObstacle m;
  m.name = "person crossing the final approach";
  m.width_m = m.height_m = 0.5;
  const AcrossFinalApproach a = across_final_approach(w, m.width_m);
  // From the side with less room to the side with more: the walk ends as far from the approach
  // as the plant allows (ended on a side too narrow to stand clear, it would block the dock
  // for good, a different fault from a crossing).
  const bool right_roomier = geom::distance(a.at, a.right) >= geom::distance(a.at, a.left);
  m.waypoints = right_roomier ? std::vector<geom::Vec2>{a.left, a.right}
                              : std::vector<geom::Vec2>{a.right, a.left};
  m.speed_mps = 0.8;
  // The robot approaches at 0.08 m/s: the person arrives when it is a quarter of the way in.
  const double robot_there_s =
      robot_at_staging_s(plan_length_m) + 0.25 * w.charger_spec.staging_distance_m / 0.08;
  m.start_time_s =
      std::max(0.0, robot_there_s - geom::distance(m.waypoints[0], a.at) / m.speed_mps);
  return m;
}

worlds::MovingObstacle person_standing_at_dock(const worlds::World& w, double plan_length_m,
                                               double standing_s) {
  worlds::MovingObstacle m;
  m.name = "person standing at the dock";
  m.width_m = m.height_m = 0.5;
  const AcrossFinalApproach a = across_final_approach(w, m.width_m);
  m.waypoints = {a.at,
                 geom::distance(a.at, a.right) >= geom::distance(a.at, a.left) ? a.right : a.left};
  m.speed_mps = 0.8;
  m.start_time_s =
      robot_at_staging_s(plan_length_m) + standing_s;  // stands until then, then walks off
  return m;
}

std::vector<geom::Rect> unmapped_across_path(const worlds::World& w,
                                             const std::vector<geom::Vec2>& plan, int count,
                                             std::uint64_t seed, double replan_clearance_m) {
  std::vector<geom::Rect> boxes;
  const double length = length_of(plan), keep_clear = 1.5;
  if (count <= 0 || plan.size() < 2 || length <= 2 * keep_clear) return boxes;
  std::mt19937_64 rng(seed * 0x9e3779b97f4a7c15ULL + 0x51);
  std::uniform_real_distribution<double> side(0.4, 0.9), offset(-0.25, 0.25);
  for (int k = 0; k < count; ++k) {
    const double s = keep_clear + (k + 0.5) / count * (length - 2 * keep_clear);
    const auto [at, dir] = point_along(plan, s);
    const geom::Vec2 normal{-dir.y, dir.x};
    const geom::Vec2 centre = at + offset(rng) * normal;
    double a = side(rng), b = side(rng);
    for (int attempt = 0; attempt < 4; ++attempt, a *= 0.7, b *= 0.7) {
      const geom::Rect box{centre.x - 0.5 * a, centre.y - 0.5 * b, centre.x + 0.5 * a,
                           centre.y + 0.5 * b};
      if (!leaves_poses_free(w, box)) continue;
      std::vector<geom::Rect> with = boxes;
      with.push_back(box);
      if (!still_dockable(w, with, replan_clearance_m)) continue;
      boxes.push_back(box);
      break;
    }
  }
  return boxes;
}

}  // namespace plantsim::batch
