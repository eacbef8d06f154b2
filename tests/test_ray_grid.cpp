// The grid ray caster against the obvious answer: every box tested, on thousands of random rays
// through random plants, grazing rays along faces and rays through corners included; and
// against Box2D's own ray casts through the physics (which work in single precision).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <random>
#include <string>

#include "geometry/near_raster.h"
#include "geometry/ray_grid.h"
#include "sim/physics_world.h"
#include "test_paths.h"
#include "worlds/random_plant.h"
#include "worlds/surfaces.h"
#include "worlds/world_loader.h"

namespace plantsim::geom {
namespace {

// The nearest entry by brute force: the box's four faces as segments, each met from outside.
std::optional<double> brute_force(const std::vector<Rect>& rects, Vec2 o, Vec2 d,
                                  double max_range) {
  std::optional<double> best;
  for (const Rect& r : rects) {
    if (r.xmin < o.x && o.x < r.xmax && r.ymin < o.y && o.y < r.ymax) continue;  // inside: no hit
    auto consider = [&](double t) {
      if (t > 0 && t <= max_range && (!best || t < *best)) best = t;
    };
    if (d.x != 0) {
      for (double x : {r.xmin, r.xmax}) {
        const double t = (x - o.x) / d.x, y = o.y + t * d.y;
        const bool from_outside = (x == r.xmin) ? d.x > 0 : d.x < 0;
        if (from_outside && y >= r.ymin && y <= r.ymax) consider(t);
      }
    }
    if (d.y != 0) {
      for (double y : {r.ymin, r.ymax}) {
        const double t = (y - o.y) / d.y, x = o.x + t * d.x;
        const bool from_outside = (y == r.ymin) ? d.y > 0 : d.y < 0;
        if (from_outside && x >= r.xmin && x <= r.xmax) consider(t);
      }
    }
  }
  return best;
}

// `count` boxes on a 100 x 60 m floor, each side min_side plus up to `spread` more.
std::vector<Rect> random_rects(std::mt19937_64& rng, int count, double min_side, double spread) {
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Rect> rects;
  for (int k = 0; k < count; ++k) {
    const double x = 100 * u(rng), y = 60 * u(rng), w = min_side + spread * u(rng),
                 h = min_side + spread * u(rng);
    rects.push_back({x, y, x + w, y + h});
  }
  return rects;
}

TEST(RayGrid, MatchesEveryBoxTestedOnRandomRays) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  int rays = 0, hits = 0, grazing = 0, corner_touches = 0;
  for (int plant = 0; plant < 20; ++plant) {
    const std::vector<Rect> rects = random_rects(rng, 5 + plant * 20, 0.2, 5);
    const RayGrid grid(rects, {});
    for (int k = 0; k < 500; ++k) {
      Vec2 o{100 * u(rng), 60 * u(rng)};
      Vec2 d = unit_from_angle(2 * M_PI * u(rng));
      if (k % 10 == 0) {  // along a face, from its corner's line: grazing
        const Rect& r = rects[static_cast<std::size_t>(k) % rects.size()];
        o = {r.xmin - 3.0, r.ymax};
        d = {1, 0};
        ++grazing;
      } else if (k % 10 == 1) {  // straight at a corner
        const Rect& r = rects[static_cast<std::size_t>(k) % rects.size()];
        d = unit_from_angle(std::atan2(r.ymin - o.y, r.xmin - o.x));
      }
      const double max_range = 20 + 60 * u(rng);
      const auto want = brute_force(rects, o, d, max_range);
      const auto got = grid.cast(o, d, max_range);
      ++rays;
      const bool same =
          want.has_value() == got.has_value() && (!want || std::fabs(got->range_m - *want) <= 1e-9);
      if (!same) {
        // Only a ray that touches a corner, which rounding may put a hair either side of, may
        // be a hit one way and pass by the other; the nearer answer is then that touch.
        const double t = std::min(want.value_or(1e300), got ? got->range_m : 1e300);
        const Vec2 p = o + t * d;
        double nearest_corner = 1e9;
        for (const Rect& r : rects)
          for (Vec2 c : {Vec2{r.xmin, r.ymin}, Vec2{r.xmin, r.ymax}, Vec2{r.xmax, r.ymin},
                         Vec2{r.xmax, r.ymax}})
            nearest_corner = std::min(nearest_corner, distance(p, c));
        EXPECT_LT(nearest_corner, 1e-9) << "plant " << plant << " ray " << k;
        ++corner_touches;
        continue;
      }
      if (want) {
        ++hits;
        EXPECT_NEAR(norm(got->normal), 1.0, 1e-12);
      }
    }
  }
  EXPECT_GT(hits, rays / 3);
  EXPECT_LT(corner_touches, rays / 100);
  EXPECT_GT(grazing, 500);
}

TEST(RayGrid, OrientedBoxesAndNormals) {
  const RayGrid grid({}, {{{5, 0}, 1.0, 0.5, M_PI / 4}});
  const auto hit = grid.cast({0, 0}, {1, 0}, 10);
  ASSERT_TRUE(hit);
  // The box's corner pointing at the origin lies sqrt(1 + 0.25)... along x at the nearer face.
  const Vec2 p{hit->range_m, 0};
  const Vec2 local = rotate(p - Vec2{5, 0}, -M_PI / 4);
  EXPECT_NEAR(std::max(std::fabs(local.x) - 1.0, std::fabs(local.y) - 0.5), 0.0, 1e-12);
  EXPECT_LT(hit->normal.x, 0);
  EXPECT_FALSE(grid.cast({5, 0}, {1, 0}, 10));  // from inside: no hit
  EXPECT_TRUE(grid.near({5, 1.1}, 0.1));        // its bounding box reaches y = 1.06
  EXPECT_FALSE(grid.near({5, 3}, 0.1));
}

// A fan is an optimisation of single casts: every ray of it must find the very range cast()
// finds, whatever the fan's start, spread and count, from origins on faces, at corners, by
// turned boxes and far outside the grid.
TEST(RayGrid, FanEqualsSingleCastsExactly) {
  std::mt19937_64 rng(19);
  std::uniform_real_distribution<double> u(0, 1);
  long rays = 0, hits = 0;
  for (int plant = 0; plant < 12; ++plant) {
    const std::vector<Rect> rects = random_rects(rng, 10 + plant * 40, 0.2, 4);
    std::vector<OrientedBox> turned;
    for (int k = 0; k < 5; ++k)
      turned.push_back(
          {{100 * u(rng), 60 * u(rng)}, 0.3 + u(rng), 0.2 + u(rng), 2 * M_PI * u(rng)});
    const RayGrid grid(rects, turned);
    for (int fan = 0; fan < 60; ++fan) {
      Vec2 o{-10 + 120 * u(rng), -10 + 80 * u(rng)};
      const Rect& r = rects[static_cast<std::size_t>(fan) % rects.size()];
      if (fan % 5 == 1) o = {r.xmin, r.ymax};                          // on a corner
      if (fan % 5 == 2) o = {r.xmin - 2.0, r.ymin};                    // on a face's line
      if (fan % 5 == 3) o = {0.5 * (r.xmin + r.xmax), r.ymax + 1e-7};  // a hair off a face
      const int n = fan % 3 == 0 ? 360 : (fan % 3 == 1 ? 7 : 1);
      const double first = -20 + 40 * u(rng);
      const double fov = fan % 2 == 0 ? 2 * M_PI : 4 * u(rng);
      const double increment = n > 1 ? fov / (n - 1) : 0.0;
      std::vector<Vec2> directions;
      for (int k = 0; k < n; ++k) directions.push_back(unit_from_angle(first + k * increment));
      const double max_range = 5 + 40 * u(rng);
      FanHits fanned;
      grid.cast_fan(o, directions, first, increment, max_range, fanned);
      ASSERT_EQ(fanned.size(), directions.size());
      for (int k = 0; k < n; ++k) {
        const auto single = grid.cast(o, directions[static_cast<std::size_t>(k)], max_range);
        const std::size_t got = static_cast<std::size_t>(k);
        ++rays;
        ASSERT_EQ(single.has_value(), fanned.hit(got))
            << "plant " << plant << " fan " << fan << " ray " << k;
        if (single) {
          ++hits;
          EXPECT_EQ(single->range_m, fanned.range_m[got])
              << "plant " << plant << " fan " << fan << " ray " << k;
          // The same face: no two random boxes share one.
          EXPECT_TRUE(single->normal.x == fanned.normal[got].x &&
                      single->normal.y == fanned.normal[got].y)
              << "plant " << plant << " fan " << fan << " ray " << k;
        }
      }
    }
  }
  EXPECT_GT(rays, 10000);
  EXPECT_GT(hits, rays / 3);
}

// The raster's yes and no must be the grid's answer wherever it gives one, on random points and
// on points exactly on grown boxes' edges and corners.
TEST(NearRaster, AgreesWithTheGridWhereverItAnswers) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(0, 1);
  long decided = 0, asked = 0;
  for (int plant = 0; plant < 10; ++plant) {
    const std::vector<Rect> rects = random_rects(rng, 20 + 50 * plant, 0.1, 3);
    const RayGrid grid(rects, {{{50, 30}, 1.0, 0.4, 0.7}});
    const double margin = 0.05 + 0.3 * u(rng);
    const Rect& a = grid.area();
    const NearRaster raster(grid.bounds(), margin, {a.xmin - 1, a.ymin - 1, a.xmax + 1, a.ymax + 1},
                            0.5 * margin);
    for (int k = 0; k < 20000; ++k) {
      Vec2 p{-2 + 104 * u(rng), -2 + 64 * u(rng)};
      if (k % 4 == 1) {  // on a grown box's edge or corner
        const Rect& r = rects[static_cast<std::size_t>(k) % rects.size()];
        p = {k % 8 == 1 ? r.xmax + margin : r.xmin - margin + (r.width() + 2 * margin) * u(rng),
             r.ymin - margin};
      }
      const auto answer = raster.at(p);
      if (k % 4 != 1) ++asked;
      if (answer == NearRaster::Answer::kDepends) continue;
      if (k % 4 != 1) ++decided;
      EXPECT_EQ(answer == NearRaster::Answer::kYes, grid.near(p, margin))
          << "plant " << plant << " point " << p.x << "," << p.y;
    }
  }
  EXPECT_GT(decided, asked * 9 / 10);  // the raster answers most random points by itself
}

