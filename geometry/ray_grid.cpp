// The grid of box lists, the cell walk and the box entry tests.
#include "geometry/ray_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/bounded_atan2.h"

namespace plantsim::geom {
namespace {

// clamp(floor(x), lo, hi) and clamp(ceil(x), lo, hi), with no call into libm (floor and ceil are
// not inlined without SSE4.1): a fan takes four per box.
inline long floor_within(double x, long lo, long hi) {
  if (!(x > static_cast<double>(lo))) return lo;
  if (!(x < static_cast<double>(hi))) return hi;
  const long i = static_cast<long>(x);  // towards zero
  return static_cast<double>(i) > x ? i - 1 : i;
}
inline long ceil_within(double x, long lo, long hi) {
  if (!(x > static_cast<double>(lo))) return lo;
  if (!(x < static_cast<double>(hi))) return hi;
  const long i = static_cast<long>(x);
  return static_cast<double>(i) < x ? i + 1 : i;
}

Rect bounds_of(const OrientedBox& b) {
  const double c = std::fabs(std::cos(b.yaw)), s = std::fabs(std::sin(b.yaw));
  const double ex = c * b.hx + s * b.hy, ey = s * b.hx + c * b.hy;
  return {b.center.x - ex, b.center.y - ey, b.center.x + ex, b.center.y + ey};
}

}  // namespace

RayGrid::RayGrid(std::vector<Rect> rects, std::vector<OrientedBox> oriented, double cell_m,
                 long max_cells)
    : rects_(std::move(rects)), oriented_(std::move(oriented)) {
  for (const Rect& r : rects_) bounds_.push_back(r);
  for (const OrientedBox& b : oriented_) bounds_.push_back(bounds_of(b));
  area_ = bounds_.empty() ? Rect{0, 0, 1, 1} : bounds_.front();
  for (const Rect& b : bounds_)
    area_ = {std::min(area_.xmin, b.xmin), std::min(area_.ymin, b.ymin),
             std::max(area_.xmax, b.xmax), std::max(area_.ymax, b.ymax)};
  const double w = std::max(area_.width(), 1e-6), h = std::max(area_.height(), 1e-6);
  // About two boxes' worth of area per cell, never so fine that the grid passes max_cells.
  cell_ = cell_m > 0
              ? cell_m
              : std::max(0.5, std::sqrt(2.0 * w * h / std::max<std::size_t>(bounds_.size(), 1)));
  cell_ = std::max(cell_, std::sqrt(w * h / static_cast<double>(std::max(1L, max_cells))));
  nx_ = std::max(1L, static_cast<long>(std::ceil(w / cell_)));
  ny_ = std::max(1L, static_cast<long>(std::ceil(h / cell_)));
  // Counting sort of (cell, box) pairs into one array.
  std::vector<std::uint32_t> count(static_cast<std::size_t>(nx_ * ny_) + 1, 0);
  auto span = [&](const Rect& b, auto&& visit) {
    const long i0 = floor_within((b.xmin - area_.xmin) / cell_, 0L, nx_ - 1);
    const long i1 = floor_within((b.xmax - area_.xmin) / cell_, 0L, nx_ - 1);
    const long j0 = floor_within((b.ymin - area_.ymin) / cell_, 0L, ny_ - 1);
    const long j1 = floor_within((b.ymax - area_.ymin) / cell_, 0L, ny_ - 1);
    for (long j = j0; j <= j1; ++j)
      for (long i = i0; i <= i1; ++i) visit(static_cast<std::size_t>(j * nx_ + i));
  };
  for (const Rect& b : bounds_) span(b, [&](std::size_t c) { ++count[c + 1]; });
  for (std::size_t c = 1; c < count.size(); ++c) count[c] += count[c - 1];
  first_ = count;
  members_.resize(first_.back());
  for (std::size_t k = 0; k < bounds_.size(); ++k)
    span(bounds_[k], [&](std::size_t c) { members_[count[c]++] = static_cast<int>(k); });
  stamp_.assign(bounds_.size(), 0);
}

inline bool RayGrid::enter(int i, Vec2 origin, Vec2 direction, double& t, Vec2& normal) const {
  const std::size_t k = static_cast<std::size_t>(i);
  if (k < rects_.size()) return ray_enters_rect(rects_[k], origin, direction, t, normal);
  // An oriented box: the ray in the box's own frame, then the normal turned back.
  const OrientedBox& b = oriented_[k - rects_.size()];
  const Vec2 o = rotate(origin - b.center, -b.yaw), d = rotate(direction, -b.yaw);
  Vec2 n;
  if (!ray_enters_rect({-b.hx, -b.hy, b.hx, b.hy}, o, d, t, n)) return false;
  normal = rotate(n, b.yaw);
  return true;
}

std::uint32_t RayGrid::next_query() const {
  if (++query_ == 0) {  // the stamps wrapped: start them afresh
    std::fill(stamp_.begin(), stamp_.end(), 0);
    query_ = 1;
  }
  return query_;
}

void RayGrid::cells_of(const Rect& q, long& i0, long& i1, long& j0, long& j1) const {
  i0 = floor_within((q.xmin - area_.xmin) / cell_, 0L, nx_ - 1);
  i1 = floor_within((q.xmax - area_.xmin) / cell_, 0L, nx_ - 1);
  j0 = floor_within((q.ymin - area_.ymin) / cell_, 0L, ny_ - 1);
  j1 = floor_within((q.ymax - area_.ymin) / cell_, 0L, ny_ - 1);
}

namespace {
// Whether a ray's line passes clear of a box: the signed distances of the box's corners from the
// line (cross products, no division) all of one sign by more than their rounding. Most boxes a
// walk meets lie beside the ray; ray_enters_rect would tell so at four divisions, and says the
// same whenever this does (its own rounding matters only within far less of a corner).
class LineClearance {
 public:
  LineClearance(Vec2 o, Vec2 d, const Rect& area) : o_(o), d_(d) {
    const double scale =
        std::max({std::fabs(o.x), std::fabs(o.y), std::fabs(area.xmin), std::fabs(area.xmax),
                  std::fabs(area.ymin), std::fabs(area.ymax)});
    margin_ = 1e-12 * (1.0 + scale);  // the rounding is about 1e-16 of the coordinates
  }
  bool operator()(const Rect& b) const {
    // cross(d, c - o) = d.x (c.y - o.y) - d.y (c.x - o.x), each term at its extreme corner.
    const double y_lo = d_.x * ((d_.x >= 0 ? b.ymin : b.ymax) - o_.y);
    const double y_hi = d_.x * ((d_.x >= 0 ? b.ymax : b.ymin) - o_.y);
    const double x_lo = -d_.y * ((d_.y >= 0 ? b.xmax : b.xmin) - o_.x);
    const double x_hi = -d_.y * ((d_.y >= 0 ? b.xmin : b.xmax) - o_.x);
    return y_lo + x_lo > margin_ || y_hi + x_hi < -margin_;
  }

