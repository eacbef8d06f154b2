// Interval search over the rectangle mesh. Portals are vertical, so an interval is a y-range
// on a line x = const and projecting it across a cell is one division per end.
#include "planner/mesh/interval_search.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geometry/vec2.h"
#include "planner/mesh/landmarks.h"

namespace plantsim::planner {
namespace {

// A landmark's distance not known (the point is unreachable from it).
constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();

DeadEnds dead_ends_of(const FreeSpaceMesh& mesh) {
  std::vector<std::int32_t> first{0}, neighbour;
  for (std::int32_t c = 0; c < static_cast<std::int32_t>(mesh.cells().size()); ++c) {
    for (const auto side : {mesh.left_portals(c), mesh.right_portals(c)})
      for (const std::int32_t q : side)
        neighbour.push_back(mesh.portals()[q].left == c ? mesh.portals()[q].right
                                                        : mesh.portals()[q].left);
    first.push_back(static_cast<std::int32_t>(neighbour.size()));
  }
  return DeadEnds(first, neighbour);
}

}  // namespace

IntervalSearch::IntervalSearch(const FreeSpaceMesh& mesh)
    : mesh_(mesh),
      dead_ends_(dead_ends_of(mesh)),
      best_(2 * mesh.portals().size()),
      stamp_(2 * mesh.portals().size(), 0) {}

std::int32_t IntervalSearch::other_side(std::int32_t portal, std::int32_t cell) const {
  const MeshPortal& p = mesh_.portals()[portal];
  return p.left == cell ? p.right : p.left;
}

double IntervalSearch::heuristic(double x, double ya, double yb, Vec2 root) const {
  if (std::fabs(root.x - x) <= mesh_.tolerance())
    return geom::distance(root, goal_);  // the root is on the interval
  Vec2 t = goal_;
  if ((t.x - x) * (root.x - x) > 0) t.x = 2 * x - t.x;  // mirrored: the way must cross the line
  const double yc = root.y + (t.y - root.y) * ((x - root.x) / (t.x - root.x));
  if (yc >= ya && yc <= yb) return geom::distance(root, t);
  const Vec2 e{x, yc < ya ? ya : yb};
  return geom::distance(root, e) + geom::distance(e, t);
}

bool IntervalSearch::corner_improves(std::int32_t vertex, double g, Vec2 from, Vec2 corner) {
  const double tol = mesh_.tolerance() * 16;
  const double len = geom::distance(from, corner);
  const Vec2 dir =
      len > 0 ? Vec2{(corner.x - from.x) / len, (corner.y - from.y) / len} : Vec2{0, 0};
  if (stamp_[vertex] == search_) {
    Arrival& best = best_[vertex];
    if (g > best.g + tol) return false;
    // As cheap as before along the same line (corners in a row, reached through one another):
    // the turn would make the very same successors again.
    if (g >= best.g - tol && std::fabs(dir.x * best.dir.y - dir.y * best.dir.x) <= 1e-12 &&
        dir.x * best.dir.x + dir.y * best.dir.y > 0)
      return false;
    if (g < best.g) best = {g, dir};
  } else {
    stamp_[vertex] = search_;
    best_[vertex] = {g, dir};
  }
  return true;
}

void IntervalSearch::push(std::int32_t parent, std::int32_t portal, std::int32_t cell, double ya,
                          double yb, Vec2 root, std::int32_t root_vertex, double g) {
  const MeshPortal& p = mesh_.portals()[portal];
  ya = std::clamp(ya, p.y0, p.y1);
  yb = std::clamp(yb, ya, p.y1);
  q_.fresh.push_back({portal, cell, ya, yb, root, root_vertex, parent, g});
}

double IntervalSearch::priority(const Node& n) const {
  if (flood_) return 0;
  const double x = mesh_.portals()[n.portal].x;
  return std::max(heuristic(x, n.ya, n.yb, n.root), landmark_bound(n.root_vertex));
}

void IntervalSearch::queue_fresh() {
  q_.queue_fresh([&](const Node& n) { return priority(n); });
}

void IntervalSearch::push_goal(std::int32_t parent, Vec2 root, double g) {
  q_.push_goal({-1, -1, 0, 0, root, -1, parent, g}, g);
}

// `from` lies on the portal's line but off the portal: the way goes along the line to the
// portal's nearer end (a corner) and turns there into the cell beyond.
void IntervalSearch::push_along_line(std::int32_t parent, Vec2 from, double g, std::int32_t portal,
                                     std::int32_t cell) {
  const MeshPortal& q = mesh_.portals()[portal];
  const int end = from.y > q.y1 ? 1 : 0;
  const Vec2 c{q.x, end ? q.y1 : q.y0};
  const double gc = g + geom::distance(from, c);
  if (!corner_improves(2 * portal + end, gc, from, c)) return;
  if (!(q_.nodes[parent].root ==
        from)) {  // a turn at `from` first: recorded for the path, never searched
    q_.nodes.push_back({-2, -1, 0, 0, from, -1, parent, g});
    parent = static_cast<std::int32_t>(q_.nodes.size() - 1);
  }
  push(parent, portal, cell, q.y0, q.y1, c, 2 * portal + end, gc);
}

void IntervalSearch::expand_in_view(std::int32_t parent, Vec2 root, std::int32_t root_vertex,
                                    double g, std::int32_t cell, std::int32_t except) {
  const double eps = mesh_.tolerance();
  if (flood_) record_corners_in_view(cell, root, g);
  if (mesh_.cell_holds(cell, goal_)) push_goal(parent, root, g + geom::distance(root, goal_));
  for (const auto side : {mesh_.left_portals(cell), mesh_.right_portals(cell)})
    for (const std::int32_t q : side) {
      if (q == except || dead_ends_.leads_nowhere(cell, other_side(q, cell))) continue;
      const MeshPortal& p = mesh_.portals()[q];
      if (std::fabs(root.x - p.x) > eps)
        push(parent, q, other_side(q, cell), p.y0, p.y1, root, root_vertex, g);
      else if (root.y < p.y0 - eps || root.y > p.y1 + eps)
        push_along_line(parent, root, g, q, other_side(q, cell));
      // else the root is on this portal: the cell beyond holds it too and is searched from it.
    }
}

void IntervalSearch::expand(std::int32_t index) {
  const Node n = q_.nodes[index];
  const MeshPortal& P = mesh_.portals()[n.portal];
  const double x = P.x, eps = mesh_.tolerance();
  const Vec2 r = n.root;
  if (std::fabs(r.x - x) <= eps)
    return expand_in_view(index, r, n.root_vertex, n.g, n.cell, n.portal);

  const MeshCell& D = mesh_.cells()[n.cell];
  const bool rightward = x > r.x;
  const double far = rightward ? D.xhi : D.xlo;
  const double s = (far - r.x) / (x - r.x);
  const double ya_far = r.y + (n.ya - r.y) * s, yb_far = r.y + (n.yb - r.y) * s;
  // Turns: where the interval ends at an obstacle corner, the cell behind that corner's ray
  // is reached by bending there.
  const bool turn_low = P.corner0 && n.ya <= P.y0 + eps,
             turn_high = P.corner1 && n.yb >= P.y1 - eps;
  const Vec2 a{x, P.y0}, b{x, P.y1};
  const double ga = turn_low ? n.g + geom::distance(r, a) : 0,
               gb = turn_high ? n.g + geom::distance(r, b) : 0;
  const bool use_low = turn_low && corner_improves(2 * n.portal, ga, r, a);
  const bool use_high = turn_high && corner_improves(2 * n.portal + 1, gb, r, b);
  if (flood_) record_corners(n.cell, r, n.g, x, n.ya, n.yb, turn_low, a, ga, turn_high, b, gb);

  if (mesh_.cell_holds(n.cell, goal_)) {
    const double sg = (goal_.x - r.x) / (x - r.x);
    const double lo = r.y + (n.ya - r.y) * sg, hi = r.y + (n.yb - r.y) * sg;
    if (goal_.y >= lo - eps && goal_.y <= hi + eps)
      push_goal(index, r, n.g + geom::distance(r, goal_));
    else if (goal_.y < lo && use_low)
      push_goal(index, a, ga + geom::distance(a, goal_));
    else if (goal_.y > hi && use_high)
      push_goal(index, b, gb + geom::distance(b, goal_));
  }
  const auto far_side = rightward ? mesh_.right_portals(n.cell) : mesh_.left_portals(n.cell);
  for (const std::int32_t q : far_side) {
    const MeshPortal& Q = mesh_.portals()[q];
    const std::int32_t beyond = other_side(q, n.cell);
    if (dead_ends_.leads_nowhere(n.cell, beyond)) continue;
    const double lo = std::max(Q.y0, ya_far), hi = std::min(Q.y1, yb_far);
    if (lo <= hi + eps) push(index, q, beyond, lo, hi, r, n.root_vertex, n.g);
    if (use_low && ya_far > Q.y0 + eps)
      push(index, q, beyond, Q.y0, std::min(Q.y1, ya_far), a, 2 * n.portal, ga);
    if (use_high && yb_far < Q.y1 - eps)
      push(index, q, beyond, std::max(Q.y0, yb_far), Q.y1, b, 2 * n.portal + 1, gb);
  }
  if (!use_low && !use_high) return;
  // Portals on the near side beyond the corner lie on the corner's own line.
  const auto near_side = rightward ? mesh_.left_portals(n.cell) : mesh_.right_portals(n.cell);
  for (const std::int32_t q : near_side) {
    if (q == n.portal || dead_ends_.leads_nowhere(n.cell, other_side(q, n.cell))) continue;
    const MeshPortal& Q = mesh_.portals()[q];
    if (use_low && Q.y1 <= P.y0 + eps) push_along_line(index, a, ga, q, other_side(q, n.cell));
    if (use_high && Q.y0 >= P.y1 - eps) push_along_line(index, b, gb, q, other_side(q, n.cell));
  }
}

// A* until the goal is popped (its node's index) or the queue runs dry (-1).
std::int32_t IntervalSearch::run(IntervalPath& out) {
  return q_.run(
      budget_bytes_, out, [](const Node& n) { return n.portal == -1; },
      // Its root was reached more cheaply since it was queued: the cheaper arrival covers it.
      [&](const Node& n) {
        return n.root_vertex >= 0 && best_[n.root_vertex].g + mesh_.tolerance() * 16 < n.g;
      },
      [&](std::int32_t index) { expand(index); }, [&](const Node& n) { return priority(n); });
}

void IntervalSearch::begin(Vec2 goal) {
  goal_ = goal;
  q_.clear();
  if (++search_ == 0) {  // the stamps wrapped: forget them all
    std::fill(stamp_.begin(), stamp_.end(), 0);
    search_ = 1;
  }
}

void IntervalSearch::queue_source(Vec2 source, const std::vector<std::int32_t>& cells) {
  q_.nodes.push_back({-1, -1, 0, 0, source, -1, -1, 0});
  q_.fresh.clear();
  for (const std::int32_t c : cells) expand_in_view(0, source, -1, 0, c, -1);
  queue_fresh();
}

IntervalPath IntervalSearch::find(Vec2 start, Vec2 goal) {
  IntervalPath out;
  begin(goal);
  const std::vector<std::int32_t> first = mesh_.cells_at(start), last = mesh_.cells_at(goal);
  if (first.empty() || last.empty()) return out;
  dead_ends_.set_goal(last.data(), prune_dead_ends_ ? last.size() : 0);
  for (const std::int32_t c : first)
    if (mesh_.cell_holds(c, goal)) {
      out.found = true;
      out.path = {start, goal};
      return out;
    }
  // A goal at a pinch is two points, one on each side: distances to it break the triangle
  // inequality the landmarks' bound rests on, so such a query does without them.
  use_landmarks_ = landmarks_ > 0 && !mesh_.is_pinch(goal);
  if (use_landmarks_) {
    // The start is no corner: its distances are bounded from its cell's corners, as the goal's.
    set_goal_bounds(first.front(), start);
    const std::vector<double> start_low = goal_low_, start_high = goal_high_;
    set_goal_bounds(last.front(), goal);
    start_bound_ = mesh_.is_pinch(start)
                       ? 0
                       : planner::landmark_bound(start_low.data(), start_high.data(), goal_low_,
                                                 goal_high_, mesh_.tolerance());
  }
  queue_source(start, first);  // the start, as the first root
  const std::int32_t reached = run(out);
  read_back(q_.nodes, reached, goal, out);
  return out;
}

// Every point where the mesh's cells meet (cell corners and portal ends) gets one number, so
// that a distance measured through any cell reaches them all.
void IntervalSearch::number_points() {
  if (!point_of_corner_.empty()) return;
  const auto& cells = mesh_.cells();
  const auto& portals = mesh_.portals();
  std::vector<std::pair<Vec2, std::size_t>> all;
  all.reserve(4 * cells.size() + 2 * portals.size());
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const MeshCell& m = cells[c];
    all.push_back({{m.xlo, m.ylo}, 4 * c}), all.push_back({{m.xhi, m.ylo}, 4 * c + 1});
    all.push_back({{m.xlo, m.yhi}, 4 * c + 2}), all.push_back({{m.xhi, m.yhi}, 4 * c + 3});
  }
  const std::size_t ends = 4 * cells.size();
  for (std::size_t p = 0; p < portals.size(); ++p) {
    all.push_back({{portals[p].x, portals[p].y0}, ends + 2 * p});
    all.push_back({{portals[p].x, portals[p].y1}, ends + 2 * p + 1});
  }
  std::sort(all.begin(), all.end(), [](const auto& u, const auto& v) {
    return u.first.x != v.first.x ? u.first.x < v.first.x : u.first.y < v.first.y;
  });
  point_of_corner_.resize(ends);
  point_of_end_.resize(2 * portals.size());
  points_ = 0;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (i > 0 && !(all[i].first == all[i - 1].first)) ++points_;
    const std::size_t slot = all[i].second;
    (slot < ends ? point_of_corner_[slot] : point_of_end_[slot - ends]) =
        static_cast<std::int32_t>(points_);
  }
  ++points_;
}