TEST(RayGrid, AgreesWithBox2dThroughThePhysics) {
  worlds::RandomPlantOptions o;
  o.rect_count = 200;
  o.seed = 3;
  const worlds::World w = worlds::random_plant(o);
  const sim::PhysicsWorld physics(w);
  std::vector<Rect> rects = w.obstacles;
  for (const Rect& r : surrounding_walls(w.floor, 1.0)) rects.push_back(r);
  const RayGrid grid(rects, {});
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  int compared = 0;
  for (int k = 0; k < 3000; ++k) {
    const Vec2 from{w.floor.xmin + w.floor.width() * u(rng),
                    w.floor.ymin + w.floor.height() * u(rng)};
    const Vec2 d = unit_from_angle(2 * M_PI * u(rng));
    const auto box2d = physics.box2d_ray_cast(from, from + 20.0 * d);
    const auto ours = grid.cast(from, d, 20.0);
    if (!box2d || box2d->kind == sim::SurfaceKind::kCharger || !ours)
      continue;  // the charger is not in `rects`
    ++compared;
    // Box2D holds the boxes in single precision: within a few of its ulps at 100 m.
    EXPECT_NEAR(ours->range_m, box2d->range_m, 1e-4) << k;
  }
  EXPECT_GT(compared, 1000);
}

}  // namespace
}  // namespace plantsim::geom

