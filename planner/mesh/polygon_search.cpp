// Polyanya over the convex mesh. Sides are measured as signed distances (cross products over a
// unit direction), so the one tolerance of the mesh, a length, decides every "on the line".
#include "planner/mesh/polygon_search.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geometry/vec2.h"
#include "planner/mesh/landmarks.h"

namespace plantsim::planner {
using geom::cross;
using geom::dot;

namespace {

DeadEnds dead_ends_of(const ConvexMesh& mesh) {
  std::vector<std::int32_t> first{0}, neighbour;
  for (std::int32_t p = 0; p < mesh.polygon_count(); ++p) {
    neighbour.insert(neighbour.end(), mesh.neighbours(p), mesh.neighbours(p) + mesh.size(p));
    first.push_back(static_cast<std::int32_t>(neighbour.size()));
  }
  return DeadEnds(first, neighbour);
}

// A range of an edge's parameter t in [0, 1]; empty when lo > hi.
struct Range {
  double lo, hi;
  Range meet(Range o) const { return {std::max(lo, o.lo), std::min(hi, o.hi)}; }
};

// Where fa + t (fb - fa) >= -eps: a side of a line, measured at the edge's two ends.
Range nonnegative(double fa, double fb, double eps) {
  if (fa >= -eps && fb >= -eps) return {0, 1};
  if (fa < -eps && fb < -eps) return {1, 0};
  const double t = fa / (fa - fb);
  return fa < -eps ? Range{t, 1} : Range{0, t};
}

Vec2 along(Vec2 a, Vec2 b, double t) {
  return t <= 0 ? a : t >= 1 ? b : Vec2{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
}

}  // namespace

PolygonSearch::PolygonSearch(const ConvexMesh& mesh)
    : mesh_(mesh),
      dead_ends_(dead_ends_of(mesh)),
      goal_stamp_(mesh.polygon_count(), 0),
      best_(mesh.points().size()),
      stamp_(mesh.points().size(), 0),
      bound_(mesh.points().size()),
      bound_stamp_(mesh.points().size(), 0) {}

// Root-level pruning: a turn at a vertex reached more dearly than before is dropped. One
// reached as cheaply is kept: the same corner seen through another polygon opens other edges.
bool PolygonSearch::corner_improves(std::int32_t vertex, double g) {
  if (stamp_[vertex] == search_) {
    if (g > best_[vertex] + mesh_.tolerance() * 16) return false;
    best_[vertex] = std::min(best_[vertex], g);
  } else {
    stamp_[vertex] = search_;
    best_[vertex] = g;
  }
  return true;
}

// Lower bound on root -> some point of [left, right] -> goal: the straight line, the goal
// mirrored across the interval's line when it is on the root's side.
double PolygonSearch::heuristic(Vec2 left, Vec2 right, Vec2 root) const {
  const Vec2 d = right - left;
  const double dd = dot(d, d);
  if (dd <= 0) return geom::distance(root, left) + geom::distance(left, goal_);
  const double sr = cross(d, root - left), st = cross(d, goal_ - left);
  if (std::fabs(sr) <= mesh_.tolerance() * std::sqrt(dd)) return geom::distance(root, goal_);
  Vec2 t = goal_;
  if ((sr > 0) == (st > 0)) t = goal_ - (2 * st / dd) * Vec2{-d.y, d.x};
  const double o1 = cross(t - root, left - root), o2 = cross(t - root, right - root);
  if ((o1 <= 0 && o2 >= 0) || (o1 >= 0 && o2 <= 0)) return geom::distance(root, t);
  return std::min(geom::distance(root, left) + geom::distance(left, t),
                  geom::distance(root, right) + geom::distance(right, t));
}

void PolygonSearch::push(std::int32_t parent, std::int32_t polygon, std::int32_t k, Vec2 right,
                         Vec2 left, Vec2 root, std::int32_t root_vertex, double g) {
  const std::int32_t beyond = mesh_.neighbours(polygon)[k];
  const std::int32_t entry = mesh_.twins(polygon)[k], k1 = k + 1 < mesh_.size(polygon) ? k + 1 : 0;
  const Vec2 a = mesh_.corner_points(polygon)[k], b = mesh_.corner_points(polygon)[k1];
  const double eps = mesh_.tolerance(), side = cross(b - a, root - a),
               reach = eps * eps * dot(b - a, b - a);
  // A root beyond the edge would look back through it: a ray that only touches the edge at an
  // end, passing by. (Sides compared squared: no square root on the common way.)
  if (side < 0 && side * side > reach) return;
  if (side * side <= reach) {
    const double len = geom::distance(a, b), at = dot(root - a, b - a) / len;
    if (at >= -eps &&
        at <= len + eps) {  // the root is on the edge: all of the polygon beyond is in view
      q_.fresh.push_back({beyond, entry, b, a, root, root_vertex, parent, g});
      return;
    }
    // On the edge's line, off the edge: along the line to its nearer end, turning there.
    const std::int32_t near = mesh_.corners(polygon)[at < 0 ? k : k1];
    const Vec2 c = mesh_.points()[near];
    const double gc = g + geom::distance(root, c);
    if (!corner_improves(near, gc)) return;
    if (!(q_.nodes[parent].root ==
          root)) {  // a turn at `root` first: recorded for the path, never searched
      q_.nodes.push_back({-2, -1, {}, {}, root, root_vertex, parent, g});
      parent = static_cast<std::int32_t>(q_.nodes.size() - 1);
    }
    q_.fresh.push_back({beyond, entry, b, a, c, near, parent, gc});
    return;
  }
  q_.fresh.push_back({beyond, entry, left, right, root, root_vertex, parent, g});
}

void PolygonSearch::push_goal(std::int32_t parent, Vec2 root, double g) {
  q_.push_goal({-1, -1, {}, {}, root, -1, parent, g}, g);
}

void PolygonSearch::expand_in_view(std::int32_t parent, Vec2 root, std::int32_t root_vertex,
                                   double g, std::int32_t polygon, std::int32_t except,
                                   bool from_start) {
  if (goal_stamp_[polygon] == search_) push_goal(parent, root, g + geom::distance(root, goal_));
  if (flood_) record_in_view(polygon, root, g);
  const double eps = mesh_.tolerance();
  for (std::int32_t k = 0; k < mesh_.size(polygon); ++k) {
    if (k == except || mesh_.neighbour(polygon, k) < 0 ||
        dead_ends_.leads_nowhere(polygon, mesh_.neighbour(polygon, k)))
      continue;
    const Vec2 a = mesh_.points()[mesh_.vertex(polygon, k)],
               b = mesh_.points()[mesh_.vertex(polygon, k + 1)];
    if (from_start) {  // the start on this edge: the polygon beyond holds it too and is searched
                       // from it
      const double len = geom::distance(a, b), at = dot(root - a, b - a) / len;
      if (std::fabs(cross(b - a, root - a)) <= eps * len && at >= -eps && at <= len + eps) continue;
    }
    push(parent, polygon, k, a, b, root, root_vertex, g);
  }
}

void PolygonSearch::expand(std::int32_t index) {
  const Node n = q_.nodes[index];
  const std::int32_t Q = n.polygon, j = n.entry;
  const std::int32_t lv = mesh_.vertex(Q, j), rv = mesh_.vertex(Q, j + 1);
  const Vec2 A = mesh_.points()[lv], B = mesh_.points()[rv], r = n.root;
  const double eps = mesh_.tolerance();
  // Q lies left of its edge A -> B; a root not strictly right of it is on the edge (sides
  // compared squared: no square root).
  const double side = cross(B - A, r - A);
  if (side >= 0 || side * side <= eps * eps * dot(B - A, B - A))
    return expand_in_view(index, r, n.root_vertex, n.g, Q, j, false);

  const Vec2 L = n.left, R = n.right;
  const double lr = geom::distance(r, R), ll = geom::distance(r, L);
  const Vec2 uR{(R.x - r.x) / lr, (R.y - r.y) / lr}, uL{(L.x - r.x) / ll, (L.y - r.y) / ll};
  const auto right_side = [&](Vec2 p) {
    return cross(uR, p - r);
  };  // >= 0: not right of the ray through R
  const auto left_side = [&](Vec2 p) {
    return cross(uL, p - r);
  };  // <= 0: not left of the ray through L
  const bool turn_right = mesh_.is_corner(rv) && dot(R - B, R - B) <= eps * eps;
  const bool turn_left = mesh_.is_corner(lv) && dot(L - A, L - A) <= eps * eps;
  const double gR = turn_right ? n.g + geom::distance(r, B) : 0,
               gL = turn_left ? n.g + geom::distance(r, A) : 0;
  const bool use_right = turn_right && corner_improves(rv, gR);
  const bool use_left = turn_left && corner_improves(lv, gL);
  if (flood_) record_view(Q, r, n.g, uR, uL, turn_right, B, gR, turn_left, A, gL);

  if (goal_stamp_[Q] == search_) {
    const double gr = right_side(goal_), gl = left_side(goal_);
    if (gr >= -eps && gl <= eps)
      push_goal(index, r, n.g + geom::distance(r, goal_));
    else if (gr < -eps && use_right)
      push_goal(index, B, gR + geom::distance(B, goal_));
    else if (gl > eps && use_left)
      push_goal(index, A, gL + geom::distance(A, goal_));
  }
  // Round the far side from the entry edge's right end, each vertex's sides measured once.
  const std::int32_t count = mesh_.size(Q);
  const Vec2* corner = mesh_.corner_points(Q);
  const std::int32_t* beyond = mesh_.neighbours(Q);
  std::int32_t k = j + 1 < count ? j + 1 : 0;
  Vec2 a = B;
  double ra = right_side(a), la = left_side(a);
  for (std::int32_t step = 1; step < count; ++step) {
    const std::int32_t next = k + 1 < count ? k + 1 : 0;
    const Vec2 b = corner[next];
    const double rb = right_side(b), lb = left_side(b);
    // Walls, dead ends, and edges wholly right of the view with no turn there or wholly left:
    // nothing.
    if (beyond[k] >= 0 && (rb >= -eps || use_right) && (la <= eps || use_left) &&
        !dead_ends_.leads_nowhere(Q, beyond[k])) {
      // The part in view: not right of the ray through R, not left of the ray through L. (Each
      // side is a range of the edge, though not always at its same end: a ray through an end
      // of the entry edge may run inside Q and meet the far side twice.)
      const Range seen = nonnegative(ra, rb, eps).meet(nonnegative(-la, -lb, eps));
      if (seen.lo <= seen.hi + 1e-12)
        push(index, Q, k, along(a, b, seen.lo), along(a, b, seen.hi), r, n.root_vertex, n.g);
      if (use_right && std::min(ra, rb) < -eps) {
        const Range hidden = nonnegative(-ra, -rb, eps);
        push(index, Q, k, along(a, b, hidden.lo), along(a, b, hidden.hi), B, rv, gR);
      }
      if (use_left && std::max(la, lb) > eps) {
        const Range hidden = nonnegative(la, lb, eps);
        push(index, Q, k, along(a, b, hidden.lo), along(a, b, hidden.hi), A, lv, gL);
      }
    }
    a = b, ra = rb, la = lb, k = next;
  }
}

double PolygonSearch::priority(const Node& n) {
  return flood_ ? 0 : std::max(heuristic(n.left, n.right, n.root), landmark_bound(n.root_vertex));
}

void PolygonSearch::queue_fresh() {
  q_.queue_fresh([&](const Node& n) { return priority(n); });
}

std::int32_t PolygonSearch::run(IntervalPath& out) {
  return q_.run(
      budget_bytes_, out, [](const Node& n) { return n.polygon == -1; },
      [&](const Node& n) {
        return n.root_vertex >= 0 && best_[n.root_vertex] + mesh_.tolerance() * 16 < n.g;
      },
      [&](std::int32_t index) { expand(index); }, [&](const Node& n) { return priority(n); });
}

void PolygonSearch::begin(Vec2 goal) {
  goal_ = goal;
  q_.clear();
  if (++search_ == 0) {  // the stamps wrapped: forget them all
    std::fill(stamp_.begin(), stamp_.end(), 0);
    std::fill(goal_stamp_.begin(), goal_stamp_.end(), 0);
    std::fill(bound_stamp_.begin(), bound_stamp_.end(), 0);
    search_ = 1;
  }
}

IntervalPath PolygonSearch::find(Vec2 start, Vec2 goal) {
  IntervalPath out;
  begin(goal);
  const std::vector<std::int32_t> first = mesh_.polygons_at(start), last = mesh_.polygons_at(goal);
  if (first.empty() || last.empty()) return out;
  for (const std::int32_t p : last) goal_stamp_[p] = search_;
  dead_ends_.set_goal(last.data(), prune_dead_ends_ ? last.size() : 0);
  for (const std::int32_t p : first)
    if (goal_stamp_[p] == search_) {
      out.found = true;
      out.path = {start, goal};
      return out;
    }
  if (prune_dead_ends_ && through_channel(first, last, start, goal, out)) return out;
  use_landmarks_ = landmarks_ > 0 && !at_pinch(last, goal);
  if (use_landmarks_) {
    bound_landmark_distances(last, goal, goal_low_, goal_high_);
    bound_landmark_distances(first, start, start_low_, start_high_);
    start_bound_ = at_pinch(first, start)
                       ? 0
                       : planner::landmark_bound(start_low_.data(), start_high_.data(), goal_low_,
                                                 goal_high_, mesh_.tolerance());
  }
  q_.nodes.push_back({-1, -1, {}, {}, start, -1, -1, 0});
  q_.fresh.clear();
  for (const std::int32_t p : first) expand_in_view(0, start, -1, 0, p, -1, true);
  queue_fresh();
  const std::int32_t reached = run(out);
  read_back(q_.nodes, reached, goal, out);
  return out;
}

// Every way from the start to the goal crosses each bridge between them once (crossing an edge
// twice, the straight piece of it between is shorter) and, between two bridges, stays in the
// convex polygon they bound (a way out of it and back in is longer than the straight one
// across it): the shortest way is the taut string through that row of polygons, from the last
// polygon on it holding the start to the first after it holding the goal. So only when no
// polygon holding the start lies beyond the row's first bridge (the start would be on both its
// sides) and none holding the goal before its last.
bool PolygonSearch::through_channel(const std::vector<std::int32_t>& first,
                                    const std::vector<std::int32_t>& last, Vec2 start, Vec2 goal,
                                    IntervalPath& out) {
  if (!dead_ends_.bridge_path(first.front(), last.front(), channel_)) return false;
  const auto length = static_cast<std::ptrdiff_t>(channel_.size());
  const auto at = [&](std::int32_t polygon) {
    return static_cast<std::ptrdiff_t>(std::find(channel_.begin(), channel_.end(), polygon) -
                                       channel_.begin());
  };
  std::ptrdiff_t from = 0, to = length - 1;
  for (const std::int32_t p : first)
    if (const std::ptrdiff_t i = at(p); i < length) from = std::max(from, i);
  for (const std::int32_t p : last)
    if (const std::ptrdiff_t i = at(p); i < length && i > from) to = std::min(to, i);
  if (from >= to) return false;
  for (const std::int32_t p : first)
    if (dead_ends_.beyond(channel_[from], channel_[from + 1], p)) return false;
  for (const std::int32_t p : last)
    if (!dead_ends_.beyond(channel_[to - 1], channel_[to], p)) return false;
  portals_.clear();
  for (std::ptrdiff_t i = from; i < to; ++i) {
    const std::int32_t p = channel_[i], q = channel_[i + 1], n = mesh_.size(p);
    std::int32_t k = 0;
    while (mesh_.neighbours(p)[k] != q) ++k;  // a bridge: the one edge they share
    // Leaving p (left of its edge k, counter-clockwise), the edge's far corner is on the left.
    portals_.push_back({mesh_.corner_points(p)[k + 1 < n ? k + 1 : 0], mesh_.corner_points(p)[k]});
  }
  out.found = out.through_channel = true;
  out.path = funnel_path(start, portals_, goal, mesh_.tolerance());
  out.expanded = to - from;  // the polygons walked
  return true;
}

// A point at a pinch is two points, one on each side: distances to it break the triangle
// inequality the landmarks' bound rests on, so a query that starts or ends there does without.
bool PolygonSearch::at_pinch(const std::vector<std::int32_t>& polygons, Vec2 p) const {
  const double eps = mesh_.tolerance();
  for (const std::int32_t q : polygons)
    for (std::int32_t k = 0; k < mesh_.size(q); ++k) {
      const std::int32_t v = mesh_.vertex(q, k);
      if (mesh_.is_pinch(v) && dot(mesh_.points()[v] - p, mesh_.points()[v] - p) <= eps * eps)
        return true;
    }
  return false;
}

void PolygonSearch::record_in_view(std::int32_t polygon, Vec2 r, double g) {
  for (std::int32_t k = 0; k < mesh_.size(polygon); ++k) {
    const std::int32_t v = mesh_.vertex(polygon, k);
    (*flood_)[v] = std::min((*flood_)[v], g + geom::distance(r, mesh_.points()[v]));
  }
}

// The polygon's vertices in the node's view get the straight way; those right (left) of it,
// the way bending at the interval's right (left) end when that is a corner.
void PolygonSearch::record_view(std::int32_t polygon, Vec2 r, double g, Vec2 uR, Vec2 uL,
                                bool right, Vec2 B, double gR, bool left, Vec2 A, double gL) {
  const double eps = mesh_.tolerance();
  for (std::int32_t k = 0; k < mesh_.size(polygon); ++k) {
    const std::int32_t v = mesh_.vertex(polygon, k);
    const Vec2 p = mesh_.points()[v];
    const double rs = cross(uR, p - r), ls = cross(uL, p - r);
    double& d = (*flood_)[v];
    if (rs >= -eps && ls <= eps)
      d = std::min(d, g + geom::distance(r, p));
    else if (rs < -eps && right)
      d = std::min(d, gR + geom::distance(B, p));
    else if (ls > eps && left)
      d = std::min(d, gL + geom::distance(A, p));
  }
}

std::vector<double> PolygonSearch::distances_to_vertices(Vec2 source) {
  std::vector<double> out(mesh_.points().size(), std::numeric_limits<double>::infinity());
  const std::vector<std::int32_t> first = mesh_.polygons_at(source);
  if (first.empty()) return out;
  flood_ = &out;
  dead_ends_.set_goal(nullptr, 0);
  begin({std::numeric_limits<double>::quiet_NaN(),
         std::numeric_limits<double>::quiet_NaN()});  // a goal nowhere
  q_.nodes.push_back({-1, -1, {}, {}, source, -1, -1, 0});
  q_.fresh.clear();
  for (const std::int32_t p : first) expand_in_view(0, source, -1, 0, p, -1, true);
  queue_fresh();
  IntervalPath flood;
  run(flood);
  flood_ = nullptr;
  // Distances cut short would bound too high: the landmarks cannot be had on this map.
  if (flood.over_budget_bytes > 0)
    throw std::invalid_argument(search_limit_note(
        "polyanya landmarks", budget_bytes_, flood.over_budget_bytes, "one landmark's search"));
  return out;
}

void PolygonSearch::add_landmarks(int count) {
  if (mesh_.polygon_count() == 0 || count <= 0) return;
  LandmarkTable table = measure_landmarks(
      count, mesh_.points().size(), static_cast<std::size_t>(mesh_.vertex(0, 0)),
      [&](std::size_t v) { return distances_to_vertices(mesh_.points()[v]); },
      [&](std::size_t v) { return mesh_.is_pinch(static_cast<std::int32_t>(v)); });
  landmarks_ = table.landmarks;
  vertex_distance_ = std::move(table.distance);
}

// Each landmark's distance to p lies within its distance to a vertex of a (convex) polygon
// holding p, give or take the straight way between them; reached through whichever polygon
// holding p is nearest, so the bounds through each are combined by their minimum. (Through one
// polygon alone they would fail where p is a pinch point, reached from the other side.)
void PolygonSearch::bound_landmark_distances(const std::vector<std::int32_t>& polygons, Vec2 p,
                                             std::vector<double>& low,
                                             std::vector<double>& high) const {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  low.assign(landmarks_, kInf);
  high.assign(landmarks_, kInf);
  std::vector<double> side_low(landmarks_), side_high(landmarks_);
  for (const std::int32_t polygon : polygons) {
    std::fill(side_low.begin(), side_low.end(), -kInf);
    std::fill(side_high.begin(), side_high.end(), kInf);
    for (std::int32_t i = 0; i < mesh_.size(polygon); ++i) {
      const std::int32_t v = mesh_.vertex(polygon, i);
      const double to = geom::distance(mesh_.points()[v], p);
      for (int k = 0; k < landmarks_; ++k) {
        const double d = vertex_distance_[static_cast<std::size_t>(v) * landmarks_ + k];
        if (!std::isfinite(d)) continue;  // unreachable, or a pinch (NaN)
        side_low[k] = std::max(side_low[k], d - to);
        side_high[k] = std::min(side_high[k], d + to);
      }
    }
    for (int k = 0; k < landmarks_; ++k)
      low[k] = std::min(low[k], side_low[k]), high[k] = std::min(high[k], side_high[k]);
  }
  for (int k = 0; k < landmarks_; ++k)
    if (!std::isfinite(low[k]) || !std::isfinite(high[k]))
      low[k] = high[k] = std::numeric_limits<double>::quiet_NaN();
}

// max over landmarks of |d(L, goal) - d(L, root)|, bounded from below; a hair less, so that
// rounding can never make it overestimate.
double PolygonSearch::landmark_bound(std::int32_t root_vertex) {
  if (!use_landmarks_) return 0;
  if (root_vertex < 0) return start_bound_;
  if (bound_stamp_[root_vertex] == search_) return bound_[root_vertex];
  const double* d = &vertex_distance_[static_cast<std::size_t>(root_vertex) * landmarks_];
  bound_stamp_[root_vertex] = search_;
  return bound_[root_vertex] =
             planner::landmark_bound(d, d, goal_low_, goal_high_, mesh_.tolerance());
}

}  // namespace plantsim::planner
