// Interval search over the rectangle mesh. Portals are vertical, so an interval is a y-range
// on a line x = const and projecting it across a cell is one division per end.
#include "planner/mesh/interval_search.h"

#include <algorithm>
#include <cmath>

namespace plantsim::planner {
namespace {

// Not std::hypot: coordinates are bounded by the world's limits, and hypot's care for overflow
// cost a third of a query's time.
double dist(Vec2 a, Vec2 b) { return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y)); }

}  // namespace

IntervalSearch::IntervalSearch(const FreeSpaceMesh& mesh)
    : mesh_(mesh), best_(2 * mesh.portals().size()), stamp_(2 * mesh.portals().size(), 0) {}

std::int32_t IntervalSearch::other_side(std::int32_t portal, std::int32_t cell) const {
  const MeshPortal& p = mesh_.portals()[portal];
  return p.left == cell ? p.right : p.left;
}

double IntervalSearch::heuristic(double x, double ya, double yb, Vec2 root) const {
  if (std::fabs(root.x - x) <= mesh_.tolerance()) return dist(root, goal_);  // the root is on the interval
  Vec2 t = goal_;
  if ((t.x - x) * (root.x - x) > 0) t.x = 2 * x - t.x;  // mirrored: the way must cross the line
  const double yc = root.y + (t.y - root.y) * ((x - root.x) / (t.x - root.x));
  if (yc >= ya && yc <= yb) return dist(root, t);
  const Vec2 e{x, yc < ya ? ya : yb};
  return dist(root, e) + dist(e, t);
}