namespace plantsim::geom {
namespace {

// Every world the project and its tests use (the repository's, the shared benchmarks', the ROS
// maps and the MovingAI maps), each cast as the lidar casts it: a 360-beam fan over 270 degrees
// and the EKF's every-sixth-beam fan, from random points of the floor (inside obstacles too),
// the start and the charger's staging point. Each beam's range must be the single cast's within
// 1e-9 m (it is in fact equal), and a beam hits in one where it hits in the other.
std::vector<std::string> every_test_world() {
  namespace fs = std::filesystem;
  std::vector<std::string> paths;
  auto add = [&](const fs::path& folder, const std::string& ext, bool recursive) {
    if (!fs::is_directory(folder)) return;
    auto consider = [&](const fs::directory_entry& e) {
      if (e.is_regular_file() && e.path().extension() == ext) paths.push_back(e.path().string());
    };
    if (recursive)
      for (const auto& e : fs::recursive_directory_iterator(folder)) consider(e);
    else
      for (const auto& e : fs::directory_iterator(folder)) consider(e);
  };
  add(test::source_file("data/worlds"), ".json", true);
  add(test::shared_data("worlds"), ".json", false);
  add(test::shared_data("ros_maps"), ".yaml", false);
  add(test::shared_data("movingai/maps"), ".map", false);
  add(test::shared_data("anyangle"), ".map", false);
  std::sort(paths.begin(), paths.end());
  return paths;
}

TEST(RayGrid, FanEqualsSingleCastsOnEveryTestWorld) {
  const std::vector<std::string> paths = every_test_world();
  ASSERT_GT(paths.size(), 100u);
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> u(0, 1);
  long beams = 0, hits = 0, worlds_cast = 0;
  for (const std::string& path : paths) {
    std::optional<worlds::World> w;
    worlds::PoseOverrides poses_from;
    if (path.ends_with(".map")) {  // a MovingAI map: its .scen's first query gives the poses
      const std::string map_name = std::filesystem::path(path).filename().string();
      poses_from.movingai_scen = path.find("/anyangle/") != std::string::npos
                                     ? path.substr(0, path.size() - 4) + ".scen"
                                     : test::shared_data("movingai/scen/" + map_name + ".scen");
    }
    try {
      w = worlds::load_world(path, poses_from);
    } catch (const worlds::WorldError& e) {
      // Only the loaders' refusal fixtures may be refused (they are tested as such elsewhere).
      EXPECT_NE(path.find("/invalid"), std::string::npos) << path << ": " << e.what();
      continue;
    }
    ++worlds_cast;
    const worlds::SurfaceGrid grid(*w);
    std::vector<Pose2> poses{w->start, worlds::staging_pose(*w)};
    for (int k = 0; k < 12; ++k)
      poses.push_back({w->floor.xmin + w->floor.width() * u(rng),
                       w->floor.ymin + w->floor.height() * u(rng), 2 * M_PI * u(rng)});
    for (const Pose2& pose : poses)
      for (const int stride : {1, 6}) {
        const double fov = 1.5 * M_PI, increment = stride * fov / 359;
        const double first = pose.yaw - 0.5 * fov;
        std::vector<Vec2> directions;
        for (int b = 0; b < 360; b += stride)
          directions.push_back(unit_from_angle(first + (b / stride) * increment));
        std::vector<std::optional<worlds::RayHit>> fanned;
        grid.cast_fan(pose.position(), directions, first, increment, 20.0, fanned);
        ASSERT_EQ(fanned.size(), directions.size());
        for (std::size_t b = 0; b < directions.size(); ++b) {
          const auto single = grid.cast(pose.position(), directions[b], 20.0);
          ++beams;
          ASSERT_EQ(single.has_value(), fanned[b].has_value()) << path << " beam " << b;
          if (!single) continue;
          ++hits;
          ASSERT_NEAR(single->range_m, fanned[b]->range_m, 1e-9) << path << " beam " << b;
        }
      }
  }
  std::cout << worlds_cast << " of " << paths.size() << " worlds, " << beams << " beams, " << hits
            << " hits\n";
  EXPECT_GT(worlds_cast, 100);
  EXPECT_GT(hits, beams / 2);
}

}  // namespace
}  // namespace plantsim::geom