template <typename F>
void IntervalSearch::for_each_point(std::int32_t cell, F&& f) const {
  const MeshCell& c = mesh_.cells()[cell];
  const std::size_t k = 4 * static_cast<std::size_t>(cell);
  f(Vec2{c.xlo, c.ylo}, point_of_corner_[k]), f(Vec2{c.xhi, c.ylo}, point_of_corner_[k + 1]);
  f(Vec2{c.xlo, c.yhi}, point_of_corner_[k + 2]), f(Vec2{c.xhi, c.yhi}, point_of_corner_[k + 3]);
  for (const auto side : {mesh_.left_portals(cell), mesh_.right_portals(cell)})
    for (const std::int32_t q : side) {
      const MeshPortal& p = mesh_.portals()[q];
      f(Vec2{p.x, p.y0}, point_of_end_[2 * q]), f(Vec2{p.x, p.y1}, point_of_end_[2 * q + 1]);
    }
}

void IntervalSearch::record_corners_in_view(std::int32_t cell, Vec2 r, double g) {
  for_each_point(cell, [&](Vec2 p, std::int32_t id) {
    (*flood_)[id] = std::min((*flood_)[id], g + geom::distance(r, p));
  });
}

// The cell's points within the node's view get the way through it; those behind a corner the
// interval ends at, the way bending there.
void IntervalSearch::record_corners(std::int32_t cell, Vec2 r, double g, double x, double ya,
                                    double yb, bool low, Vec2 a, double ga, bool high, Vec2 b,
                                    double gb) {
  const double eps = mesh_.tolerance();
  for_each_point(cell, [&](Vec2 p, std::int32_t id) {
    const double s = (p.x - r.x) / (x - r.x);
    const double lo = r.y + (ya - r.y) * s, hi = r.y + (yb - r.y) * s;
    double& d = (*flood_)[id];
    if (p.y >= lo - eps && p.y <= hi + eps)
      d = std::min(d, g + geom::distance(r, p));
    else if (p.y < lo && low)
      d = std::min(d, ga + geom::distance(a, p));
    else if (p.y > hi && high)
      d = std::min(d, gb + geom::distance(b, p));
  });
}