bool IntervalSearch::corner_improves(std::int32_t vertex, double g, Vec2 from, Vec2 corner) {
  const double tol = mesh_.tolerance() * 16;
  const double len = dist(from, corner);
  const Vec2 dir = len > 0 ? Vec2{(corner.x - from.x) / len, (corner.y - from.y) / len} : Vec2{0, 0};
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

void IntervalSearch::push(std::int32_t parent, std::int32_t portal, std::int32_t cell, double ya, double yb, Vec2 root,
                          std::int32_t root_vertex, double g) {
  // A cell whose only portal is this one leads nowhere unless the goal is in it.
  if (mesh_.portal_count(cell) == 1 && !mesh_.cell_holds(cell, goal_)) return;
  const MeshPortal& p = mesh_.portals()[portal];
  ya = std::clamp(ya, p.y0, p.y1);
  yb = std::clamp(yb, ya, p.y1);
  fresh_.push_back({portal, cell, ya, yb, root, root_vertex, parent, g});
}

void IntervalSearch::push_open(Entry e) {
  open_.push_back(e);
  std::push_heap(open_.begin(), open_.end());
}

void IntervalSearch::queue_fresh() {
  for (const Node& n : fresh_) {
    nodes_.push_back(n);
    const double x = mesh_.portals()[n.portal].x;
    push_open({n.g + heuristic(x, n.ya, n.yb, n.root), n.g, static_cast<std::int32_t>(nodes_.size() - 1)});
  }
}

void IntervalSearch::expand_and_queue(std::int32_t index, std::int64_t& expanded) {
  fresh_.clear();
  expand(index);
  ++expanded;
  // A lone successor (a corridor of cells) is expanded at once: its f is no smaller than its
  // parent's, so A* would take it next anyway, and the queue is spared (Polyanya's
  // intermediate pruning).
  while (fresh_.size() == 1) {
    nodes_.push_back(fresh_.front());
    fresh_.clear();
    expand(static_cast<std::int32_t>(nodes_.size() - 1));
    ++expanded;
  }
  queue_fresh();
}

void IntervalSearch::push_goal(std::int32_t parent, Vec2 root, double g) {
  nodes_.push_back({-1, -1, 0, 0, root, -1, parent, g});
  push_open({g, g, static_cast<std::int32_t>(nodes_.size() - 1)});
}

// `from` lies on the portal's line but off the portal: the way goes along the line to the
// portal's nearer end (a corner) and turns there into the cell beyond.
void IntervalSearch::push_along_line(std::int32_t parent, Vec2 from, double g, std::int32_t portal, std::int32_t cell) {
  const MeshPortal& q = mesh_.portals()[portal];
  const int end = from.y > q.y1 ? 1 : 0;
  const Vec2 c{q.x, end ? q.y1 : q.y0};
  const double gc = g + dist(from, c);
  if (!corner_improves(2 * portal + end, gc, from, c)) return;
  if (!(nodes_[parent].root == from)) {  // a turn at `from` first: recorded for the path, never searched
    nodes_.push_back({-2, -1, 0, 0, from, -1, parent, g});
    parent = static_cast<std::int32_t>(nodes_.size() - 1);
  }
  push(parent, portal, cell, q.y0, q.y1, c, 2 * portal + end, gc);
}

void IntervalSearch::expand_in_view(std::int32_t parent, Vec2 root, std::int32_t root_vertex, double g, std::int32_t cell,
                                    std::int32_t except) {
  const double eps = mesh_.tolerance();
  if (mesh_.cell_holds(cell, goal_)) push_goal(parent, root, g + dist(root, goal_));
  for (const auto side : {mesh_.left_portals(cell), mesh_.right_portals(cell)})
    for (const std::int32_t q : side) {
      if (q == except) continue;
      const MeshPortal& p = mesh_.portals()[q];
      if (std::fabs(root.x - p.x) > eps)
        push(parent, q, other_side(q, cell), p.y0, p.y1, root, root_vertex, g);
      else if (root.y < p.y0 - eps || root.y > p.y1 + eps)
        push_along_line(parent, root, g, q, other_side(q, cell));
      // else the root is on this portal: the cell beyond holds it too and is searched from it.
    }
}

void IntervalSearch::expand(std::int32_t index) {
  const Node n = nodes_[index];
  const MeshPortal& P = mesh_.portals()[n.portal];
  const double x = P.x, eps = mesh_.tolerance();
  const Vec2 r = n.root;
  if (std::fabs(r.x - x) <= eps) return expand_in_view(index, r, n.root_vertex, n.g, n.cell, n.portal);

  const MeshCell& D = mesh_.cells()[n.cell];
  const bool rightward = x > r.x;
  const double far = rightward ? D.xhi : D.xlo;
  const double s = (far - r.x) / (x - r.x);
  const double ya_far = r.y + (n.ya - r.y) * s, yb_far = r.y + (n.yb - r.y) * s;
  // Turns: where the interval ends at an obstacle corner, the cell behind that corner's ray
  // is reached by bending there.
  const bool turn_low = P.corner0 && n.ya <= P.y0 + eps, turn_high = P.corner1 && n.yb >= P.y1 - eps;
  const Vec2 a{x, P.y0}, b{x, P.y1};
  const double ga = turn_low ? n.g + dist(r, a) : 0, gb = turn_high ? n.g + dist(r, b) : 0;
  const bool use_low = turn_low && corner_improves(2 * n.portal, ga, r, a);
  const bool use_high = turn_high && corner_improves(2 * n.portal + 1, gb, r, b);

  if (mesh_.cell_holds(n.cell, goal_)) {
    const double sg = (goal_.x - r.x) / (x - r.x);
    const double lo = r.y + (n.ya - r.y) * sg, hi = r.y + (n.yb - r.y) * sg;
    if (goal_.y >= lo - eps && goal_.y <= hi + eps)
      push_goal(index, r, n.g + dist(r, goal_));
    else if (goal_.y < lo && use_low)
      push_goal(index, a, ga + dist(a, goal_));
    else if (goal_.y > hi && use_high)
      push_goal(index, b, gb + dist(b, goal_));
  }
  const auto far_side = rightward ? mesh_.right_portals(n.cell) : mesh_.left_portals(n.cell);
  for (const std::int32_t q : far_side) {
    const MeshPortal& Q = mesh_.portals()[q];
    const std::int32_t beyond = other_side(q, n.cell);
    const double lo = std::max(Q.y0, ya_far), hi = std::min(Q.y1, yb_far);
    if (lo <= hi + eps) push(index, q, beyond, lo, hi, r, n.root_vertex, n.g);
    if (use_low && ya_far > Q.y0 + eps) push(index, q, beyond, Q.y0, std::min(Q.y1, ya_far), a, 2 * n.portal, ga);
    if (use_high && yb_far < Q.y1 - eps) push(index, q, beyond, std::max(Q.y0, yb_far), Q.y1, b, 2 * n.portal + 1, gb);
  }
  if (!use_low && !use_high) return;
  // Portals on the near side beyond the corner lie on the corner's own line.
  const auto near_side = rightward ? mesh_.left_portals(n.cell) : mesh_.right_portals(n.cell);
  for (const std::int32_t q : near_side) {
    if (q == n.portal) continue;
    const MeshPortal& Q = mesh_.portals()[q];
    if (use_low && Q.y1 <= P.y0 + eps) push_along_line(index, a, ga, q, other_side(q, n.cell));
    if (use_high && Q.y0 >= P.y1 - eps) push_along_line(index, b, gb, q, other_side(q, n.cell));
  }
}

IntervalPath IntervalSearch::find(Vec2 start, Vec2 goal) {
  IntervalPath out;
  goal_ = goal;
  nodes_.clear();
  open_.clear();
  if (++search_ == 0) {  // the stamps wrapped: forget them all
    std::fill(stamp_.begin(), stamp_.end(), 0);
    search_ = 1;
  }
  const std::vector<std::int32_t> first = mesh_.cells_at(start);
  if (first.empty() || mesh_.cells_at(goal).empty()) return out;
  for (const std::int32_t c : first)
    if (mesh_.cell_holds(c, goal)) {
      out.found = true;
      out.path = {start, goal};
      return out;
    }
  nodes_.push_back({-1, -1, 0, 0, start, -1, -1, 0});  // the start, as the first root
  fresh_.clear();
  for (const std::int32_t c : first) expand_in_view(0, start, -1, 0, c, -1);
  queue_fresh();
  while (!open_.empty()) {
    std::pop_heap(open_.begin(), open_.end());
    const Entry e = open_.back();
    open_.pop_back();
    const Node& n = nodes_[e.node];
    if (n.portal == -1) {
      out.found = true;
      out.path.push_back(goal);
      for (std::int32_t i = e.node; i >= 0; i = nodes_[i].parent)
        if (!(nodes_[i].root == out.path.back())) out.path.push_back(nodes_[i].root);
      std::reverse(out.path.begin(), out.path.end());
      out.generated = static_cast<std::int64_t>(nodes_.size());
      return out;
    }
    // Its root was reached more cheaply since it was queued: the cheaper arrival covers it.
    if (n.root_vertex >= 0 && best_[n.root_vertex].g + mesh_.tolerance() * 16 < n.g) continue;
    expand_and_queue(e.node, out.expanded);
  }
  out.generated = static_cast<std::int64_t>(nodes_.size());
  return out;
}

}  // namespace plantsim::planner
