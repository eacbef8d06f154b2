// Ray casting through a fixed set of boxes (axis-aligned rectangles and oriented boxes), exactly
// in double precision, through a uniform grid built once: each cell lists the boxes that overlap
// it, a ray walks the cells it crosses in order (Amanatides and Woo's traversal) and stops at the
// first cell whose far side lies beyond the nearest hit found. A ray starting inside a box does
// not hit it (as Box2D's polygon ray casts). The plant's static parts cost a handful of box tests
// per beam, whatever their number, where a Box2D cast walks its tree for each.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "geometry/vec2.h"

namespace plantsim::geom {

/// A box of half extents (hx, hy) about `center`, turned by `yaw`.
struct OrientedBox {
  Vec2 center;
  double hx = 0, hy = 0, yaw = 0;
};

struct RayGridHit {
  double range_m;  ///< along the unit direction from the origin
  Vec2 normal;     ///< unit, out of the face hit
  int box;         ///< index in the order the boxes were given (rectangles first, then oriented)
};

/// Where the ray from `origin` along unit `direction` enters `r`: true with the distance and the
/// outward normal of the face it enters by; false when it misses or starts inside (or on a face,
/// leaving). Inline, with plain out-parameters: an optional returned through memory stalled
/// every fan on store forwarding.
inline bool ray_enters_rect(const Rect& r, Vec2 o, Vec2 d, double& t, Vec2& normal) {
  double t_in = -std::numeric_limits<double>::infinity(),
         t_out = std::numeric_limits<double>::infinity();
  double nx = 0, ny = 0;
  const double lo[2] = {r.xmin, r.ymin}, hi[2] = {r.xmax, r.ymax}, org[2] = {o.x, o.y},
               dir[2] = {d.x, d.y};
  for (int a = 0; a < 2; ++a) {
    if (dir[a] == 0) {
      if (org[a] < lo[a] || org[a] > hi[a]) return false;
      continue;
    }
    double t0 = (lo[a] - org[a]) / dir[a], t1 = (hi[a] - org[a]) / dir[a];
    double side = -1;  // entering through the low face when moving up the axis
    if (t0 > t1) std::swap(t0, t1), side = 1;
    if (t0 > t_in) {
      t_in = t0;
      nx = a == 0 ? side : 0;
      ny = a == 0 ? 0 : side;
    }
    t_out = std::min(t_out, t1);
  }
  // Starting inside (or on the face, leaving): no entry, as Box2D's polygons.
  if (!(t_in > 0) || t_in > t_out) return false;
  t = t_in;
  normal = {nx, ny};
  return true;
}

/// The same, as one value.
inline std::optional<std::pair<double, Vec2>> ray_enters_rect(const Rect& r, Vec2 o, Vec2 d) {
  double t;
  Vec2 normal;
  if (!ray_enters_rect(r, o, d, t, normal)) return std::nullopt;
  return std::pair{t, normal};
}

/// A fan's answers as parallel arrays, one entry per ray: box -1 where the ray meets nothing
/// within its range (range_m then holds no distance). Arrays, not optionals: the fan tests a
/// box's rays in a tight loop that reads and writes a ray's range alone.
struct FanHits {
  std::vector<double> range_m;  ///< along the ray's unit direction from the origin
  std::vector<Vec2> normal;     ///< unit, out of the face hit
  std::vector<int> box;         ///< as RayGridHit::box, or -1
  bool hit(std::size_t k) const { return box[k] >= 0; }
  std::size_t size() const { return box.size(); }
};

class RayGrid {
 public:
  /// `cell_m` 0: chosen from the boxes' number and extent (a few per cell; at most max_cells).
  RayGrid(std::vector<Rect> rects, std::vector<OrientedBox> oriented, double cell_m = 0,
          long max_cells = 4'000'000);

  /// The nearest box face the ray from `origin` along unit `direction` meets within `max_range_m`.
  std::optional<RayGridHit> cast(Vec2 origin, Vec2 direction, double max_range_m) const;
  /// A fan of rays from one origin: ray k along unit `directions[k]`, whose angle lies within
  /// 1e-6 rad of `first_angle + k * increment`. hits[k] is what cast() finds for it (the same
  /// range; where two faces tie exactly either may be named). One pass over the boxes within
  /// reach, nearest cells first, each tried only on the rays its angular extent covers; the few
  /// rays still open once most boxes are settled walk on alone from what the fan found, past
  /// the boxes it tried: a lidar scan without a walk per beam.
  void cast_fan(Vec2 origin, std::span<const Vec2> directions, double first_angle, double increment,
                double max_range_m, FanHits& hits) const;
  /// True when some box comes within `margin_m` per axis of `p` (its bounding box, for oriented
  /// ones).
  bool near(Vec2 p, double margin_m) const;

  std::size_t box_count() const { return bounds_.size(); }
  /// Each box's axis-aligned bounds, in the order given; and the extent of them all.
  const std::vector<Rect>& bounds() const { return bounds_; }
  const Rect& area() const { return area_; }
  double cell_m() const { return cell_; }

 private:
  /// The ray's entry into box i: true with the distance and normal; false if it misses or starts
  /// inside.
  bool enter(int i, Vec2 origin, Vec2 direction, double& t, Vec2& normal) const;

  /// The best hit of one ray so far: box -1 for none, with `range_m` then just beyond the ray's
  /// reach, so that one comparison (t < range_m) asks both "within reach" and "nearer".
  struct Best {
    double& range_m;
    Vec2& normal;
    int& box;
  };
  /// The cells the ray crosses, near to far, each box in them tested once (stamped `query`)
  /// unless stamped `done_query` (nonzero: tested before on this ray's direction), until no
  /// later cell can hold a hit nearer than `best`, which it updates. Cells the ray crosses
  /// before `t_from` are passed over (their boxes all tried).
  void walk(Vec2 origin, Vec2 direction, double max_range_m, std::uint32_t query,
            std::uint32_t done_query, Best best, double t_from = 0) const;
  /// The cells [i0, i1] x [j0, j1] that `q` overlaps, clamped to the grid.
  void cells_of(const Rect& q, long& i0, long& i1, long& j0, long& j1) const;
  /// A fresh stamp for a query that must visit each box once.
  std::uint32_t next_query() const;
  /// cast_fan's steps: one box tried on the rays it can cover, one cell's boxes, and before a
  /// ring, whether every ray is settled (casting the few still open singly).
  struct Fan;
  void fan_try_box(Fan& fan, int box) const;
  void fan_visit_cell(Fan& fan, long i, long j) const;
  bool fan_settled_before_ring(Fan& fan, long k) const;
  /// The corners that bound box i's silhouette seen from `origin`: `first` the clockwise-most,
  /// `last` the counter-clockwise-most (less than half a turn apart); false when the origin lies
  /// in the box or so near it that the extent is ill-conditioned.
  bool silhouette(int i, Vec2 origin, Vec2& first, Vec2& last) const;

  std::vector<Rect> rects_;
  std::vector<OrientedBox> oriented_;
  std::vector<Rect> bounds_;  // each box's axis-aligned bounds
  Rect area_;                 // the grid's extent
  double cell_ = 1;
  long nx_ = 1, ny_ = 1;
  std::vector<std::uint32_t> first_;  // cell c's boxes: members_[first_[c] .. first_[c + 1])
  std::vector<int> members_;
  mutable std::vector<std::uint32_t> stamp_;  // per box: the query that last tested it
  mutable std::uint32_t query_ = 0;
  mutable std::vector<long> open_rays_;  // cast_fan's scratch
};

}  // namespace plantsim::geom
