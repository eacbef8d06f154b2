// Localisation a robot could trust where plantsim was never tuned: the global scan matcher on
// known answers, scans of open ground that say nothing, a kidnapped robot found again, a sparse
// plant crossed without giving up, and encoder noise that does not pass for slip.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <utility>
#include <vector>

#include "batch/batch_runner.h"
#include "episode/episode_config.h"
#include "episode/episode_config_json.h"
#include "episode/episode_result.h"
#include "episode/run_episode.h"
#include "geometry/predicates.h"
#include "planner/planner.h"
#include "planner/registry.h"
#include "robot/ekf_localizer.h"
#include "robot/global_match.h"
#include "robot/likelihood_field.h"
#include "robot/lost_search.h"
#include "robot/map_raycaster.h"
#include "robot/median_spread.h"
#include "robot/near_rasters.h"
#include "robot/particle_localizer.h"
#include "robot/place_hypotheses.h"
#include "robot/place_refinement.h"
#include "robot/scan_matcher.h"
#include "robot/scan_points.h"
#include "sim/kidnap_landing.h"
#include "test_paths.h"
#include "util/huge_page_block.h"
#include "worlds/surfaces.h"
#include "worlds/world_loader.h"

namespace plantsim::sim {
using namespace plantsim::episode;  // the episode's config and result
using episode::load_episode_config;
using episode::run_episode;

using namespace robot;  // the robot's side under test, beside the simulator that feeds it
namespace {

// An exact scan of `world` from `pose` (rays against its rectangles and walls), 360 beams over
// 270 degrees, 20 m.
LidarScan exact_scan(const worlds::World& world, const geom::Pose2& pose) {
  LidarScan s;
  s.angle_min_rad = -0.75 * M_PI;
  s.angle_increment_rad = 1.5 * M_PI / 359;
  s.min_range_m = 0.05;
  s.max_range_m = 20;
  std::vector<geom::Rect> rects = world.obstacles;
  for (const geom::Rect& r : geom::surrounding_walls(world.floor, 1.0)) rects.push_back(r);
  for (int i = 0; i < 360; ++i) {
    const geom::Vec2 u = geom::unit_from_angle(pose.yaw + s.angle(static_cast<std::size_t>(i)));
    double best = s.max_range_m;
    for (const geom::Rect& r : rects) {
      // Slab test of the ray against the box.
      double t0 = 0, t1 = 1e9;
      const double o[2] = {pose.x, pose.y}, d[2] = {u.x, u.y}, lo[2] = {r.xmin, r.ymin},
                   hi[2] = {r.xmax, r.ymax};
      bool hit = true;
      for (int a = 0; a < 2 && hit; ++a) {
        if (std::fabs(d[a]) < 1e-12) {
          hit = o[a] >= lo[a] && o[a] <= hi[a];
          continue;
        }
        double ta = (lo[a] - o[a]) / d[a], tb = (hi[a] - o[a]) / d[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        hit = t0 <= t1;
      }
      if (hit && t0 > 0) best = std::min(best, t0);
    }
    s.ranges.push_back(best);
  }
  return s;
}

// A plant of `boxes` on `floor`, starting at `start`, its charger at `charger`.
worlds::World plant(geom::Rect floor, std::vector<geom::Rect> boxes, geom::Pose2 start,
                    geom::Pose2 charger) {
  worlds::World w;
  w.floor = floor;
  w.obstacles = std::move(boxes);
  w.start = start;
  w.charger = charger;
  return w;
}

worlds::World l_room() {
  worlds::World w;
  w.name = "l_room";
  w.floor = {0, 0, 14, 9};
  w.obstacles = {{3, 2, 5, 3}, {8, 5, 9, 8}, {10, 1, 12, 2}};
  w.start = {1.5, 4.5, 0};
  w.charger = {13.5, 4.5, 0};
  return w;
}

// The network's spread is nth_element's bit for bit, its median equal (a zero's sign aside): every
// size up to the network's 64 and past it (selection), ties (values on a millimetre grid), both
// zeros, values all equal.
TEST(MedianSpread, EqualsTwoSelectionsBitForBit) {
  auto selected = [](std::vector<double> r) {
    const auto mid = r.begin() + static_cast<std::ptrdiff_t>(r.size() / 2);
    std::nth_element(r.begin(), mid, r.end());
    const double median = *mid;
    for (double& v : r) v = std::fabs(v - median);
    std::nth_element(r.begin(), mid, r.end());
    return robot::MedianSpread{median, *mid};
  };
  std::mt19937_64 rng(43);
  std::normal_distribution<double> residual(0.002, 0.01);
  long compared = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const std::size_t n = 1 + static_cast<std::size_t>(trial % 90);
    std::vector<double> values(n);
    for (double& v : values) {
      v = residual(rng);
      if (trial % 3 == 1) v = std::round(v * 1000) / 1000;   // ties
      if (trial % 7 == 2) v = (trial % 2 ? -0.0 : 0.0) * v;  // zeros of both signs
    }
    if (trial % 11 == 5) std::fill(values.begin(), values.end(), 0.25);
    const robot::MedianSpread want = selected(values);
    std::vector<double> ours = values;
    const robot::MedianSpread got = robot::median_spread(ours);
    ASSERT_EQ(got.median, want.median) << "n " << n;  // a zero's sign may differ
    ASSERT_EQ(std::memcmp(&got.mad, &want.mad, sizeof(double)), 0)
        << "n " << n << ": " << got.mad << " vs " << want.mad;
    ++compared;
  }
  EXPECT_EQ(compared, 4000);
}

TEST(ScanMatcher, FindsTheTruePoseFromAnOffPrior) {
  const worlds::World w = l_room();
  const ScanMatcher matcher(w);
  const geom::Pose2 truth{6.3, 4.1, 0.4};
  const LidarScan scan = exact_scan(w, truth);
  const auto m = matcher.match(scan, {7.2, 3.5, 0.5}, {2.0, 0.3});
  ASSERT_TRUE(m.has_value());
  EXPECT_TRUE(m->accepted) << "score " << m->score << ", runner-up " << m->runner_up;
  EXPECT_LT(geom::distance(m->pose.position(), truth.position()), 0.15);
  EXPECT_LT(std::fabs(geom::wrap_angle(m->pose.yaw - truth.yaw)), 0.03);  // the filter refines it
  // Branch and bound: far fewer poses scored than the window holds.
  const long window = static_cast<long>(std::pow(2 * 2.0 / matcher.resolution_m() + 1, 2));
  EXPECT_LT(m->scored, window);
}

TEST(ScanMatcher, AWideWindowAtAllHeadingsKeepsItsFullReach) {
  // A reseeding search's tile: +-3.5 m at every heading. Its rotation steps were once rounded so
  // that the window came out over the work budget and was narrowed to +-2.6 m, leaving gaps
  // between tiles 7 m apart; a robot 3 m off along x and turned half round was never found.
  const worlds::World w = l_room();
  ScanMatcherParams wide;
  wide.max_candidates =
      120'000;  // as the particle filter's reseeding searches (particle_localizer)
  const ScanMatcher matcher(w, wide);
  const geom::Pose2 truth{3.0, 6.8, 2.5};
  const LidarScan scan = exact_scan(w, truth);
  const auto m = matcher.match(scan, {6.0, 4.5, 0.0}, {3.5, M_PI});
  ASSERT_TRUE(m.has_value());
  // Coarse rotation steps: the truth among the places it lists, within a cell or two.
  double nearest = INFINITY;
  for (const auto& [pose, score] : m->alternatives)
    if (std::fabs(geom::wrap_angle(pose.yaw - truth.yaw)) < 0.1)
      nearest = std::min(nearest, geom::distance(pose.position(), truth.position()));
  EXPECT_LT(nearest, 0.25) << m->alternatives.size() << " places listed";
}

TEST(ScanMatcher, ALongFeaturelessCorridorIsAmbiguous) {
  worlds::World w;
  w.name = "corridor";
  w.floor = {0, 0, 60, 2};
  w.start = {2, 1, 0};
  w.charger = {59, 1, 0};
  const ScanMatcher matcher(w);
  const LidarScan scan = exact_scan(w, {30, 1, 0});
  const auto m = matcher.match(scan, {31.5, 1, 0}, {3.0, 0.1});
  ASSERT_TRUE(m.has_value());
  EXPECT_FALSE(m->accepted) << "score " << m->score << ", runner-up " << m->runner_up;
}

// A scan of one long wall alone (the floor's edge, 5 m ahead, nothing else in range): the match
// puts the returns on the wall's face, never inside the wall (a grid that scored a solid's inside
// let such a scan slide half a metre into it with a perfect score, on open ground a robot then
// believed itself lost), and along the wall it stays ambiguous.
// A lone wall seen from 3 m, its ends out of the lidar's range: the match is ambiguous along
// the wall, yet its near-best poses agree across it and in heading, and their spread says so.
// (The wall is 4 m thick: its far face, where the same returns would fit as well, lies outside
// the window.)
TEST(ScanMatcher, ALoneWallsSpreadIsOpenAlongItAndTightAcrossIt) {
  worlds::World w;
  w.name = "lone_wall";
  w.floor = {0, 0, 100, 60};
  w.obstacles = {{20, 27, 80, 31}};
  w.start = {50, 34, 0};
  w.charger = {99, 45, 0};
  const ScanMatcher matcher(w);
  const geom::Pose2 truth{50, 34, 0.1};
  const auto m = matcher.match(exact_scan(w, truth), {51.5, 33.4, 0.12}, {3.0, 0.2});
  ASSERT_TRUE(m.has_value());
  EXPECT_FALSE(m->accepted);
  EXPECT_NEAR(m->pose.y, truth.y, 0.15);  // a cell and a half of the grid
  EXPECT_NEAR(m->pose.yaw, truth.yaw, 0.02);
  EXPECT_GT(std::sqrt(m->spread(0, 0)), 1.0);   // along the wall: open
  EXPECT_LT(std::sqrt(m->spread(1, 1)), 0.15);  // across it: pinned
  EXPECT_LT(std::sqrt(m->spread(2, 2)), 0.03);
}

// The likelihood field holds the exact signed distance to the nearest mapped surface, within
// float rounding: positive on the floor, negative inside a block and beyond the floor's walls,
// linear across a flat surface (no half-cell offset), capped at the reach, the reach off the grid.
TEST(LikelihoodField, SignedExactDistancesCappedAtTheReach) {
  const worlds::World w = plant({0, 0, 20, 12}, {{8, 4, 12, 8}}, {2, 6, 0}, {19.5, 6, 0});
  const LikelihoodField field(w, 0.05, 1.0);
  const double tight = 1e-6;
  EXPECT_NEAR(field.distance({7.6, 6.0}), 0.4, tight);
  EXPECT_NEAR(field.distance({7.98, 6.1}), 0.02, tight);
  EXPECT_NEAR(field.distance({8.02, 6.1}), -0.02, tight);  // across the face, no step
  EXPECT_NEAR(field.distance({8.25, 6.0}), -0.25, tight);
  EXPECT_NEAR(field.distance({10.0, 6.0}), -1.0, tight);  // deep inside: the reach, negative
  EXPECT_NEAR(field.distance({10.0, 3.3}), 0.7, tight);
  EXPECT_NEAR(field.distance({4.0, 2.0}), 1.0, tight);    // open floor: capped
  EXPECT_NEAR(field.distance({4.0, -0.3}), -0.3, tight);  // beyond the floor's wall
  EXPECT_NEAR(field.distance({4.0, 0.3}), 0.3, tight);
  EXPECT_DOUBLE_EQ(field.distance({100.0, 100.0}), 1.0);  // off the grid
}

// The field's storage: zeroed, writable to its last byte, and owned by one block at a time.
TEST(HugePageBlock, ZeroedWritableAndMovable) {
  util::HugePageBlock block(5u << 20);
  ASSERT_NE(block.data(), nullptr);
  auto* bytes = static_cast<unsigned char*>(block.data());
  EXPECT_EQ(bytes[0], 0);
  EXPECT_EQ(bytes[block.size() - 1], 0);
  bytes[block.size() - 1] = 7;
  util::HugePageBlock moved(std::move(block));
  EXPECT_EQ(block.data(), nullptr);
  EXPECT_EQ(block.size(), 0u);
  EXPECT_EQ(static_cast<unsigned char*>(moved.data())[moved.size() - 1], 7);
  EXPECT_EQ(util::HugePageBlock(0).data(), nullptr);
}

// A pose measured with a spread open along x and tight along y moves the estimate along y only,
// and narrows it there; one beyond the gate changes nothing.
// Episodes on one plant share its field; a plant that differs by one box, or another
// resolution, gets a field of its own, with that box in it.
TEST(LikelihoodField, SharedAmongEpisodesOnTheSameMapOnly) {
  const worlds::World w = l_room();
  const auto a = shared_likelihood_field(w, 0.05);
  EXPECT_EQ(a.get(), shared_likelihood_field(worlds::World(w), 0.05).get());
  EXPECT_NE(a.get(), shared_likelihood_field(w, 0.1).get());
  worlds::World moved = w;
  ASSERT_FALSE(moved.obstacles.empty());
  moved.obstacles.front().xmin += 0.5;
  moved.obstacles.front().xmax += 0.5;
  const auto b = shared_likelihood_field(moved, 0.05);
  EXPECT_NE(a.get(), b.get());
  const LikelihoodField built(moved, 0.05);
  const geom::Rect& r = moved.obstacles.front();
  for (const geom::Vec2 p :
       {geom::Vec2{r.xmax + 0.2, 0.5 * (r.ymin + r.ymax)}, geom::Vec2{r.xmin - 0.3, r.ymin + 0.1}})
    EXPECT_EQ(b->distance(p), built.distance(p));
  EXPECT_NE(a->distance({r.xmax + 0.2, 0.5 * (r.ymin + r.ymax)}),
            b->distance({r.xmax + 0.2, 0.5 * (r.ymin + r.ymax)}));
}

// The nearness rasters likewise: two episodes' maps of one plant share a raster per margin; a
// plant one box apart, or another margin, gets its own, which knows that box.
TEST(MapRaycaster, NearnessRastersSharedAmongEpisodesOnTheSameMapOnly) {
  const worlds::World w = l_room();
  const worlds::SurfaceGrid one(w), again{worlds::World(w)};
  const auto a = shared_near_raster(one.grid(), 0.07);
  EXPECT_EQ(a.get(), shared_near_raster(again.grid(), 0.07).get());
  EXPECT_NE(a.get(), shared_near_raster(one.grid(), 0.08).get());
  worlds::World moved = w;
  ASSERT_FALSE(moved.obstacles.empty());
  moved.obstacles.front().xmin += 0.5;
  moved.obstacles.front().xmax += 0.5;
  const worlds::SurfaceGrid other(moved);
  const auto b = shared_near_raster(other.grid(), 0.07);
  EXPECT_NE(a.get(), b.get());
  const geom::Rect& r = moved.obstacles.front();
  const geom::Vec2 inside{r.xmax - 0.2, 0.5 * (r.ymin + r.ymax)};  // 0.3 m off the box unmoved
  EXPECT_EQ(b->at(inside), geom::NearRaster::Answer::kYes);
  EXPECT_EQ(a->at(inside), geom::NearRaster::Answer::kNo);
  // And a raycaster's answers are the grid's, whichever episode built the raster.
  const MapRaycaster first(w), second(w);
  const auto near_first = first.surface_near(0.07), near_second = second.surface_near(0.07);
  for (double x = w.floor.xmin; x <= w.floor.xmax; x += 0.13)
    for (double y = w.floor.ymin; y <= w.floor.ymax; y += 0.17) {
      EXPECT_EQ(near_first({x, y}), one.grid().near({x, y}, 0.07)) << x << "," << y;
      EXPECT_EQ(near_second({x, y}), one.grid().near({x, y}, 0.07)) << x << "," << y;
    }
}

// A correlative match's answer is a grid cell and a rotation step off; refined on the exact
// likelihood field it lands on the pose the scan was taken from, and the ray-cast check that
// rejected the coarse answer (a return 20 m away moved 20 cm) accepts it.
TEST(PlaceRefinement, BringsAGridAnswerOntoTheTruePose) {
  const worlds::World w = l_room();
  const geom::Pose2 truth{6.3, 4.1, 0.4};
  const LidarScan scan = exact_scan(w, truth);
  const LikelihoodField field(w, 0.05);
  const geom::Pose2 coarse{truth.x + 0.12, truth.y - 0.08, truth.yaw + 0.025};
  const geom::Pose2 fine = refine_on_field(field, scan_points(scan, 90), coarse, 0.2, 0.05);
  EXPECT_NEAR(fine.x, truth.x, 0.01);
  EXPECT_NEAR(fine.y, truth.y, 0.01);
  EXPECT_NEAR(geom::wrap_angle(fine.yaw - truth.yaw), 0.0, 0.003);
  const MapRaycaster map(w);
  EXPECT_LT(*scan_agreement(map, scan, coarse, 0.05), 0.8);
  EXPECT_GT(*scan_agreement(map, scan, fine, 0.05), 0.95);
}

// Three places after a reseed: one the scans keep contradicting, one that trails the best by a
// little on every scan (a look-alike that differs in a beam or two), and the best. The first goes
// after `strikes` scans, the second once its summed log-likelihood trails by the margin; the
// best is then the only place, and no rival of an estimate on it is left.
TEST(PlaceHypotheses, ContradictedOrTrailingPlacesAreRuledOutAndMoveWithTheOdometry) {
  PlaceHypotheses places;
  places.reset({{0, 0, 0}, {8, 0, 0}, {0, 8, 0}});
  auto judge = [](geom::Pose2& p) {
    if (p.y > 4) return PlaceHypotheses::Verdict{true, -1.0};  // contradicted, yet fits
    return PlaceHypotheses::Verdict{false, p.x > 4 ? -3.0 : -1.0};
  };
  places.check(judge, 3, 10.0);
  places.check(judge, 3, 10.0);
  EXPECT_EQ(places.rivals({0, 0, 0}, 1.0, 0.3).size(), 2u) << "two strikes, 4 behind: all live";
  places.check(judge, 3, 10.0);
  EXPECT_EQ(places.rivals({0, 0, 0}, 1.0, 0.3).size(), 1u) << "three strikes: ruled out";
  places.check(judge, 3, 10.0);
  places.check(judge, 3, 10.0);
  EXPECT_EQ(places.rivals({0, 0, 0}, 1.0, 0.3).size(), 1u) << "10 behind: not beyond the margin";
  places.check(judge, 3, 10.0);
  EXPECT_TRUE(places.rivals({0, 0, 0}, 1.0, 0.3).empty()) << "12 behind: the look-alike is gone";
  EXPECT_TRUE(places.holds({0.5, 0, 0.1}, 1.0, 0.3));
  places.move({2, 0, M_PI / 2});  // the robot drove 2 m and turned left
  EXPECT_TRUE(places.holds({2, 0, M_PI / 2}, 0.01, 0.01));
  EXPECT_FALSE(places.holds({0, 0, 0}, 1.0, 0.3));
  // The place nearest an estimate moved onto it (the estimate fits the scan clearly better).
  places.move_nearest({2.4, 0, M_PI / 2}, 1.0, 0.3, {2.4, 0, M_PI / 2});
  EXPECT_TRUE(places.holds({2.4, 0, M_PI / 2}, 0.01, 0.01));
  EXPECT_FALSE(places.holds({2, 0, M_PI / 2}, 0.3, 0.01));
  places.move_nearest({9, 9, 0}, 1.0, 0.3, {9, 9, 0});  // none near: nothing moves
  EXPECT_FALSE(places.holds({9, 9, 0}, 1.0, 0.3));
}

// A scan of `world` from `pose` as a short-range lidar sees it (6 m: open ground shows a handful
// of returns or none).
LidarScan short_scan(const worlds::World& world, const geom::Pose2& pose, double t_s) {
  LidarScan s = exact_scan(world, pose);
  s.t_s = t_s;
  s.max_range_m = 6;
  for (double& r : s.ranges) r = std::min(r, s.max_range_m);
  return s;
}

// Kidnapped on open ground, where the lidar sees one small box (about 13 returns, fewer than a
// contradiction needs) or nothing: the view changed at once, and the particle filter reports
// itself lost within half a second rather than driving on for the 16 s it took before.
TEST(Particles, AKidnapOnOpenGroundIsNoticedFromAHandfulOfReturnsOrNone) {
  worlds::World yard;
  yard.name = "yard";
  yard.floor = {0, 0, 60, 60};
  yard.obstacles = {{29.75, 32.75, 30.25, 33.25}, {44.75, 12.75, 45.25, 13.25}};
  yard.start = {30, 30, M_PI / 2};
  yard.charger = {59, 30, 0};
  const MapRaycaster map(yard);
  for (const geom::Pose2 landing : {geom::Pose2{45, 10, 0}, geom::Pose2{50, 50, 0}}) {
    ParticleLocalizer filter(yard, map, EkfParams{}, GlobalMatchParams{}, ParticleParams{});
    const double dt = 1.0 / 15;
    int k = 0;
    for (; k < 30; ++k) {
      filter.predict(0, 0, dt);
      filter.observe(short_scan(yard, yard.start, k * dt));
    }
    const LidarScan before = short_scan(yard, yard.start, 0);
    ASSERT_GE(valid_returns(before), 10);
    ASSERT_LT(valid_returns(before), ParticleParams{}.min_returns);
    ASSERT_NE(filter.health(), LocalizationHealth::kLost);
    int scans = 0;
    for (; scans < 45 && filter.health() != LocalizationHealth::kLost; ++scans, ++k) {
      filter.predict(0, 0, dt);
      filter.observe(short_scan(yard, landing, k * dt));
    }
    EXPECT_LE(scans, ParticleParams{}.view_change_lost_scans + 1)
        << "set down at " << landing.x << ", " << landing.y << " with "
        << valid_returns(short_scan(yard, landing, 0)) << " returns";
  }
}

// Settled, the filter weighs a scan as AMCL does, after update_min_m of travel (0.25 m): between
// those, the particles are left alone (the same view weighed again would make the set surer than
// the scans are, and costs) while the estimate follows the odometry and every scan is still
// judged against the map.
TEST(Particles, ASettledFilterWeighsAfterATravelAndFollowsTheOdometryBetween) {
  const worlds::World w = l_room();
  const MapRaycaster map(w);
  ParticleLocalizer filter(w, map, EkfParams{}, GlobalMatchParams{}, ParticleParams{});
  const double dt = 1.0 / 15, speed = 0.5;
  int k = 0;
  for (; k < 30; ++k) {  // at rest until settled
    filter.predict(0, 0, dt);
    filter.observe(exact_scan(w, w.start));
  }
  ASSERT_EQ(filter.health(), LocalizationHealth::kOk);
  geom::Pose2 truth = w.start;
  int updates = 0, scans = 0;
  for (; truth.x < w.start.x + 1.5; ++k, ++scans) {
    const std::vector<ParticleLocalizer::Particle> before = filter.particles();
    truth.x += speed * dt;
    filter.predict(speed * dt, 0, dt);
    LidarScan scan = exact_scan(w, truth);
    scan.t_s = k * dt;
    filter.observe(scan);
    const std::vector<ParticleLocalizer::Particle>& after = filter.particles();
    updates += after.size() != before.size() || after.front().x != before.front().x;
    EXPECT_NEAR(filter.pose().x, truth.x, 0.02) << "scan " << scans;
    EXPECT_NEAR(filter.pose().y, truth.y, 0.02) << "scan " << scans;
  }
  EXPECT_EQ(filter.health(), LocalizationHealth::kOk);
  // 1.5 m in steps of 3.3 cm: an update every eighth scan, six in all (every scan moved the
  // particles before).
  EXPECT_GE(updates, 5);
  EXPECT_LE(updates, 7) << "of " << scans << " scans";
}

// A box the map lacks fills the view on an open yard: the scan contradicts the estimate. Then the
// view shows a mapped box again beside a smaller unmapped one: too few beams meet a mapped
// surface to judge by agreement, but the map explains a fair share of the returns. That ends the
// run of contradictions (the count had stayed frozen at 14, the filter degraded and the robot
// waiting for it until it gave up: held-out yard_s7 seed 1, three unmapped boxes, cc2201b).
TEST(Particles, AFairShareOfExplainedReturnsEndsARunOfContradictions) {
  const worlds::World map =
      plant({0, 0, 100, 100}, {{52, 49.8, 52.5, 50.2}}, {50, 50, 0}, {99, 50, 0});
  worlds::World blocked = map, beside = map;
  blocked.obstacles.push_back({51, 46, 52, 54});   // unmapped, hiding the mapped box
  beside.obstacles.push_back({51.5, 51, 52, 52});  // unmapped, smaller, off to the side
  const MapRaycaster raycaster(map);
  ParticleLocalizer filter(map, raycaster, EkfParams{}, GlobalMatchParams{}, ParticleParams{});
  const double dt = 1.0 / 15;
  int k = 0;
  auto scans = [&](const worlds::World& truth, int count) {
    for (int i = 0; i < count; ++i, ++k) {
      LidarScan scan = exact_scan(truth, map.start);
      scan.t_s = k * dt;
      filter.predict(0, 0, dt);
      filter.observe(scan);
    }
  };
  // Beside one small box at a standstill the spread settles slowly, about the ok bound (4 cm):
  // how many scans it takes depends on the filter's draws.
  scans(map, 30);
  for (int more = 0; more < 150 && filter.health() != LocalizationHealth::kOk; ++more)
    scans(map, 1);
  ASSERT_EQ(filter.health(), LocalizationHealth::kOk);
  // One contradicting scan (two would start a search, which on this bare map finds nothing
  // better and clears the count itself; in a plant it found look-alikes the beams rejected).
  scans(blocked, 1);
  ASSERT_EQ(filter.failed_matches(), 1);
  const LidarScan view = exact_scan(beside, map.start);
  ASSERT_GE(valid_returns(view), ParticleParams{}.min_returns);
  ASSERT_FALSE(scan_agreement(raycaster, view, map.start, 0.05).has_value()) << "no agreement";
  scans(beside, 3);
  EXPECT_EQ(filter.failed_matches(), 0);
  EXPECT_EQ(filter.health(), LocalizationHealth::kOk);
  EXPECT_LT(geom::distance(filter.pose().position(), map.start.position()), 0.05);
}

// Lost in a long bare hall (every place along it looks alike), the search turns once on the
// spot, then drives along the nearest wall, keeping off it; its guard sees the walls ahead and
// nothing behind (the lidar's blind quarter is never free).
TEST(LostSearch, TurnsOnceThenFollowsTheNearestWallAndKeepsOffIt) {
  worlds::World hall;
  hall.floor = {0, 0, 40, 3};
  LostSearch search({}, 0.2);
  const LidarScan side = exact_scan(hall, {5, 1.5, 0});
  EXPECT_NEAR(search.free_ahead(side, 0.0), 20.0, 1e-9);             // capped at the lidar's range
  EXPECT_NEAR(search.free_ahead(side, M_PI / 2), 1.5 - 0.55, 1e-6);  // the wall, less the disk
  EXPECT_EQ(search.free_ahead(side, M_PI), 0.0);                     // behind: unseen, not free
  geom::Pose2 pose{5, 1.2, 1.0};
  const double dt = 0.1;
  double turned = 0, driven = 0;
  for (int k = 0; k < 1200 && driven < 6.0; ++k) {
    const controller::Twist t = search.step(exact_scan(hall, pose), pose);
    if (driven == 0) turned += std::fabs(t.omega_radps) * dt;
    const geom::Vec2 before = pose.position();
    pose = geom::compose(pose, {t.v_mps * dt, 0, t.omega_radps * dt});
    driven += geom::distance(before, pose.position());
    ASSERT_GT(pose.y, 0.5);
    ASSERT_LT(pose.y, 2.5);
  }
  EXPECT_GE(turned, 2 * M_PI - 0.1);
  EXPECT_GE(driven, 6.0);
  EXPECT_LT(std::fabs(std::sin(pose.yaw)), 0.3) << "along the hall";
  EXPECT_TRUE(search.driving());
}

// Lost in a corridor narrower than the footprint and twice the clearance (1.2 m for a 0.6 m disk
// and 0.35 m a side), no heading is free by the clearance: the search drives along the corridor
// with the narrow clearance, never touching a wall. Held to the full clearance it would turn on
// the spot until the relocalisation timeout (held-out corridors_s6 seed 8, 1270d62).
TEST(LostSearch, DrivesACorridorNarrowerThanItsClearance) {
  worlds::World corridor;
  corridor.floor = {0, 0, 40, 1.2};
  const double radius = 0.3, dt = 0.1;
  auto search_drives = [&](LostSearchParams params) {
    LostSearch search(params, radius);
    geom::Pose2 pose{8, 0.6, 0.3};
    double driven = 0;
    for (int k = 0; k < 600 && driven < 6.0; ++k) {  // a minute
      const controller::Twist t = search.step(exact_scan(corridor, pose), pose);
      const geom::Vec2 before = pose.position();
      pose = geom::compose(pose, {t.v_mps * dt, 0, t.omega_radps * dt});
      driven += geom::distance(before, pose.position());
      EXPECT_GT(pose.y - radius, 0.0) << "touched the lower wall at step " << k;
      EXPECT_LT(pose.y + radius, 1.2) << "touched the upper wall at step " << k;
      if (pose.y - radius <= 0.0 || pose.y + radius >= 1.2) break;
    }
    return driven;
  };
  const LostSearchParams defaults;
  ASSERT_GT(2 * radius + 2 * defaults.clearance_m, 1.2);
  EXPECT_GE(search_drives(defaults), 6.0);
  LostSearchParams no_narrow_way = defaults;
  no_narrow_way.narrow_clearance_m = defaults.clearance_m;
  EXPECT_EQ(search_drives(no_narrow_way), 0.0) << "only the full clearance: turns on the spot";
}

TEST(Ekf, APoseMeasuredInOneDirectionUpdatesThatDirectionOnly) {
  const worlds::World w = l_room();
  const MapRaycaster map(w);
  EkfParams p;
  p.initial_position_sigma_m = 2.0;
  p.initial_yaw_sigma_rad = 0.2;
  EkfLocalizer ekf(p, {6, 4, 0}, map);
  Eigen::Matrix3d r = Eigen::Matrix3d::Zero();
  r.diagonal() << 100.0, 0.01, 0.0004;
  ASSERT_TRUE(ekf.update_pose({7, 5, 0.05}, r, 16.27));
  EXPECT_NEAR(ekf.pose().y, 5.0, 0.01);
  EXPECT_NEAR(ekf.pose().yaw, 0.05, 0.002);
  EXPECT_NEAR(ekf.pose().x, 6.0 + 4.0 / 104.0, 1e-6);  // P / (P + R) of the x innovation
  EXPECT_LT(std::sqrt(ekf.covariance()(1, 1)), 0.1);
  EXPECT_GT(std::sqrt(ekf.covariance()(0, 0)), 1.9);
  const geom::Pose2 before = ekf.pose();
  r.diagonal() << 0.01, 0.01, 0.0004;
  // 3 m across, where the estimate is now sure to 0.1 m: a look-alike, refused.
  EXPECT_FALSE(ekf.update_pose({before.x, before.y + 3.0, before.yaw}, r, 16.27));
  EXPECT_EQ(ekf.pose().y, before.y);
}

TEST(ScanMatcher, ReturnsFitAWallsFaceNotItsInside) {
  worlds::World w;
  w.name = "yard";
  w.floor = {0, 0, 100, 60};
  w.start = {5, 30, 0};
  w.charger = {5, 5, M_PI};  // far out of range
  const ScanMatcher matcher(w);
  const geom::Pose2 truth{95, 30, 0};
  const LidarScan scan = exact_scan(w, truth);
  for (const double toward_wall : {0.3, 0.6}) {
    const auto m = matcher.match(scan, {95 + toward_wall, 30, 0.02}, {1.0, 0.1});
    ASSERT_TRUE(m.has_value());
    EXPECT_NEAR(m->pose.x, truth.x, 0.1 + 1e-9) << toward_wall;
    EXPECT_NEAR(m->pose.yaw, truth.yaw, 0.011) << toward_wall;
    EXPECT_FALSE(m->accepted) << "along the wall nothing places it";
    EXPECT_LT(matcher.likelihood({100.5, 30}), 0.01);  // half a metre inside the wall
    EXPECT_GT(matcher.likelihood({100.02, 30}), 0.9);  // on its face
  }
}

EpisodeResult run(const worlds::World& w, const EpisodeConfig& c) {
  auto p = planner::make_planner("vg", planner::planner_input(w, true));
  return run_episode(w, *p, c);
}

TEST(Localization, AKidnappedRobotFindsItselfAgainAndDocks) {
  EpisodeConfig c;
  c.kidnap = {8.0, 0.0, -1.2, 0.3};  // set down 1.2 m aside and turned, mid-travel
  const EpisodeResult r = run(l_room(), c);
  EXPECT_TRUE(r.docked) << episode::status_name(r)
                        << (r.failure ? ": " + r.failure->detail : std::string());
  EXPECT_GE(r.relocalizations, 1);
  EXPECT_EQ(r.collisions, 0);
}

// The drawn kidnap (scenarios' random_kidnap): always within its distances, on free floor
// clear of everything the plant holds by the robot's radius and 0.2 m, any heading; the same
// seed the same landing.
TEST(KidnapLanding, LandsOnFreeFloorWithinItsDistances) {
  worlds::World w =
      worlds::load_world(test::source_file("data/worlds/generated/styles/dense_s1.json"));
  w.unmapped.push_back({40, 20, 41, 21});
  const double clear = w.robot.radius_m + 0.2;
  double min_yaw = 10, max_yaw = -10;
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    const geom::Vec2 from{50, 30};
    const auto to = sim::kidnap_landing(w, from, 3.0, 10.0, seed);
    ASSERT_TRUE(to) << seed;
    const double d = geom::distance(from, to->position());
    EXPECT_GE(d, 3.0 - 1e-9);
    EXPECT_LE(d, 10.0 + 1e-9);
    for (const geom::Rect& r : w.obstacles)
      EXPECT_FALSE(geom::in_closed_rect(r.inflated(clear), to->position())) << seed;
    for (const geom::Rect& r : w.unmapped)
      EXPECT_FALSE(geom::in_closed_rect(r.inflated(clear), to->position())) << seed;
    min_yaw = std::min(min_yaw, to->yaw), max_yaw = std::max(max_yaw, to->yaw);
    const auto again = sim::kidnap_landing(w, from, 3.0, 10.0, seed);
    EXPECT_EQ(again->x, to->x);
    EXPECT_EQ(again->yaw, to->yaw);
  }
  EXPECT_LT(min_yaw, -2.5);
  EXPECT_GT(max_yaw, 2.5);
  // A floor with no room that far: no landing (the episode leaves the robot where it was).
  worlds::World hall;
  hall.floor = {0, 0, 4, 2};
  hall.charger = {3.5, 1, 0};
  EXPECT_FALSE(sim::kidnap_landing(hall, {1, 1}, 5.0, 6.0, 1));
}

TEST(Localization, ParticlesFindAKidnappedRobotAgainAndDock) {
  EpisodeConfig c;
  c.perception.estimator = "particles";
  c.kidnap = {8.0, 0.0, -1.2, 0.3};  // the EKF's test above, with the particle filter
  const EpisodeResult near = run(l_room(), c);
  EXPECT_TRUE(near.docked) << episode::status_name(near)
                           << (near.failure ? ": " + near.failure->detail : std::string());
  EXPECT_EQ(near.collisions, 0);
  // Carried 5 to 8 m and set down at any heading, in a plant of racks (a tuning-set world): past
  // the EKF's search window (its global match covers about 2.5 m at all headings), found again
  // by reseeding from global matches. The mechanism, on two draws; how often it works is
  // measured by data/scenarios/kidnap_particles.yaml. With the sensors' and the filter's draws
  // of the PCG streams (util/random_stream.h), seed 1 settles on a look-alike 3.7 m off and docks
  // from it (docked_off_estimate, 1 of seeds 1-12 here; the failure class issue 49 leaves open);
  // seeds 2 and 3 show the mechanism.
  const worlds::World racks =
      worlds::load_world(test::source_file("data/worlds/generated/styles/racks_s1.json"));
  c.kidnap = {20.0, 0, 0, 0, 5.0, 8.0};
  for (const std::uint64_t seed : {2u, 3u}) {
    c.seed = seed;
    const EpisodeResult r = run(racks, c);
    EXPECT_TRUE(r.docked) << seed << ": " << episode::status_name(r)
                          << (r.failure ? ": " + r.failure->detail : std::string());
    EXPECT_GE(r.relocalizations, 1) << seed;
    EXPECT_FALSE(r.integrity.breach.has_value()) << seed;
  }
  c.perception.estimator = "ekf";  // the EKF on the same draw
  const EpisodeResult ekf = run(racks, c);
  EXPECT_FALSE(ekf.docked) << "the EKF's window does not reach this far";
}

TEST(Localization, AKidnapPastEveryWindowEndsLocalizationLost) {
  worlds::World w;  // a bare hall: every place along its walls looks alike
  w.name = "hall";
  w.floor = {0, 0, 40, 3};
  w.start = {1.5, 1.5, 0};
  w.charger = {39, 1.5, 0};
  EpisodeConfig c;
  c.kidnap = {5.0, 12.0, 0.0, 0.0};
  c.detection.enabled = false;
  c.timeout_s = 200;
  const EpisodeResult r = run(w, c);
  ASSERT_TRUE(r.failure.has_value()) << episode::status_name(r);
  EXPECT_EQ(to_string(r.failure->reason), "localization_lost") << r.failure->detail;
}

TEST(Localization, ASparsePlantIsCrossedWithoutGivingUpAndNeverOkWhenFarOff) {
  // A tuning-set world (seed 1 of the sparse style): 8 boxes on 100 x 60 m, long stretches where
  // the lidar sees nothing; it failed with "degraded" and a true error of 9 mm before.
  const worlds::World w =
      worlds::load_world(test::source_file("data/worlds/generated/styles/sparse_s1.json"));
  const EpisodeConfig c = load_episode_config(test::source_file("configs/noisy_sensing.json"));
  const EpisodeResult r = run(w, c);
  EXPECT_TRUE(r.docked) << episode::status_name(r)
                        << (r.failure ? ": " + r.failure->detail : std::string());
  // Consistency: the status never says ok while the estimate is far off.
  if (r.localization_error_max_m > 0.10) {
    EXPECT_NE(r.localization_status, "ok");
  }
  // Open ground grew the estimate: the robot slowed, it did not stop (a stop to settle after
  // the estimate jumped back onto the map lasts a second or two).
  double stopped_since = -1, longest_stop = 0;
  for (const auto& s : r.trajectory) {
    if (s.phase != controller::DockPhase::kTravel) continue;
    const bool stopped = std::fabs(s.speed_mps) < 0.01;
    if (stopped && stopped_since < 0) stopped_since = s.t_s;
    if (!stopped) stopped_since = -1;
    if (stopped_since >= 0) longest_stop = std::max(longest_stop, s.t_s - stopped_since);
  }
  EXPECT_LT(longest_stop, 5.0);
  std::printf("longest stop while travelling %.1f s, relocalisations %d, worst error %.2f m (%s)\n",
              longest_stop, r.relocalizations, r.localization_error_max_m,
              r.localization_status.c_str());
}

// The record of the one episode a scenario of one world, one fault and one seed runs, through
// the batch (as a user reruns one): `faults_and_seed` is the scenario's text from `faults:` on.
nlohmann::json run_one_scenario_episode(const std::string& name, const std::string& generated,
                                        const std::string& faults_and_seed) {
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::temp_directory_path() / ("plantsim_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "s.yaml") << "name: " << name << "\nworlds: ["
                                << test::source_file("data/worlds/generated/" + generated)
                                << "]\nplanners: [vg]\n"
                                << faults_and_seed;
  batch::RunOptions o;
  o.out_dir = (dir / "out").string();
  o.progress = false;
  o.figures = false;
  o.threads = 1;
  batch::run_batch((dir / "s.yaml").string(), o);
  std::ifstream in(dir / "out" / "episodes.jsonl");
  std::string line;
  std::getline(in, line);
  fs::remove_all(dir);
  return line.empty() ? nlohmann::json() : nlohmann::json::parse(line);
}

// A tuning-set episode (yard_s3, six boxes the map lacks, a wet floor, start 22): after open
// ground the estimate's spread had grown to 0.7 m while it stayed 7 cm from the truth; coming up
// to a box the map lacks, the returns from it were counted against every pose (the map has no
// surface there), the robot judged itself lost, stopped, looked round for 20 s and failed
// `localization_lost`. A return where the map has nothing in range is something the map lacks,
// as one short of a mapped surface is; and an estimate that reads what the map predicts is not
// contradicted, even when no single place fits the scan.
TEST(Localization, BoxesTheMapLacksInAnOpenYardDoNotMakeARightEstimateLost) {
  const nlohmann::json j = run_one_scenario_episode(
      "yard_boxes", "styles/yard_s3.json",
      "faults:\n  unmapped6_wet: {unmapped_obstacles: 6, drive: {tyre_friction: 0.1}}\n"
      "seeds: [22]\n");
  ASSERT_FALSE(j.is_null());
  EXPECT_TRUE(j["succeeded"].get<bool>()) << j.dump().substr(0, 400);
  EXPECT_EQ(j["collisions"].get<int>(), 0);
}

// A tuning-set episode (yard_s3, very wet, every noise doubled, the robot untold, seed 1): lost 8 m
// off after 150 s of open ground, the robot was pulled to a look-alike 2 m off by an ambiguous
// match repeated every period, each time as if new, while the window shrank with the estimate
// until the look-alikes left it; it then reported itself ok there for 101 s and failed. On the
// shortest path: the coastal route (robot/coastal_route.h) avoids that open ground.
TEST(Localization, AnAmbiguousMatchRepeatedDoesNotBecomeCertainty) {
  const nlohmann::json j =
      run_one_scenario_episode("yard_alike", "styles/yard_s3.json",
                               "controllers:\n  shortest: {coastal: {enabled: false}}\n"
                               "faults:\n  very_wet_noise2x_untold:\n"
                               "    drive: {tyre_friction: 0.05}\n"
                               "    odometry: {wheel_speed_noise: 0.04, left_scale_error: 0.006, "
                               "right_scale_error: -0.006}\n"
                               "    lidar: {range_noise_m: 0.06, dropout_probability: 0.1}\n"
                               "    imu: {yaw_rate_noise_radps: 0.012, bias_radps: 0.012}\n"
                               "    detection: {position_noise_m: 0.01, yaw_noise_rad: 0.01, "
                               "false_negative_probability: 0.6,"
                               " outlier_probability: 0.06, latency_s: 0.4}\n"
                               "seeds: [1]\n");
  ASSERT_FALSE(j.is_null());
  // Never ok while more than 0.10 m off for longer than a blink.
  EXPECT_LT(j["ok_while_off_s"].get<double>(), 1.0) << j.dump().substr(0, 400);
  // It knew it was lost, yet drove on: 88 m in all on an estimate more than 0.25 m off (263 s,
  // measured on e03a352) before the charger's marker found it. Issue 89 closed that loophole of
  // the integrity rule: it charged, but it is no success, and the record says why.
  EXPECT_TRUE(j["charging"].get<bool>()) << j.dump().substr(0, 400);
  EXPECT_FALSE(j["succeeded"].get<bool>());
  EXPECT_EQ(j["status"], "docked_off_estimate");
  EXPECT_EQ(j["failure"], "localization_lost");
  EXPECT_GT(j["driven_off_estimate_m"].get<double>(), 1.0);
  EXPECT_NE(j["failure_detail"].get<std::string>().find("whatever its estimator reported"),
            std::string::npos)
      << j["failure_detail"];
}

// A tuning-set episode on the larger floor (sparse_s21 at 160 x 90 m, no fault, start seed 3):
// after open ground the robot called itself lost by its spread alone while 1 cm off; a global
// match on the floor's wall 12 m away restarted it 0.29 m off, and along that lone wall nothing
// corrected it for 160 s (docked, but failed by the integrity rule). A match the estimate already
// holds is fused with it, not restarted from.
TEST(Localization, AMatchTheEstimateHoldsIsFusedNotRestartedFrom) {
  const nlohmann::json j = run_one_scenario_episode("lone_wall", "large_tuning/sparse_s21.json",
                                                    "faults:\n  none: {}\nseeds: [3]\n");
  ASSERT_FALSE(j.is_null());
  EXPECT_TRUE(j["succeeded"].get<bool>()) << j.dump().substr(0, 400);
  EXPECT_LT(j["localization_error_max_m"].get<double>(), 0.1) << j.dump().substr(0, 400);
}

TEST(Localization, EncoderNoiseAloneDoesNotPassForSlip) {
  EpisodeConfig c;
  c.odometry.wheel_speed_noise = 0.04;  // twice the noisy level
  const EpisodeResult r = run(l_room(), c);
  EXPECT_TRUE(r.docked) << episode::status_name(r);
  EXPECT_EQ(r.slips, 0);
  EXPECT_EQ(r.recoveries, 0);
}

}  // namespace
}  // namespace plantsim::sim
