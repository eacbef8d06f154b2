// Exact predicates: table-driven cases and a cross-check of orient() against integer
// arithmetic on random near-degenerate inputs.
#include <gtest/gtest.h>

#include <random>

#include "geometry/bounded_atan2.h"
#include "geometry/clearance.h"
#include "geometry/predicates.h"

namespace plantsim::geom {
namespace {

TEST(Orient, BasicCases) {
  EXPECT_EQ(orient({0, 0}, {1, 0}, {0, 1}), Orientation::kCounterClockwise);
  EXPECT_EQ(orient({0, 0}, {1, 0}, {0, -1}), Orientation::kClockwise);
  EXPECT_EQ(orient({0, 0}, {1, 1}, {3, 3}), Orientation::kCollinear);
}

TEST(Orient, NearlyCollinearDecidedExactly) {
  // 0.1 is not representable: the three points are not exactly collinear in doubles, and the
  // naive determinant gets the sign wrong or zero for some of these perturbations.
  const Vec2 a{0.1, 0.1}, b{0.3, 0.3};
  const Vec2 c{0.7, 0.7};
  const Vec2 c_up{0.7, std::nextafter(0.7, 1.0)}, c_down{0.7, std::nextafter(0.7, 0.0)};
  // Exactly: a=(0.1d,0.1d), b=(0.3d,0.3d) lie on y=x since each pair has equal coordinates.
  EXPECT_EQ(orient(a, b, c), Orientation::kCollinear);
  EXPECT_EQ(orient(a, b, c_up), Orientation::kCounterClockwise);
  EXPECT_EQ(orient(a, b, c_down), Orientation::kClockwise);
}

// Coordinates k * 2^-20 with |k| < 2^26: the determinant in integers fits in __int128.
TEST(Orient, MatchesIntegerArithmeticOnRandomDegenerateInputs) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<std::int64_t> coord(-(1LL << 26), 1LL << 26);
  std::uniform_int_distribution<int> small(-3, 3);
  const double unit = std::ldexp(1.0, -20);
  for (int i = 0; i < 200000; ++i) {
    const std::int64_t ax = coord(rng), ay = coord(rng), bx = coord(rng), by = coord(rng);
    // c near the line through a and b: a + t (b - a) + tiny integer offset.
    const std::int64_t t = small(rng);
    const std::int64_t cx = ax + t * (bx - ax) / 4 + small(rng),
                       cy = ay + t * (by - ay) / 4 + small(rng);
    if (std::llabs(cx) > (1LL << 28) || std::llabs(cy) > (1LL << 28)) continue;
    const __int128 det =
        static_cast<__int128>(bx - ax) * (cy - ay) - static_cast<__int128>(by - ay) * (cx - ax);
    const int expected = (det > 0) - (det < 0);
    const Orientation o =
        orient({ax * unit, ay * unit}, {bx * unit, by * unit}, {cx * unit, cy * unit});
    ASSERT_EQ(static_cast<int>(o), expected) << "case " << i;
  }
}

TEST(SegmentEntersOpenRect, TableOfCases) {
  const Rect r{0, 0, 1, 1};
  struct Case {
    Vec2 p, q;
    bool enters;
    const char* what;
  };
  const Case cases[] = {
      {{-1, 0.5}, {2, 0.5}, true, "crosses the middle"},
      {{-1, 0}, {2, 0}, false, "slides along the bottom edge"},
      {{-1, 1}, {2, 1}, false, "slides along the top edge"},
      {{0, 2}, {2, 0}, false, "touches the corner (1,1) only"},
      {{-1, -1}, {2, 2}, true, "runs through the diagonal"},
      {{0.5, 0.5}, {0.6, 0.6}, true, "lies inside"},
      {{1, 1}, {2, 3}, false, "starts at a corner and leaves"},
      {{1, 1}, {0.5, 2}, false, "starts at a corner, leaves upward"},
      {{1, 0.5}, {2, 0.5}, false, "starts on the right edge, leaves"},
      {{1, 0.5}, {0.9, 0.5}, true, "starts on the right edge, goes in"},
      {{-0.5, 1.5}, {0.5, 0.9999999}, true, "dips just inside"},
      {{2, 2}, {3, 3}, false, "far away"},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(segment_enters_open_rect(c.p, c.q, r), c.enters) << c.what;
    EXPECT_EQ(segment_enters_open_rect(c.q, c.p, r), c.enters) << c.what << " (reversed)";
  }
}

TEST(OccupiesQuadrant, CornerAndEdgePoints) {
  const Rect r{0, 0, 1, 1};
  EXPECT_TRUE(occupies_quadrant(r, {1, 1}, -1, -1));
  EXPECT_FALSE(occupies_quadrant(r, {1, 1}, 1, 1));
  EXPECT_FALSE(occupies_quadrant(r, {1, 1}, -1, 1));
  EXPECT_TRUE(occupies_quadrant(r, {1, 0.5}, -1, 1));  // on the right edge
  EXPECT_TRUE(occupies_quadrant(r, {1, 0.5}, -1, -1));
  EXPECT_FALSE(occupies_quadrant(r, {1, 0.5}, 1, 1));
}

TEST(WrapAngle, StaysInHalfOpenRange) {
  EXPECT_DOUBLE_EQ(wrap_angle(3 * M_PI), M_PI);
  EXPECT_DOUBLE_EQ(wrap_angle(-M_PI), M_PI);
  EXPECT_NEAR(wrap_angle(2 * M_PI + 0.1), 0.1, 1e-12);
}

}  // namespace
}  // namespace plantsim::geom