 private:
  Vec2 o_, d_;
  double margin_ = 0;
};

// Just beyond a ray's reach: a hit at t counts when t < this (t <= max_range_m).
double beyond_reach(double max_range_m) {
  return std::nextafter(max_range_m, std::numeric_limits<double>::infinity());
}
}  // namespace

std::optional<RayGridHit> RayGrid::cast(Vec2 origin, Vec2 direction, double max_range_m) const {
  if (bounds_.empty() || !(max_range_m > 0)) return std::nullopt;
  double range = beyond_reach(max_range_m);
  Vec2 normal;
  int box = -1;
  walk(origin, direction, max_range_m, next_query(), 0, {range, normal, box});
  if (box < 0) return std::nullopt;
  return RayGridHit{range, normal, box};
}

void RayGrid::walk(Vec2 origin, Vec2 direction, double max_range_m, std::uint32_t query,
                   std::uint32_t done_query, Best best, double t_from) const {
  // Clip the ray to the grid's extent; a ray that misses it hits nothing.
  double t = t_from, t_end = max_range_m;
  {
    const double lo[2] = {area_.xmin, area_.ymin}, hi[2] = {area_.xmax, area_.ymax};
    const double org[2] = {origin.x, origin.y}, dir[2] = {direction.x, direction.y};
    for (int a = 0; a < 2; ++a) {
      if (dir[a] == 0) {
        if (org[a] < lo[a] || org[a] > hi[a]) return;
        continue;
      }
      double t0 = (lo[a] - org[a]) / dir[a], t1 = (hi[a] - org[a]) / dir[a];
      if (t0 > t1) std::swap(t0, t1);
      t = std::max(t, t0);
      t_end = std::min(t_end, t1);
    }
    if (t > t_end) return;
  }
  const Vec2 start = origin + t * direction;
  long i = floor_within((start.x - area_.xmin) / cell_, 0L, nx_ - 1);
  long j = floor_within((start.y - area_.ymin) / cell_, 0L, ny_ - 1);
  const long step_i = direction.x > 0 ? 1 : -1, step_j = direction.y > 0 ? 1 : -1;
  const double inf = std::numeric_limits<double>::infinity();
  // Distance along the ray to the next vertical and horizontal cell boundary, and between them.
  auto boundary = [&](long cell, double lo, double o, double d, long step) {
    if (d == 0) return inf;
    const double edge = lo + (cell + (step > 0 ? 1 : 0)) * cell_;
    return (edge - o) / d;
  };
  double next_x = boundary(i, area_.xmin, origin.x, direction.x, step_i);
  double next_y = boundary(j, area_.ymin, origin.y, direction.y, step_j);
  const double delta_x = direction.x != 0 ? cell_ / std::fabs(direction.x) : inf;
  const double delta_y = direction.y != 0 ? cell_ / std::fabs(direction.y) : inf;
  const LineClearance clear_of(origin, direction, area_);
  while (true) {
    const std::size_t c = static_cast<std::size_t>(j * nx_ + i);
    for (std::uint32_t m = first_[c]; m < first_[c + 1]; ++m) {
      const int k = members_[m];
      std::uint32_t& stamp = stamp_[static_cast<std::size_t>(k)];
      // Tested in an earlier cell, or by the fan this walk finishes.
      if (stamp == query || (done_query != 0 && stamp == done_query)) continue;
      stamp = query;
      if (clear_of(bounds_[static_cast<std::size_t>(k)])) continue;
      double t;
      Vec2 normal;
      if (enter(k, origin, direction, t, normal) && t < best.range_m)
        best.range_m = t, best.normal = normal, best.box = k;
    }
    const double cell_exit = std::min(next_x, next_y);
    // A hit within this cell is nearer than anything a later cell can hold.
    if ((best.box >= 0 && best.range_m <= cell_exit) || cell_exit > t_end) break;
    if (next_x < next_y) {
      i += step_i;
      next_x += delta_x;
      if (i < 0 || i >= nx_) break;
    } else {
      j += step_j;
      next_y += delta_y;
      if (j < 0 || j >= ny_) break;
    }
  }
}

bool RayGrid::silhouette(int i, Vec2 origin, Vec2& first, Vec2& last) const {
  // Corners as enter() sees the box; an origin within 1e-6 m of it is left to every ray (the
  // corners' angles would carry rounding far beyond the fan's tolerance).
  constexpr double kClearance = 1e-6;
  const std::size_t k = static_cast<std::size_t>(i);
  if (k < rects_.size()) {
    const Rect& r = rects_[k];
    if (r.xmin - kClearance <= origin.x && origin.x <= r.xmax + kClearance &&
        r.ymin - kClearance <= origin.y && origin.y <= r.ymax + kClearance)
      return false;
    const Vec2 corners[4] = {
        {r.xmin, r.ymin}, {r.xmax, r.ymin}, {r.xmax, r.ymax}, {r.xmin, r.ymax}};
    // Outside a rectangle, the side of it the origin lies on names the two corners that bound
    // its silhouette: [below, level, above][left, level, right], the clockwise-most corner then
    // the counter-clockwise-most (the search below finds the same two, at four times the cost).
    static constexpr int kSilhouette[3][3][2] = {
        {{1, 3}, {1, 0}, {2, 0}}, {{0, 3}, {0, 0}, {2, 1}}, {{0, 2}, {3, 2}, {3, 1}}};
    const int sx = origin.x < r.xmin ? 0 : origin.x > r.xmax ? 2 : 1;
    const int sy = origin.y < r.ymin ? 0 : origin.y > r.ymax ? 2 : 1;
    first = corners[kSilhouette[sy][sx][0]];
    last = corners[kSilhouette[sy][sx][1]];
    return true;
  }
  const OrientedBox& b = oriented_[k - rects_.size()];
  const Vec2 o = rotate(origin - b.center, -b.yaw);
  if (std::fabs(o.x) <= b.hx + kClearance && std::fabs(o.y) <= b.hy + kClearance) return false;
  const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
  Vec2 corners[4];
  for (int c = 0; c < 4; ++c) corners[c] = b.center + rotate({sx[c] * b.hx, sy[c] * b.hy}, b.yaw);
  // Seen from outside, a convex box's extent runs from the corner every other lies
  // counter-clockwise of to the one every other lies clockwise of, less than half a turn.
  const Vec2* cw_most = nullptr;
  const Vec2* ccw_most = nullptr;
  for (const Vec2& c : corners) {
    bool all_ccw = true, all_cw = true;
    for (const Vec2& other : corners) {
      const double turn = cross(c - origin, other - origin);
      all_ccw &= turn >= 0, all_cw &= turn <= 0;
    }
    if (all_ccw && !cw_most) cw_most = &c;
    if (all_cw && !ccw_most) ccw_most = &c;
  }
  if (!cw_most || !ccw_most) return false;
  first = *cw_most;
  last = *ccw_most;
  return true;
}

namespace {

// The faces of a rectangle that an origin outside it sees (one, or two meeting at a corner).
// A ray that certainly enters the rectangle enters through one of them: its distance and normal
// are ray_enters_rect's, bit for bit (the same divisions, the same tie to the x face), at half
// the divisions.
struct SeenFaces {
  int side_x, side_y;  // -1 below the low face, 1 beyond the high one, 0 between them
  double face_x, face_y;
  SeenFaces(const Rect& r, Vec2 o)
      : side_x(o.x < r.xmin   ? -1
               : o.x > r.xmax ? 1
                              : 0),
        side_y(o.y < r.ymin   ? -1
               : o.y > r.ymax ? 1
                              : 0),
        face_x(side_x < 0 ? r.xmin : r.xmax),
        face_y(side_y < 0 ? r.ymin : r.ymax) {}
  void enter(Vec2 o, Vec2 d, double& t, Vec2& normal) const {
    if (side_x == 0) {
      t = (face_y - o.y) / d.y, normal = {0, static_cast<double>(side_y)};
      return;
    }
    t = (face_x - o.x) / d.x, normal = {static_cast<double>(side_x), 0};
    if (side_y == 0) return;
    const double t_y = (face_y - o.y) / d.y;
    if (t_y > t) t = t_y, normal = {0, static_cast<double>(side_y)};
  }
};

}  // namespace

// One fan in flight: its rays, the hits found so far and the cell entries not yet visited.
struct RayGrid::Fan {
  Vec2 origin;
  std::span<const Vec2> directions;
  double first_angle, increment, max_range_m;
  double* range;  // the hits' arrays (FanHits), each ray's best so far
  Vec2* normal;
  int* box;
  long ci, cj;  // the origin's cell, the rings' centre
  long n;
  bool spread;  // rays spaced evenly by angle: a box is tried only on those its extent covers
  double last;  // the last ray's angle from the first
  std::uint32_t query;
  long unvisited = 0;        // cell entries (a box counts once per cell it spans) not yet visited
  bool open_listed = false;  // open_rays_ holds this fan's rays still open at the last ring
  // The wedge no ray comes near (behind a lidar), from its clockwise edge to its
  // counter-clockwise one, when it spans at most half a turn; a box within it meets no ray.
  bool blind = false;
  Vec2 blind_from{}, blind_to{};
};

namespace {
// A ray's own angle lies within 1e-6 rad of its place in the fan; an extent's corners within
// kBoundedAtan2ErrorRad of theirs.
constexpr double kFanAngleTolerance = 1e-6 + kBoundedAtan2ErrorRad;
// A ray cast singly walks a few cells of a few boxes each; the rings' remaining boxes each cost an
// angular extent. Past this many boxes left per open ray, the open rays are cast singly.
constexpr long kBoxesPerOpenRay = 2;
// Beyond the rays' tolerance, for the rounding of a cross product (about 1e-16 of its inputs).
constexpr double kBlindMarginRad = 1e-9;
}  // namespace

void RayGrid::fan_try_box(Fan& fan, int box) const {
  const Rect& b = bounds_[static_cast<std::size_t>(box)];
  const Vec2 o = fan.origin;
  const double gap_x = std::max({b.xmin - o.x, o.x - b.xmax, 0.0});
  const double gap_y = std::max({b.ymin - o.y, o.y - b.ymax, 0.0});
  // Lowered by far more than sqrt's rounding: a box is passed over only when it certainly lies
  // beyond a ray's hit (hypot, exact to the last bit, cost a tenth of the fan).
  const double nearest = std::sqrt(gap_x * gap_x + gap_y * gap_y) * (1.0 - 1e-12);
  if (nearest > fan.max_range_m) return;
  Vec2 first_corner, last_corner;
  const bool bounded = fan.spread && silhouette(box, o, first_corner, last_corner);
  // Both silhouette corners in the blind wedge (convex, at most half a turn): the extent between
  // them, less than half a turn, lies in it too.
  if (bounded && fan.blind && cross(fan.blind_from, first_corner - o) > 0 &&
      cross(first_corner - o, fan.blind_to) > 0 && cross(fan.blind_from, last_corner - o) > 0 &&
      cross(last_corner - o, fan.blind_to) > 0)
    return;
  const bool is_rect = static_cast<std::size_t>(box) < rects_.size();
  const SeenFaces seen(is_rect ? rects_[static_cast<std::size_t>(box)] : b, o);
  // A box no nearer than a ray's hit cannot change it (a ray with none holds a range beyond its
  // reach, so that one test asks both). An inner ray certainly enters the box.
  double* const range = fan.range;
  const Vec2* const directions = fan.directions.data();
  auto try_ray = [&](long r, bool inner) {
    const double best = range[r];
    if (best <= nearest) return;
    const Vec2 d = directions[r];
    double t;
    Vec2 normal;
    if (inner)
      seen.enter(o, d, t, normal);
    else if (!enter(box, o, d, t, normal))
      return;
    if (!(t < best)) return;
    range[r] = t;
    fan.normal[r] = normal;
    fan.box[r] = box;
  };
  if (!bounded) {
    for (long r = 0; r < fan.n; ++r) try_ray(r, false);
    return;
  }
  // The fan widens its tolerance by the bound.
  const double extent_lo = bounded_atan2(first_corner.y - o.y, first_corner.x - o.x);
  double extent_hi = bounded_atan2(last_corner.y - o.y, last_corner.x - o.x);
  if (extent_hi < extent_lo) extent_hi += 2 * M_PI;
  // The extent relative to the first ray, its start brought into [0, 2 pi); then the rays it
  // covers at each whole turn that can hold some. Inner rays (of a rectangle) lie inside it by
  // more than a ray's own angular tolerance and the extent's rounding together.
  const double turn = 2 * M_PI;
  double lo = extent_lo - fan.first_angle - kFanAngleTolerance,
         hi = extent_hi - fan.first_angle + kFanAngleTolerance;
  constexpr long kManyTurns = 1L << 40;  // far beyond any angle's whole turns
  const double turns = static_cast<double>(floor_within(lo / turn, -kManyTurns, kManyTurns)) * turn;
  lo -= turns, hi -= turns;
  const double inner = 3 * kFanAngleTolerance;
  for (double shift = -turn; lo + shift <= fan.last + kFanAngleTolerance; shift += turn) {
    if (hi + shift < 0) continue;  // short of the first ray: no ray at this turn
    const long r0 = ceil_within((lo + shift) / fan.increment, 0, fan.n);
    const long r1 = floor_within((hi + shift) / fan.increment, -1, fan.n - 1);
    long inner0 = r1 + 1, inner1 = r1;
    if (is_rect && hi - lo > 2 * inner) {
      inner0 = std::max(r0, ceil_within((lo + shift + inner) / fan.increment, 0, fan.n));
      inner1 = std::min(r1, floor_within((hi + shift - inner) / fan.increment, -1, fan.n - 1));
      inner1 = std::max(inner1, inner0 - 1);
    }
    for (long r = r0; r < inner0; ++r) try_ray(r, false);
    for (long r = inner0; r <= inner1; ++r) try_ray(r, true);
    for (long r = std::max(r0, inner1 + 1); r <= r1; ++r) try_ray(r, false);
  }
}

void RayGrid::fan_visit_cell(Fan& fan, long i, long j) const {
  const std::size_t c = static_cast<std::size_t>(j * nx_ + i);
  fan.unvisited -= first_[c + 1] - first_[c];
  for (std::uint32_t m = first_[c]; m < first_[c + 1]; ++m) {
    const int box = members_[m];
    if (stamp_[static_cast<std::size_t>(box)] == fan.query) continue;
    stamp_[static_cast<std::size_t>(box)] = fan.query;
    fan_try_box(fan, box);
  }
}

// Every cell of ring k lies at least (k - 1) cells from the origin: a ray with a hit that near is
// settled. When few rays remain open (they pass through gaps into the distance), each walks its
// own cells (cast()) rather than the rings visiting every box out to the range. True when every
// ray is settled.
bool RayGrid::fan_settled_before_ring(Fan& fan, long k) const {
  if (k < 2) return false;
  const double ring_near = static_cast<double>(k - 1) * cell_;
  // Hits only come nearer and rings only further: a ray settled before one ring stays settled,
  // so each ring sifts the rays the last one left open.
  // Kept without a branch: whether a ray is settled is as good as a coin toss to the CPU.
  std::vector<long>& open = open_rays_;
  auto still_open = [&](long r) {
    return static_cast<std::size_t>(!((fan.box[r] >= 0) & (fan.range[r] <= ring_near)));
  };
  std::size_t kept = 0;
  if (!fan.open_listed) {
    open.resize(static_cast<std::size_t>(fan.n));
    for (long r = 0; r < fan.n; ++r) open[kept] = r, kept += still_open(r);
    fan.open_listed = true;
  } else {
    for (const long r : open) open[kept] = r, kept += still_open(r);
  }
  open.resize(kept);
  if (open.empty()) return true;
  if (static_cast<long>(open.size()) * kBoxesPerOpenRay >= fan.unvisited) return false;
  // Each open ray walks on from what the fan found, past the boxes the fan has tried (on every
  // ray their extent covers; a box outside a ray's extent cannot meet it): from where it leaves
  // the square of cells the rings have visited, since every box in them has been tried. An
  // origin outside the grid is no exception (the rings then centre on the grid's edge cell):
  // before the ray leaves the square through its far side, wherever it is not in the square it
  // is outside the grid.
  const Vec2 o = fan.origin;
  const double visited_lo[2] = {area_.xmin + static_cast<double>(fan.ci - k + 1) * cell_,
                                area_.ymin + static_cast<double>(fan.cj - k + 1) * cell_};
  const double visited_hi[2] = {area_.xmin + static_cast<double>(fan.ci + k) * cell_,
                                area_.ymin + static_cast<double>(fan.cj + k) * cell_};
  for (long r : open) {
    const std::uint32_t query = next_query();
    if (query <= fan.query) fan.query = 0;  // the stamps wrapped: the fan's marks are gone
    const Vec2 d = fan.directions[static_cast<std::size_t>(r)];
    double leaves = std::numeric_limits<double>::infinity();
    if (d.x != 0) leaves = ((d.x > 0 ? visited_hi[0] : visited_lo[0]) - o.x) / d.x;
    if (d.y != 0)
      leaves = std::min(leaves, ((d.y > 0 ? visited_hi[1] : visited_lo[1]) - o.y) / d.y);
    walk(o, d, fan.max_range_m, query, fan.query, {fan.range[r], fan.normal[r], fan.box[r]},
         std::max(0.0, leaves));
  }
  return true;
}

void RayGrid::cast_fan(Vec2 origin, std::span<const Vec2> directions, double first_angle,
                       double increment, double max_range_m, FanHits& hits) const {
  const long n = static_cast<long>(directions.size());
  hits.range_m.assign(directions.size(), beyond_reach(max_range_m));
  hits.normal.resize(directions.size());
  hits.box.assign(directions.size(), -1);
  if (bounds_.empty() || !(max_range_m > 0) || n == 0) return;
  // Each box within reach, once, against the rays whose angles its extent covers; cells in rings
  // about the origin's, near to far, so that a ray's hit is usually known before the boxes
  // behind it come up.
  const Rect reach{origin.x - max_range_m, origin.y - max_range_m, origin.x + max_range_m,
                   origin.y + max_range_m};
  if (reach.xmax < area_.xmin || reach.xmin > area_.xmax || reach.ymax < area_.ymin ||
      reach.ymin > area_.ymax)
    return;
  long i0, i1, j0, j1;
  cells_of(reach, i0, i1, j0, j1);
  long ci, cj, unused_i, unused_j;
  cells_of({origin.x, origin.y, origin.x, origin.y}, ci, unused_i, cj, unused_j);
  const bool spread =
      n > 1 && increment > 0 && std::isfinite(increment) && std::isfinite(first_angle);
  Fan fan{origin,
          directions,
          first_angle,
          increment,
          max_range_m,
          hits.range_m.data(),
          hits.normal.data(),
          hits.box.data(),
          ci,
          cj,
          n,
          spread,
          static_cast<double>(n - 1) * increment,
          next_query()};
  if (const double seen = fan.last + 2 * (kFanAngleTolerance + kBlindMarginRad);
      spread && seen >= M_PI && seen < 2 * M_PI) {
    fan.blind = true;
    fan.blind_from = unit_from_angle(first_angle + fan.last + kFanAngleTolerance + kBlindMarginRad);
    fan.blind_to = unit_from_angle(first_angle - kFanAngleTolerance - kBlindMarginRad);
  }
  for (long j = j0; j <= j1; ++j)
    fan.unvisited += first_[static_cast<std::size_t>(j * nx_ + i1 + 1)] -
                     first_[static_cast<std::size_t>(j * nx_ + i0)];
  const long rings = std::max({ci - i0, i1 - ci, cj - j0, j1 - cj});
  for (long k = 0; k <= rings; ++k) {
    if (fan_settled_before_ring(fan, k)) return;
    for (long i = std::max(i0, ci - k); i <= std::min(i1, ci + k); ++i) {
      if (cj - k >= j0) fan_visit_cell(fan, i, cj - k);
      if (k > 0 && cj + k <= j1) fan_visit_cell(fan, i, cj + k);
    }
    for (long j = std::max(j0, cj - k + 1); j <= std::min(j1, cj + k - 1); ++j) {
      if (ci - k >= i0) fan_visit_cell(fan, ci - k, j);
      if (k > 0 && ci + k <= i1) fan_visit_cell(fan, ci + k, j);
    }
  }
}

bool RayGrid::near(Vec2 p, double margin_m) const {
  const Rect q{p.x - margin_m, p.y - margin_m, p.x + margin_m, p.y + margin_m};
  if (q.xmax < area_.xmin || q.xmin > area_.xmax || q.ymax < area_.ymin || q.ymin > area_.ymax)
    return false;
  long i0, i1, j0, j1;
  cells_of(q, i0, i1, j0, j1);
  for (long j = j0; j <= j1; ++j)
    for (long i = i0; i <= i1; ++i) {
      const std::size_t c = static_cast<std::size_t>(j * nx_ + i);
      for (std::uint32_t m = first_[c]; m < first_[c + 1]; ++m) {
        const Rect& b = bounds_[static_cast<std::size_t>(members_[m])];
        if (b.xmin <= q.xmax && q.xmin <= b.xmax && b.ymin <= q.ymax && q.ymin <= b.ymax)
          return true;
      }
    }
  return false;
}

}  // namespace plantsim::geom