namespace plantsim::geom {
namespace {

// Casts the fan, and each of its rays singly: both must meet the same thing (the range bit for
// bit, and where `same_box` the same box). Returns the rays that met something.
long fan_matches_single_casts(const RayGrid& grid, Vec2 o, const std::vector<Vec2>& directions,
                              double first, double increment, double range_m, bool same_box) {
  FanHits fanned;
  grid.cast_fan(o, directions, first, increment, range_m, fanned);
  long hits = 0;
  for (std::size_t k = 0; k < directions.size(); ++k) {
    const auto single = grid.cast(o, directions[k], range_m);
    EXPECT_EQ(single.has_value(), fanned.hit(k)) << "ray " << k;
    if (!single || !fanned.hit(k)) continue;
    ++hits;
    EXPECT_EQ(single->range_m, fanned.range_m[k]) << "ray " << k;
    if (same_box) {
      EXPECT_EQ(single->box, fanned.box[k]) << "ray " << k;
    }
  }
  return hits;
}

// Fans from far outside the grid, where the rings centre on the grid's edge cell: the rays still
// open must walk from the sensor, not from where they would leave a square the sensor is not in.
TEST(RayGrid, FanFromOutsideTheGridEqualsSingleCasts) {
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> u(0, 1);
  // Sparse boxes, so that many rays stay open and walk; the sensor 5 to 30 m off the boxes' area.
  const std::vector<Rect> rects = random_rects(rng, 60, 0.2, 1.5);
  const RayGrid grid(rects, {});
  const Rect a = grid.area();
  long hits = 0;
  for (int fan = 0; fan < 400; ++fan) {
    const double side = u(rng);
    const Vec2 o = side < 0.25   ? Vec2{a.xmin - 5 - 25 * u(rng), a.ymin + a.height() * u(rng)}
                   : side < 0.5  ? Vec2{a.xmax + 5 + 25 * u(rng), a.ymin + a.height() * u(rng)}
                   : side < 0.75 ? Vec2{a.xmin + a.width() * u(rng), a.ymin - 5 - 25 * u(rng)}
                                 : Vec2{a.xmin - 5 - 25 * u(rng), a.ymin - 5 - 25 * u(rng)};
    const int n = 360;
    const double first = 2 * M_PI * u(rng), increment = 2 * M_PI / n;
    std::vector<Vec2> directions;
    for (int k = 0; k < n; ++k) directions.push_back(unit_from_angle(first + k * increment));
    SCOPED_TRACE("fan " + std::to_string(fan));
    hits += fan_matches_single_casts(grid, o, directions, first, increment, 150.0, false);
  }
  // Both kinds of ray exercised: those that meet a box and those that walk out of the grid.
  EXPECT_GT(hits, 0);
  EXPECT_LT(hits, 400L * 360);
}

}  // namespace
}  // namespace plantsim::geom