std::vector<double> IntervalSearch::distances_to_corners(Vec2 source) {
  number_points();
  std::vector<double> at_point(points_, std::numeric_limits<double>::infinity());
  std::vector<double> out(4 * mesh_.cells().size(), std::numeric_limits<double>::infinity());
  const std::vector<std::int32_t> first = mesh_.cells_at(source);
  if (first.empty()) return out;
  flood_ = &at_point;
  dead_ends_.set_goal(nullptr, 0);
  begin({std::numeric_limits<double>::quiet_NaN(),
         std::numeric_limits<double>::quiet_NaN()});  // a goal in no cell
  queue_source(source, first);
  IntervalPath flood;
  run(flood);
  flood_ = nullptr;
  // Distances cut short would bound too high: the landmarks cannot be had on this map.
  if (flood.over_budget_bytes > 0)
    throw std::invalid_argument(search_limit_note(
        "interval landmarks", budget_bytes_, flood.over_budget_bytes, "one landmark's search"));
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = at_point[point_of_corner_[i]];
  return out;
}

void IntervalSearch::add_landmarks(int count) {
  const auto& cells = mesh_.cells();
  if (cells.empty() || count <= 0) return;
  const auto corner_point = [&](std::size_t i) {
    const MeshCell& c = cells[i / 4];
    return Vec2{i % 2 ? c.xhi : c.xlo, i % 4 >= 2 ? c.yhi : c.ylo};
  };
  // Cell 0's lower left corner first.
  LandmarkTable table = measure_landmarks(
      count, 4 * cells.size(), 0,
      [&](std::size_t i) { return distances_to_corners(corner_point(i)); },
      [&](std::size_t i) { return mesh_.is_pinch(corner_point(i)); });
  landmarks_ = table.landmarks;
  corner_distance_ = std::move(table.distance);
  // A portal's end is a corner of the cell on one side or the other (or both).
  const auto& portals = mesh_.portals();
  end_distance_.assign(2 * portals.size() * landmarks_, 0);
  for (std::size_t p = 0; p < portals.size(); ++p) {
    const MeshPortal& q = portals[p];
    const std::size_t low = cells[q.left].ylo == q.y0 ? 4 * q.left + 1 : 4 * q.right + 0;
    const std::size_t high = cells[q.left].yhi == q.y1 ? 4 * q.left + 3 : 4 * q.right + 2;
    for (int k = 0; k < landmarks_; ++k) {
      end_distance_[(2 * p) * landmarks_ + k] = corner_distance_[low * landmarks_ + k];
      end_distance_[(2 * p + 1) * landmarks_ + k] = corner_distance_[high * landmarks_ + k];
    }
  }
  goal_low_.assign(landmarks_, 0);
  goal_high_.assign(landmarks_, 0);
}