TEST(BoundedAtan2, WithinItsBoundOfLibmEverywhere) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI), scale(-6, 3);
  double worst = 0;
  auto check = [&](double y, double x) {
    double diff = std::fabs(plantsim::geom::bounded_atan2(y, x) - std::atan2(y, x));
    diff = std::min(diff, std::fabs(diff - 2 * M_PI));  // either end of the cut
    worst = std::max(worst, diff);
    ASSERT_LE(diff, plantsim::geom::kBoundedAtan2ErrorRad) << y << " " << x;
  };
  for (int k = 0; k < 200000; ++k) {
    const double a = angle(rng), r = std::pow(10.0, scale(rng));
    check(r * std::sin(a), r * std::cos(a));
  }
  // The axes, the diagonals, the reduction's seam at tan(pi/12) and the cut.
  for (double y : {0.0, -0.0, 1.0, -1.0, 0.26794919243112270, -1e-300})
    for (double x : {0.0, -0.0, 1.0, -1.0, 1e-300}) check(y, x);
  EXPECT_GT(worst, 0.0);  // an approximation, not libm itself
}

namespace plantsim::geom {
namespace {

// The part of a segment within a distance of a rectangle: one interval, against a dense sampling
// of the segment's points by their exact distance.
TEST(SegmentSpanWithin, MatchesSampledDistancesOnRandomSegments) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-20.0, 20.0);
  const Rect r{-3, -1, 4, 2};
  const double d = 5.0;
  int met = 0, missed = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Vec2 p{u(rng), u(rng)}, q{u(rng), u(rng)};
    const auto span = segment_span_within(p, q, r, d);
    constexpr int kSamples = 4000;
    double lo = 2, hi = -1;
    for (int k = 0; k <= kSamples; ++k) {
      const double t = static_cast<double>(k) / kSamples;
      if (distance_to_rect(p + t * (q - p), r) <= d) lo = std::min(lo, t), hi = std::max(hi, t);
    }
    if (lo > hi) {
      // No sample within d: the span, if any, is shorter than two samples.
      if (span) {
        EXPECT_LT(span->second - span->first, 2.0 / kSamples);
      }
      ++missed;
      continue;
    }
    ASSERT_TRUE(span.has_value());
    EXPECT_NEAR(span->first, lo, 1.0 / kSamples);
    EXPECT_NEAR(span->second, hi, 1.0 / kSamples);
    // Its ends are at distance d (or are the segment's own ends).
    for (const double t : {span->first, span->second})
      if (t > 0 && t < 1) {
        EXPECT_NEAR(distance_to_rect(p + t * (q - p), r), d, 1e-9);
      }
    ++met;
  }
  EXPECT_GT(met, 50);
  EXPECT_GT(missed, 20);
  // Along a side at 3 m, past the ends of the side: the corners' disks decide.
  const auto along = segment_span_within({-10, 2 + 3}, {10, 2 + 3}, r, d);
  ASSERT_TRUE(along.has_value());
  const double reach = std::sqrt(d * d - 3.0 * 3.0);  // 4 m past either end of the top side
  EXPECT_NEAR(along->first, (-3 - reach + 10) / 20.0, 1e-12);
  EXPECT_NEAR(along->second, (4 + reach + 10) / 20.0, 1e-12);
}

}  // namespace
}  // namespace plantsim::geom
