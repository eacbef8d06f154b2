// The coastal route: on a 160 x 90 m yard of the tuning set it trades length for sight, stays
// clear of every grown obstacle and ends where the plan ends; where the shortest path keeps a
// surface in sight, or the route is turned off, the shortest path is driven unchanged.
#include <gtest/gtest.h>

#include "geometry/polyline.h"
#include "geometry/predicates.h"
#include "planner/planner.h"
#include "planner/registry.h"
#include "robot/coastal_route.h"
#include "test_paths.h"
#include "worlds/world_loader.h"

namespace plantsim::robot {
namespace {

constexpr double kLidarRangeM = 20.0;

std::vector<geom::Vec2> shortest(const worlds::World& w) {
  const planner::PlanResult plan =
      planner::make_planner("vg", planner::planner_input(w, true))
          ->plan(w.start.position(), worlds::staging_pose(w).position());
  EXPECT_EQ(plan.status, planner::PlanStatus::kOk);
  return plan.path;
}

void expect_clear(const worlds::World& w, const std::vector<geom::Vec2>& route) {
  const planner::PlannerInput in = planner::planner_input(w, true);
  for (std::size_t i = 0; i + 1 < route.size(); ++i)
    for (const geom::Rect& r : in.obstacles)
      EXPECT_FALSE(
          geom::segment_enters_open_rect(route[i], route[i + 1], r.inflated(in.inflation_m)))
          << "leg " << i;
}

TEST(CoastalRoute, KeepsSurfacesInSightAcrossAnOpenYard) {
  // Three long walls on 160 x 90 m: the shortest path from this start crosses 100 m or more of
  // ground with no surface within 12 m.
  const worlds::World w =
      worlds::load_world(test::source_file("data/worlds/generated/large_tuning/yard_s22.json"));
  const std::vector<geom::Vec2> path = shortest(w);
  const CoastalParams p;
  const Blindness before = blindness(w, path, kLidarRangeM, p);
  ASSERT_GT(before.longest_m, p.activate_blind_m);
  const std::vector<geom::Vec2> route = coastal_route(w, path, kLidarRangeM, p);
  ASSERT_NE(route, path);
  EXPECT_EQ(route.front(), path.front());
  EXPECT_EQ(route.back(), path.back());
  expect_clear(w, route);
  const Blindness after = blindness(w, route, kLidarRangeM, p);
  EXPECT_LT(after.longest_m, 0.5 * before.longest_m);
  EXPECT_LT(geom::polyline_length(route) + after.cost_m,
            geom::polyline_length(path) + before.cost_m);
  EXPECT_LT(geom::polyline_length(route), 2.0 * geom::polyline_length(path));
}

TEST(CoastalRoute, TheShortestPathWhereItKeepsSightOrWhenTurnedOff) {
  // A dense plant: nothing on the way is far from a box.
  const worlds::World dense =
      worlds::load_world(test::source_file("data/worlds/generated/styles/dense_s1.json"));
  const std::vector<geom::Vec2> path = shortest(dense);
  EXPECT_LE(blindness(dense, path, kLidarRangeM, {}).longest_m, CoastalParams{}.activate_blind_m);
  EXPECT_EQ(coastal_route(dense, path, kLidarRangeM, {}), path);
  const worlds::World yard =
      worlds::load_world(test::source_file("data/worlds/generated/large_tuning/yard_s22.json"));
  const std::vector<geom::Vec2> open = shortest(yard);
  CoastalParams off;
  off.enabled = false;
  EXPECT_EQ(coastal_route(yard, open, kLidarRangeM, off), open);
  EXPECT_EQ(coastal_route(yard, open, 0.0, {}), open);  // no lidar: nothing to keep in sight
}

}  // namespace
}  // namespace plantsim::robot