// Each landmark's distance to the point lies within its distance to a corner of the point's
// (convex) cell, give or take the straight way between them.
void IntervalSearch::set_goal_bounds(std::int32_t cell, Vec2 p) {
  const MeshCell& c = mesh_.cells()[cell];
  const Vec2 corners[4] = {{c.xlo, c.ylo}, {c.xhi, c.ylo}, {c.xlo, c.yhi}, {c.xhi, c.yhi}};
  for (int k = 0; k < landmarks_; ++k) {
    double low = -std::numeric_limits<double>::infinity(),
           high = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 4; ++i) {
      const double d = corner_distance_[(4 * static_cast<std::size_t>(cell) + i) * landmarks_ + k];
      if (!std::isfinite(d)) continue;
      low = std::max(low, d - geom::distance(corners[i], p));
      high = std::min(high, d + geom::distance(corners[i], p));
    }
    const bool known = std::isfinite(low);
    goal_low_[k] = known ? low : kUnknown, goal_high_[k] = known ? high : kUnknown;
  }
}

// max over landmarks of |d(L, goal) - d(L, root)|, bounded from below; a hair less, so that
// rounding can never make it overestimate.
double IntervalSearch::landmark_bound(std::int32_t root_vertex) const {
  if (!use_landmarks_) return 0;
  if (root_vertex < 0) return start_bound_;
  const double* d = &end_distance_[static_cast<std::size_t>(root_vertex) * landmarks_];
  return planner::landmark_bound(d, d, goal_low_, goal_high_, mesh_.tolerance());
}

}  // namespace plantsim::planner
