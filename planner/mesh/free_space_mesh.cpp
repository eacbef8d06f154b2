// Vertical decomposition of the free floor by an x-sweep over the obstacle rectangles, with a
// coverage tree over the rectangles' y coordinates that lists the uncovered intervals.
#include "planner/mesh/free_space_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace plantsim::planner {
namespace {

// How many rectangles cover each elementary y-interval, answering "which maximal intervals of
// [lo, hi] are uncovered?" in time proportional to their number (times log n).
class Coverage {
 public:
  explicit Coverage(std::size_t leaves)
      : n_(static_cast<int>(leaves)),
        min_(4 * leaves + 4),
        max_(4 * leaves + 4),
        add_(4 * leaves + 4) {}
  void add(int lo, int hi, int v) { add(1, 0, n_ - 1, lo, hi, v); }
  /// Appends the maximal uncovered leaf ranges within leaves [lo, hi], as [first, last].
  void uncovered(int lo, int hi, std::vector<std::pair<int, int>>& out) const {
    uncovered(1, 0, n_ - 1, lo, hi, 0, out);
  }

 private:
  void add(int node, int l, int r, int lo, int hi, int v) {
    if (hi < l || r < lo) return;
    if (lo <= l && r <= hi) {
      add_[node] += v, min_[node] += v, max_[node] += v;
      return;
    }
    const int m = (l + r) / 2;
    add(2 * node, l, m, lo, hi, v);
    add(2 * node + 1, m + 1, r, lo, hi, v);
    min_[node] = add_[node] + std::min(min_[2 * node], min_[2 * node + 1]);
    max_[node] = add_[node] + std::max(max_[2 * node], max_[2 * node + 1]);
  }
  void uncovered(int node, int l, int r, int lo, int hi, int above,
                 std::vector<std::pair<int, int>>& out) const {
    if (hi < l || r < lo || above + min_[node] > 0) return;
    if (above + max_[node] == 0 && lo <= l && r <= hi) {
      if (!out.empty() && out.back().second + 1 == l)
        out.back().second = r;
      else
        out.emplace_back(l, r);
      return;
    }
    const int m = (l + r) / 2;
    uncovered(2 * node, l, m, lo, hi, above + add_[node], out);
    uncovered(2 * node + 1, m + 1, r, lo, hi, above + add_[node], out);
  }
  int n_;
  std::vector<int> min_, max_, add_;
};

struct Event {
  double x;
  int sign;    // +1 the rectangle starts covering, -1 it stops
  int lo, hi;  // leaf range in y
};

struct OpenCell {
  double yhi;
  std::int32_t id;
};

}  // namespace

FreeSpaceMesh::FreeSpaceMesh(const std::vector<Rect>& rects, const Rect& floor) {
  eps_ = 1e-13 * std::max({1.0, std::fabs(floor.xmin), std::fabs(floor.xmax), std::fabs(floor.ymin),
                           std::fabs(floor.ymax)});
  if (!(floor.xmax > floor.xmin && floor.ymax > floor.ymin)) return;  // no free floor: no cells
  std::vector<Rect> blocked;
  std::vector<double> ys{floor.ymin, floor.ymax};
  for (const Rect& r : rects) {
    const Rect c{std::max(r.xmin, floor.xmin), std::max(r.ymin, floor.ymin),
                 std::min(r.xmax, floor.xmax), std::min(r.ymax, floor.ymax)};
    if (c.xmax > c.xmin && c.ymax > c.ymin) {
      blocked.push_back(c);
      ys.push_back(c.ymin);
      ys.push_back(c.ymax);
    }
  }
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  const auto leaf = [&](double y) {
    return static_cast<int>(std::lower_bound(ys.begin(), ys.end(), y) - ys.begin());
  };
  std::vector<Event> events;
  events.reserve(2 * blocked.size());
  for (const Rect& r : blocked) {
    const int lo = leaf(r.ymin), hi = leaf(r.ymax) - 1;
    events.push_back({r.xmin, +1, lo, hi});
    if (r.xmax < floor.xmax) events.push_back({r.xmax, -1, lo, hi});
  }
  std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) { return a.x < b.x; });

  Coverage coverage(ys.size() - 1);
  std::map<double, OpenCell> open;  // by ylo
  std::vector<std::pair<int, int>> runs;
  std::vector<std::pair<double, double>> ranges, hulls;
  std::vector<std::int32_t> closed_now, opened_now;
  const auto open_cell = [&](double x, double ylo, double yhi) {
    const auto id = static_cast<std::int32_t>(cells_.size());
    cells_.push_back({x, std::numeric_limits<double>::quiet_NaN(), ylo, yhi});
    open[ylo] = {yhi, id};
    return id;
  };
  // The open cells whose intervals overlap or touch [lo, hi], as map iterators [first, last).
  const auto touching = [&](double lo, double hi) {
    auto first = open.upper_bound(lo);
    if (first != open.begin() && std::prev(first)->second.yhi >= lo) --first;
    auto last = first;
    while (last != open.end() && last->first <= hi) ++last;
    return std::make_pair(first, last);
  };

  std::size_t e = 0;
  while (e < events.size() && events[e].x == floor.xmin)
    coverage.add(events[e].lo, events[e].hi, events[e].sign), ++e;
  coverage.uncovered(0, static_cast<int>(ys.size()) - 2, runs);
  for (const auto& [a, b] : runs) open_cell(floor.xmin, ys[a], ys[b + 1]);

  while (e < events.size()) {
    const double x = events[e].x;
    ranges.clear();
    for (; e < events.size() && events[e].x == x; ++e) {
      coverage.add(events[e].lo, events[e].hi, events[e].sign);
      ranges.emplace_back(ys[events[e].lo], ys[events[e].hi + 1]);
    }
    std::sort(ranges.begin(), ranges.end());
    // Each changed y-range grown by the open cells it reaches; grown ranges that meet are one.
    hulls.clear();
    for (const auto& [a, b] : ranges) {
      double lo = a, hi = b;
      const auto [first, last] = touching(a, b);
      for (auto it = first; it != last; ++it)
        lo = std::min(lo, it->first), hi = std::max(hi, it->second.yhi);
      if (!hulls.empty() && lo <= hulls.back().second)
        hulls.back().second = std::max(hulls.back().second, hi);
      else
        hulls.emplace_back(lo, hi);
    }
    closed_now.clear();
    opened_now.clear();
    for (const auto& [lo, hi] : hulls) {
      runs.clear();
      coverage.uncovered(leaf(lo), leaf(hi) - 1, runs);
      auto [first, last] = touching(lo, hi);
      std::vector<std::pair<double, double>> fresh;
      for (const auto& [a, b] : runs) fresh.emplace_back(ys[a], ys[b + 1]);
      // Cells whose interval is unchanged live on; the others end here and new ones begin.
      std::size_t k = 0;
      for (auto it = first; it != last;) {
        while (k < fresh.size() && fresh[k].first < it->first) ++k;
        if (k < fresh.size() && fresh[k].first == it->first && fresh[k].second == it->second.yhi) {
          fresh[k].first = std::numeric_limits<double>::quiet_NaN();  // taken
          ++it;
          continue;
        }
        cells_[it->second.id].xhi = x;
        closed_now.push_back(it->second.id);
        it = open.erase(it);
      }
      for (const auto& [a, b] : fresh)
        if (!std::isnan(a)) opened_now.push_back(open_cell(x, a, b));
    }
    // Portals: every closing cell against every opening one that shares a stretch of x.
    std::sort(opened_now.begin(), opened_now.end(),
              [&](std::int32_t a, std::int32_t b) { return cells_[a].ylo < cells_[b].ylo; });
    std::size_t j = 0;
    for (std::int32_t l : closed_now) {
      const MeshCell& L = cells_[l];
      while (j < opened_now.size() && cells_[opened_now[j]].yhi <= L.ylo) ++j;
      for (std::size_t k = j; k < opened_now.size() && cells_[opened_now[k]].ylo < L.yhi; ++k) {
        const MeshCell& R = cells_[opened_now[k]];
        const double y0 = std::max(L.ylo, R.ylo), y1 = std::min(L.yhi, R.yhi);
        if (y1 > y0)
          portals_.push_back({x, y0, y1, l, opened_now[k], L.ylo != R.ylo, L.yhi != R.yhi});
      }
    }
  }
  for (auto& [ylo, c] : open) cells_[c.id].xhi = floor.xmax;
  index_portals();
  index_cells();
}