namespace plantsim::geom {
namespace {

// A fan wider than half a turn passes over the boxes in the wedge behind it, where no ray comes
// near: those astride the wedge's edges, and rays as far off their place in the fan as the
// fan allows (1e-6 rad), must still meet what single casts meet. Spans from just under half a
// turn (no wedge passed over) to nearly a whole turn, the lidar's 360 rays and the EKF's 60.
TEST(RayGrid, FanPassesOverOnlyTheBoxesBehindItsRays) {
  std::mt19937_64 rng(37);
  std::uniform_real_distribution<double> u(0, 1);
  const std::vector<Rect> rects = random_rects(rng, 300, 0.2, 2.0);
  const RayGrid grid(rects, {});
  long hits = 0;
  for (const double span : {M_PI - 1e-3, M_PI + 1e-7, 1.2 * M_PI, 1.5 * M_PI, 1.95 * M_PI})
    for (const int n : {360, 60})
      for (int fan = 0; fan < 60; ++fan) {
        Vec2 o{100 * u(rng), 60 * u(rng)};
        while (grid.near(o, 0.05)) o = {100 * u(rng), 60 * u(rng)};
        const double first = 2 * M_PI * u(rng), increment = span / (n - 1);
        std::vector<Vec2> directions;
        for (int k = 0; k < n; ++k)
          directions.push_back(unit_from_angle(first + k * increment + 1e-6 * (2 * u(rng) - 1)));
        SCOPED_TRACE("span " + std::to_string(span) + ", fan " + std::to_string(fan));
        hits += fan_matches_single_casts(grid, o, directions, first, increment, 20.0, true);
      }
  EXPECT_GT(hits, 5L * 60 * (360 + 60) / 2);  // most rays meet a box within 20 m
}

// The wedge's edges to the last micro-radian: a box lying almost wholly behind the fan, which its
// first or last ray (0.9e-6 rad off its place, within the fan's tolerance) enters 2e-7 rad inside
// the box's edge, 10 m out.
TEST(RayGrid, FanMeetsBoxesJustInsideItsEdgeRays) {
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> u(0, 1);
  int met = 0;
  for (const double span : {M_PI + 1e-7, 1.5 * M_PI, 1.95 * M_PI})
    for (const int n : {360, 60})
      for (int fan = 0; fan < 20; ++fan) {
        const Vec2 o{100 * u(rng), 60 * u(rng)};
        const double first = 2 * M_PI * u(rng), increment = span / (n - 1);
        const double first_ray = first - 0.9e-6, last_ray = first + span + 0.9e-6;
        // Boxes along a ray, 10 to 11 m out, reaching 2 m to its side: behind the last ray
        // counter-clockwise, behind the first clockwise.
        const double at_last = last_ray - 2e-7, at_first = first_ray + 2e-7;
        const std::vector<OrientedBox> boxes = {
            {o + rotate({10.5, 1.0}, at_last), 0.5, 1.0, at_last},
            {o + rotate({10.5, -1.0}, at_first), 0.5, 1.0, at_first}};
        const RayGrid grid({}, boxes);
        std::vector<Vec2> directions;
        for (int k = 0; k < n; ++k) directions.push_back(unit_from_angle(first + k * increment));
        directions.front() = unit_from_angle(first_ray);
        directions.back() = unit_from_angle(last_ray);
        FanHits fanned;
        grid.cast_fan(o, directions, first, increment, 20.0, fanned);
        for (const std::size_t k : {std::size_t{0}, directions.size() - 1}) {
          const auto single = grid.cast(o, directions[k], 20.0);
          ASSERT_TRUE(single) << "span " << span << " ray " << k;
          ASSERT_TRUE(fanned.hit(k)) << "span " << span << " ray " << k;
          EXPECT_EQ(single->range_m, fanned.range_m[k]) << "span " << span << " ray " << k;
          met += fanned.hit(k);
        }
      }
  EXPECT_EQ(met, 3 * 2 * 20 * 2);
}

}  // namespace
}  // namespace plantsim::geom
