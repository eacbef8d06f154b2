// Vertical decomposition of the free floor by an x-sweep over the obstacle rectangles, with a
// coverage tree over the rectangles' y coordinates that lists the uncovered intervals.
#include "planner/mesh/free_space_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

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

// The floor swept left to right: the elementary y-intervals between the rectangles' edges, how
// many rectangles cover each, and the open cells by their lower y. Closing and opening cells
// where the coverage changes, it appends cells and the portals between them.
class Sweep {
 public:
  Sweep(std::vector<double> ys, std::vector<MeshCell>& cells, std::vector<MeshPortal>& portals)
      : ys_(std::move(ys)), coverage_(ys_.size() - 1), cells_(cells), portals_(portals) {}

  int leaf(double y) const {
    return static_cast<int>(std::lower_bound(ys_.begin(), ys_.end(), y) - ys_.begin());
  }
  double y(int leaf) const { return ys_[static_cast<std::size_t>(leaf)]; }
  void cover(const Event& e) { coverage_.add(e.lo, e.hi, e.sign); }

  // The cells at the floor's left edge: every stretch the rectangles there leave free.
  void open_first_cells(double x) {
    runs_.clear();
    coverage_.uncovered(0, static_cast<int>(ys_.size()) - 2, runs_);
    for (const auto& [a, b] : runs_) open_cell(x, ys_[a], ys_[b + 1]);
  }

  // After the events at x (ranges: the y-ranges they changed): cells whose interval changed end
  // here, new ones begin, and portals join them.
  void renew_at(double x, std::vector<std::pair<double, double>>& ranges) {
    closed_now_.clear();
    opened_now_.clear();
    for (const auto& [lo, hi] : changed_hulls(ranges)) renew_within(x, lo, hi);
    add_portals(x);
  }

  // Every cell still open ends at the floor's right edge.
  void close_all(double x) {
    for (auto& [ylo, c] : open_) cells_[c.id].xhi = x;
  }

 private:
  std::int32_t open_cell(double x, double ylo, double yhi) {
    const auto id = static_cast<std::int32_t>(cells_.size());
    cells_.push_back({x, std::numeric_limits<double>::quiet_NaN(), ylo, yhi});
    open_[ylo] = {yhi, id};
    return id;
  }

  // The open cells whose intervals overlap or touch [lo, hi], as map iterators [first, last).
  auto touching(double lo, double hi) {
    auto first = open_.upper_bound(lo);
    if (first != open_.begin() && std::prev(first)->second.yhi >= lo) --first;
    auto last = first;
    while (last != open_.end() && last->first <= hi) ++last;
    return std::make_pair(first, last);
  }

  // Each changed y-range grown by the open cells it reaches; grown ranges that meet are one.
  const std::vector<std::pair<double, double>>& changed_hulls(
      std::vector<std::pair<double, double>>& ranges) {
    std::sort(ranges.begin(), ranges.end());
    hulls_.clear();
    for (const auto& [a, b] : ranges) {
      double lo = a, hi = b;
      const auto [first, last] = touching(a, b);
      for (auto it = first; it != last; ++it)
        lo = std::min(lo, it->first), hi = std::max(hi, it->second.yhi);
      if (!hulls_.empty() && lo <= hulls_.back().second)
        hulls_.back().second = std::max(hulls_.back().second, hi);
      else
        hulls_.emplace_back(lo, hi);
    }
    return hulls_;
  }

  // Cells within [lo, hi] whose interval is unchanged live on; the others end at x and the free
  // stretches there that no live cell holds begin new ones.
  void renew_within(double x, double lo, double hi) {
    runs_.clear();
    coverage_.uncovered(leaf(lo), leaf(hi) - 1, runs_);
    auto [first, last] = touching(lo, hi);
    std::vector<std::pair<double, double>> fresh;
    for (const auto& [a, b] : runs_) fresh.emplace_back(ys_[a], ys_[b + 1]);
    std::size_t k = 0;
    for (auto it = first; it != last;) {
      while (k < fresh.size() && fresh[k].first < it->first) ++k;
      if (k < fresh.size() && fresh[k].first == it->first && fresh[k].second == it->second.yhi) {
        fresh[k].first = std::numeric_limits<double>::quiet_NaN();  // taken
        ++it;
        continue;
      }
      cells_[it->second.id].xhi = x;
      closed_now_.push_back(it->second.id);
      it = open_.erase(it);
    }
    for (const auto& [a, b] : fresh)
      if (!std::isnan(a)) opened_now_.push_back(open_cell(x, a, b));
  }

