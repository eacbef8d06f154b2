// The convex mesh covers exactly the free floor of the rectangle mesh it is built from, with
// convex counter-clockwise polygons whose shared edges agree from both sides, no edge across a
// pinch or a zero-width slit, and corners exactly where a path may bend.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "planner/mesh/convex_mesh.h"
#include "planner/mesh/free_space_mesh.h"
#include "planner/mesh/interval_search.h"
#include "planner/mesh/polygon_search.h"

namespace plantsim::planner {
namespace {

double polygon_area(const ConvexMesh& m, std::int32_t p) {
  double twice = 0;
  for (std::int32_t k = 0; k < m.size(p); ++k) {
    const Vec2 a = m.points()[m.vertex(p, k)], b = m.points()[m.vertex(p, k + 1)];
    twice += a.x * b.y - a.y * b.x;
  }
  return twice / 2;
}

void expect_sound(const FreeSpaceMesh& rectangles, const ConvexMesh& m, const std::string& what) {
  double free_area = 0, area = 0;
  for (const MeshCell& c : rectangles.cells()) free_area += (c.xhi - c.xlo) * (c.yhi - c.ylo);
  for (std::int32_t p = 0; p < m.polygon_count(); ++p) {
    const double a = polygon_area(m, p);
    ASSERT_GT(a, 0) << what << ": polygon " << p << " is not counter-clockwise";
    area += a;
    for (std::int32_t k = 0; k < m.size(p); ++k) {
      const Vec2 u = m.points()[m.vertex(p, k - 1)], v = m.points()[m.vertex(p, k)],
                 w = m.points()[m.vertex(p, k + 1)];
      ASSERT_GE((v.x - u.x) * (w.y - v.y) - (v.y - u.y) * (w.x - v.x), -1e-12)
          << what << ": polygon " << p << " is not convex";
      const std::int32_t q = m.neighbour(p, k);
      if (q < 0) continue;
      const std::int32_t j = m.twin(p, k);
      ASSERT_GE(j, 0) << what;
      EXPECT_EQ(m.neighbour(q, j), p) << what;
      EXPECT_EQ(m.vertex(q, j), m.vertex(p, k + 1)) << what;
      EXPECT_EQ(m.vertex(q, j + 1), m.vertex(p, k)) << what;
    }
  }
  EXPECT_NEAR(area, free_area, 1e-9 * free_area) << what;
}

TEST(ConvexMesh, CoversTheFreeFloorWithConvexPolygonsThatAgreeAcrossEdges) {
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> at(0, 20), size(1, 5), count(1, 25);
  for (int world = 0; world < 300; ++world) {
    std::vector<Rect> blocked;
    for (int i = count(rng); i > 0; --i) {
      const double x = at(rng), y = at(rng);
      blocked.push_back({x, y, x + size(rng), y + size(rng)});
    }
    const FreeSpaceMesh rectangles(blocked, {0, 0, 20, 20});
    const ConvexMesh m(rectangles);
    expect_sound(rectangles, m, "world " + std::to_string(world));
  }
}

// Merging pays: a staircase wall leaves one open area that the rectangle mesh cuts at every step.
TEST(ConvexMesh, OnePolygonSpansTheOpenSideOfAStaircase) {
  std::vector<Rect> steps;
  for (int i = 0; i < 10; ++i) steps.push_back({double(i), 0, double(i + 1), double(i + 1)});
  const FreeSpaceMesh rectangles(steps, {0, 0, 10, 12});
  const ConvexMesh m(rectangles);
  expect_sound(rectangles, m, "staircase");
  EXPECT_GE(rectangles.cells().size(), 10u);
  // The triangle above the diagonal through the steps' corners is convex: one polygon holds
  // points near both ends of it.
  const auto low = m.polygons_at({1.2, 2.5}), high = m.polygons_at({8.8, 9.9});
  ASSERT_EQ(low.size(), 1u);
  ASSERT_EQ(high.size(), 1u);
  EXPECT_EQ(low.front(), high.front());
}

// Two squares touching at a corner (a pinch) and two blocks side by side (a slit of no width
// between them): no edge joins the two sides of either; the outer corners are corners a path
// bends at, the contact point and the slit's ends are not.
TEST(ConvexMesh, PinchesAndSlitsShareNoEdgeAndCornersAreWherePathsBend) {
  const FreeSpaceMesh rectangles({{2, 2, 4, 4}, {4, 4, 6, 6}, {2, 8, 4, 10}, {4, 8, 6, 10}},
                                 {0, 0, 8, 12});
  const ConvexMesh m(rectangles);
  expect_sound(rectangles, m, "pinch");
  const auto vertex_at = [&](Vec2 p) {
    for (std::size_t v = 0; v < m.points().size(); ++v)
      if (m.points()[v] == p) return static_cast<std::int32_t>(v);
    return std::int32_t{-1};
  };
  const std::int32_t contact = vertex_at({4, 4});
  ASSERT_GE(contact, 0);
  EXPECT_FALSE(m.is_corner(contact));
  for (const Vec2 c : {Vec2{2, 2}, Vec2{6, 6}, Vec2{2, 4}, Vec2{6, 4}, Vec2{2, 8}, Vec2{6, 10}})
    EXPECT_TRUE(m.is_corner(vertex_at(c))) << c.x << " " << c.y;
  for (const Vec2 c : {Vec2{4, 8}, Vec2{4, 10}}) {
    const std::int32_t v = vertex_at(c);
    if (v >= 0) {
      EXPECT_FALSE(m.is_corner(v)) << c.x << " " << c.y;
    }
  }
  // The polygons on the two open sides of the contact point share no edge.
  const auto upper_left = m.polygons_at({3.9, 4.1}), lower_right = m.polygons_at({4.1, 3.9});
  ASSERT_EQ(upper_left.size(), 1u);
  ASSERT_EQ(lower_right.size(), 1u);
  for (std::int32_t k = 0; k < m.size(upper_left.front()); ++k)
    EXPECT_NE(m.neighbour(upper_left.front(), k), lower_right.front());
  // Nothing passes through the slit: no polygon has an edge inside it, and below it and above
  // it are different polygons.
  for (std::int32_t p = 0; p < m.polygon_count(); ++p)
    for (std::int32_t k = 0; k < m.size(p); ++k) {
      const Vec2 a = m.points()[m.vertex(p, k)], b = m.points()[m.vertex(p, k + 1)];
      EXPECT_FALSE(a.x == 4 && b.x == 4 && std::max(a.y, b.y) > 8 && std::min(a.y, b.y) < 10)
          << "an edge in the slit";
    }
  const auto below = m.polygons_at({4, 7.9}), above = m.polygons_at({4, 10.1});
  ASSERT_FALSE(below.empty());
  ASSERT_FALSE(above.empty());
  for (const std::int32_t p : below)
    for (const std::int32_t q : above) EXPECT_NE(p, q);
}

// Rows of small boxes along a corridor (brackets along a tunnel wall): the corridor between the
// rows is convex, thousands of collinear corners long. Merged whole, it made building the mesh
// quadratic; polygons stay within kMaxCorners, and paths through the gaps keep their lengths.
TEST(ConvexMesh, ACombOfBoxesMakesNoGiantPolygon) {
  std::vector<Rect> brackets;
  const int per_row = 400;
  for (int i = 0; i < per_row; ++i) {
    const double x = 2 + 2 * i;
    brackets.push_back({x, 1, x + 1, 2});
    brackets.push_back({x, 10, x + 1, 11});
  }
  const double length = 2 * per_row + 4;
  const FreeSpaceMesh rectangles(brackets, {0, 0, length, 12});
  const ConvexMesh m(rectangles);
  expect_sound(rectangles, m, "comb");
  std::int32_t largest = 0;
  for (std::int32_t p = 0; p < m.polygon_count(); ++p) largest = std::max(largest, m.size(p));
  // Whole, the corridor would be one polygon of some 1,600 corners.
  EXPECT_LE(largest, ConvexMesh::kMaxCorners);
  EXPECT_LE(largest, 64);
  EXPECT_GT(largest, 8) << "the corridor should still be cut into large polygons";

  PolygonSearch polygons(m);
  IntervalSearch cells(rectangles);
  for (const auto& [from, to] :
       {std::pair{Vec2{1, 0.5}, Vec2{40.5, 11.5}}, std::pair{Vec2{30.5, 0.5}, Vec2{length - 1, 6}},
        std::pair{Vec2{1.5, 6}, Vec2{length - 1.5, 11.5}},
        std::pair{Vec2{99.5, 1.5}, Vec2{7.5, 10.5}}}) {
    const IntervalPath a = polygons.find(from, to), b = cells.find(from, to);
    ASSERT_TRUE(a.found) << from.x << " " << from.y << " -> " << to.x << " " << to.y;
    ASSERT_TRUE(b.found);
    const auto length_of = [](const IntervalPath& r) {
      double sum = 0;
      for (std::size_t i = 1; i < r.path.size(); ++i)
        sum += std::hypot(r.path[i].x - r.path[i - 1].x, r.path[i].y - r.path[i - 1].y);
      return sum;
    };
    EXPECT_NEAR(length_of(a), length_of(b), 1e-9 * length_of(b))
        << from.x << " " << from.y << " -> " << to.x << " " << to.y;
  }
}

}  // namespace
}  // namespace plantsim::planner