void FreeSpaceMesh::index_portals() {
  const std::size_t n = cells_.size();
  left_start_.assign(n + 1, 0);
  right_start_.assign(n + 1, 0);
  for (const MeshPortal& p : portals_) ++left_start_[p.right + 1], ++right_start_[p.left + 1];
  for (std::size_t c = 0; c < n; ++c)
    left_start_[c + 1] += left_start_[c], right_start_[c + 1] += right_start_[c];
  left_index_.resize(portals_.size());
  right_index_.resize(portals_.size());
  std::vector<std::int32_t> lfill(left_start_.begin(), left_start_.end() - 1),
      rfill(right_start_.begin(), right_start_.end() - 1);
  // Portals were made in x order and, at one x, in y order: each side's list comes out by y.
  for (std::size_t i = 0; i < portals_.size(); ++i) {
    left_index_[lfill[portals_[i].right]++] = static_cast<std::int32_t>(i);
    right_index_[rfill[portals_[i].left]++] = static_cast<std::int32_t>(i);
  }
}

void FreeSpaceMesh::index_cells() {
  std::vector<BoxBuckets::Box> boxes;
  boxes.reserve(cells_.size());
  for (const MeshCell& c : cells_) boxes.push_back({c.xlo, c.ylo, c.xhi, c.yhi});
  buckets_ = BoxBuckets(boxes, eps_);
}

bool FreeSpaceMesh::cell_holds(std::int32_t cell, Vec2 p) const {
  const MeshCell& c = cells_[cell];
  return p.x >= c.xlo - eps_ && p.x <= c.xhi + eps_ && p.y >= c.ylo - eps_ && p.y <= c.yhi + eps_;
}

bool FreeSpaceMesh::is_pinch(Vec2 p) const {
  // Which quadrants round p the cells holding it reach into: bit 0 lower left, 1 lower right,
  // 2 upper left, 3 upper right.
  unsigned quadrants = 0;
  for (const std::int32_t i : cells_at(p)) {
    const MeshCell& c = cells_[i];
    const bool left = c.xlo<p.x - eps_, right = c.xhi> p.x + eps_,
               below = c.ylo<p.y - eps_, above = c.yhi> p.y + eps_;
    quadrants |= (left && below ? 1u : 0u) | (right && below ? 2u : 0u) |
                 (left && above ? 4u : 0u) | (right && above ? 8u : 0u);
  }
  return quadrants == (1u | 8u) || quadrants == (2u | 4u);
}

std::vector<std::int32_t> FreeSpaceMesh::cells_at(Vec2 p) const {
  std::vector<std::int32_t> out;
  for (const std::int32_t c : buckets_.near(p))
    if (cell_holds(c, p)) out.push_back(c);
  return out;
}

}  // namespace plantsim::planner