  // Portals: every closing cell against every opening one that shares a stretch of y.
  void add_portals(double x) {
    std::sort(opened_now_.begin(), opened_now_.end(),
              [&](std::int32_t a, std::int32_t b) { return cells_[a].ylo < cells_[b].ylo; });
    std::size_t j = 0;
    for (std::int32_t l : closed_now_) {
      const MeshCell& L = cells_[l];
      while (j < opened_now_.size() && cells_[opened_now_[j]].yhi <= L.ylo) ++j;
      for (std::size_t k = j; k < opened_now_.size() && cells_[opened_now_[k]].ylo < L.yhi; ++k) {
        const MeshCell& R = cells_[opened_now_[k]];
        const double y0 = std::max(L.ylo, R.ylo), y1 = std::min(L.yhi, R.yhi);
        if (y1 > y0)
          portals_.push_back({x, y0, y1, l, opened_now_[k], L.ylo != R.ylo, L.yhi != R.yhi});
      }
    }
  }

  std::vector<double> ys_;
  Coverage coverage_;
  std::map<double, OpenCell> open_;  // by ylo
  std::vector<MeshCell>& cells_;
  std::vector<MeshPortal>& portals_;
  std::vector<std::pair<int, int>> runs_;
  std::vector<std::pair<double, double>> hulls_;
  std::vector<std::int32_t> closed_now_, opened_now_;
};

// The rectangles' parts on the floor, and every y where one begins or ends (sorted, unique).
std::pair<std::vector<Rect>, std::vector<double>> blocked_parts(const std::vector<Rect>& rects,
                                                                const Rect& floor) {
  std::vector<Rect> blocked;
  std::vector<double> ys{floor.ymin, floor.ymax};
  for (const Rect& r : rects) {
    const Rect c = geom::clipped(r, floor);
    if (c.xmax > c.xmin && c.ymax > c.ymin) {
      blocked.push_back(c);
      ys.push_back(c.ymin);
      ys.push_back(c.ymax);
    }
  }
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  return {std::move(blocked), std::move(ys)};
}

}  // namespace

FreeSpaceMesh::FreeSpaceMesh(const std::vector<Rect>& rects, const Rect& floor) {
  eps_ = 1e-13 * std::max({1.0, std::fabs(floor.xmin), std::fabs(floor.xmax), std::fabs(floor.ymin),
                           std::fabs(floor.ymax)});
  if (!(floor.xmax > floor.xmin && floor.ymax > floor.ymin)) return;  // no free floor: no cells
  auto [blocked, ys] = blocked_parts(rects, floor);
  Sweep sweep(std::move(ys), cells_, portals_);
  std::vector<Event> events;
  events.reserve(2 * blocked.size());
  for (const Rect& r : blocked) {
    const int lo = sweep.leaf(r.ymin), hi = sweep.leaf(r.ymax) - 1;
    events.push_back({r.xmin, +1, lo, hi});
    if (r.xmax < floor.xmax) events.push_back({r.xmax, -1, lo, hi});
  }
  std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) { return a.x < b.x; });

  std::size_t e = 0;
  while (e < events.size() && events[e].x == floor.xmin) sweep.cover(events[e++]);
  sweep.open_first_cells(floor.xmin);
  std::vector<std::pair<double, double>> ranges;
  while (e < events.size()) {
    const double x = events[e].x;
    ranges.clear();
    for (; e < events.size() && events[e].x == x; ++e) {
      sweep.cover(events[e]);
      ranges.emplace_back(sweep.y(events[e].lo), sweep.y(events[e].hi + 1));
    }
    sweep.renew_at(x, ranges);
  }
  sweep.close_all(floor.xmax);
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
