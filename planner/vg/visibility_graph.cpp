// Convex-corner extraction and the ring-by-ring search for visible, tangent vertices.
#include "planner/vg/visibility_graph.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <tuple>

#include "geometry/predicates.h"

namespace plantsim::planner {
namespace {

int sign(double v) { return (v > 0) - (v < 0); }

}  // namespace

VisibilityGraph::VisibilityGraph(const ObstacleMap& map) : map_(map) {
  const auto& rects = map.rects();
  for (std::size_t i = 0; i < map.obstacle_count(); ++i) {
    const Rect& r = rects[i];
    // Each corner with the diagonal pointing away from its rectangle.
    const struct {
      Vec2 c;
      int sx, sy;
    } corners[4] = {{{r.xmin, r.ymin}, -1, -1},
                    {{r.xmax, r.ymin}, 1, -1},
                    {{r.xmax, r.ymax}, 1, 1},
                    {{r.xmin, r.ymax}, -1, 1}};
    for (const auto& k : corners) {
      if (!geom::in_closed_rect(map.free_floor(), k.c)) continue;
      const auto self = static_cast<std::int32_t>(i);
      if (map.quadrant_occupied(k.c, k.sx, k.sy, self) ||
          map.quadrant_occupied(k.c, -k.sx, k.sy, self) ||
          map.quadrant_occupied(k.c, k.sx, -k.sy, self))
        continue;
      vertices_.push_back(
          {k.c, r.center(), static_cast<std::int8_t>(k.sx), static_cast<std::int8_t>(k.sy)});
    }
  }
  // Nested rectangles sharing a corner give the same vertex twice.
  auto key = [](const GraphVertex& v) { return std::make_tuple(v.p.x, v.p.y, v.sx, v.sy); };
  std::sort(vertices_.begin(), vertices_.end(),
            [&](const GraphVertex& a, const GraphVertex& b) { return key(a) < key(b); });
  vertices_.erase(
      std::unique(vertices_.begin(), vertices_.end(),
                  [&](const GraphVertex& a, const GraphVertex& b) { return key(a) == key(b); }),
      vertices_.end());
  vertices_in_cell_.resize(static_cast<std::size_t>(map.grid_width()) * map.grid_height());
  for (std::size_t i = 0; i < vertices_.size(); ++i)
    vertices_in_cell_[static_cast<std::size_t>(map.cell_y(vertices_[i].p.y)) * map.grid_width() +
                      map.cell_x(vertices_[i].p.x)]
        .push_back(static_cast<std::int32_t>(i));
  candidates_.resize(vertices_.size());
  verdict_.resize(vertices_.size());
  candidates_ready_.assign(vertices_.size(), 0);
  scan_box_.resize(vertices_.size());
  rect_seen_.assign(map.rects().size(), 0);
}

VisibilityGraph::VisibilityGraph(const ObstacleMap& map, const VisibilityGraph& base,
                                 const std::vector<Rect>& changed)
    : VisibilityGraph(map) {
  // A vertex's candidates and verdicts came from the rectangles inside the square its scan
  // covered, and its segments to them lie in that square: where no changed rectangle reaches
  // into it (a cell's margin added, for corners on its edge), the new map gives the same.
  auto key = [](const GraphVertex& v) { return std::make_tuple(v.p.x, v.p.y, v.sx, v.sy); };
  auto before = [&](const GraphVertex& a, const GraphVertex& b) { return key(a) < key(b); };
  const auto& old_vertices = base.vertices_;
  std::vector<std::int32_t> old_to_new(old_vertices.size(), -1);
  for (std::size_t i = 0, j = 0; i < old_vertices.size() && j < vertices_.size();) {
    if (before(old_vertices[i], vertices_[j]))
      ++i;
    else if (before(vertices_[j], old_vertices[i]))
      ++j;
    else
      old_to_new[i++] = static_cast<std::int32_t>(j++);
  }
  const double margin = std::max(map.cell_size(), base.map_.cell_size());
  for (std::size_t i = 0; i < old_vertices.size(); ++i) {
    const std::int32_t v = old_to_new[i];
    if (v < 0 || !base.candidates_ready_[i]) continue;
    const Rect box = base.scan_box_[i].inflated(margin);
    const bool touched = std::any_of(changed.begin(), changed.end(), [&](const Rect& r) {
      return r.xmin <= box.xmax && box.xmin <= r.xmax && r.ymin <= box.ymax && box.ymin <= r.ymax;
    });
    if (touched) continue;
    std::vector<GraphEdge> kept;
    std::vector<std::int8_t> verdicts;
    bool complete = true;
    for (std::size_t c = 0; c < base.candidates_[i].size(); ++c) {
      const std::int32_t to = old_to_new[static_cast<std::size_t>(base.candidates_[i][c].to)];
      if (to < 0) {  // a vertex gone: it lay on a changed rectangle, so this one was touched
        complete = false;
        break;
      }
      kept.push_back({to, base.candidates_[i][c].length});
      verdicts.push_back(base.verdict_[i][c]);
    }
    if (!complete) continue;
    const auto n = static_cast<std::size_t>(v);
    candidates_[n] = std::move(kept);
    verdict_[n] = std::move(verdicts);
    candidates_ready_[n] = base.candidates_ready_[i];
    candidate_bytes_ += bytes_of(n);
    scan_box_[n] = base.scan_box_[i];
    ++reused_;
  }
}

bool VisibilityGraph::tangent(const GraphVertex& v, Vec2 d) {
  return sign(d.x) * sign(d.y) != v.turn_sign();
}

const std::vector<GraphEdge>& VisibilityGraph::candidates(std::int32_t v) const {
  if (!candidates_ready_[v]) {
    scan(vertices_[v].p, &vertices_[v], v, candidates_[v]);
    verdict_[v].assign(candidates_[v].size(), -1);
    candidates_gathered_ += static_cast<std::int64_t>(candidates_[v].size());
    candidate_bytes_ += bytes_of(static_cast<std::size_t>(v));
    candidates_ready_[v] = 1;
  }
  return candidates_[v];
}

bool VisibilityGraph::candidate_visible(std::int32_t v, std::size_t i) const {
  std::int8_t& verdict = verdict_[v][i];
  if (verdict < 0) {
    verdict = visible(vertices_[v].p, vertices_[candidates_[v][i].to].p) ? 1 : 0;
    edges_found_ += verdict;
  }
  return verdict == 1;
}

void VisibilityGraph::resolve(std::int32_t v) const {
  candidates(v);
  candidate_bytes_ -= bytes_of(static_cast<std::size_t>(v));
  std::vector<GraphEdge> kept;
  for (std::size_t i = 0; i < candidates_[v].size(); ++i)
    if (candidate_visible(v, i)) kept.push_back(candidates_[v][i]);
  candidates_[v] = std::move(kept);
  verdict_[v].assign(candidates_[v].size(), 1);
  candidate_bytes_ += bytes_of(static_cast<std::size_t>(v));
  candidates_ready_[v] = 2;
}

std::vector<std::pair<std::int32_t, std::int32_t>> VisibilityGraph::visible_edges() const {
  std::vector<std::pair<std::int32_t, std::int32_t>> out;
  for (std::size_t v = 0; v < candidates_.size(); ++v)
    for (std::size_t i = 0; i < verdict_[v].size(); ++i)
      if (verdict_[v][i] == 1) {
        const auto a = static_cast<std::int32_t>(v), b = candidates_[v][i].to;
        out.emplace_back(std::min(a, b), std::max(a, b));
      }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

bool VisibilityGraph::taut(Vec2 prev, std::int32_t v, Vec2 next) const {
  const GraphVertex& c = vertices_[v];
  const geom::Orientation turn = geom::orient(prev, c.p, next);
  // The incoming edge is tangent at c, so the whole rectangle lies on one side of its line.
  return turn == geom::Orientation::kCollinear || turn == geom::orient(prev, c.p, c.inside);
}

void VisibilityGraph::candidates_from_point(Vec2 p, std::vector<GraphEdge>& out) const {
  scan(p, nullptr, -1, out);
}

void VisibilityGraph::add_span(AngleCoverage& coverage, Vec2 u, const Rect& r) const {
  if (!(r.xmin < r.xmax && r.ymin < r.ymax)) return;
  // The two corners that bound the rectangle's view from u, clockwise one first, chosen by
  // which of the eight regions around the rectangle u lies in.
  Vec2 cw, ccw;
  if (u.x < r.xmin) {
    if (u.y < r.ymin)
      cw = {r.xmax, r.ymin}, ccw = {r.xmin, r.ymax};
    else if (u.y > r.ymax)
      cw = {r.xmin, r.ymin}, ccw = {r.xmax, r.ymax};
    else
      cw = {r.xmin, r.ymin}, ccw = {r.xmin, r.ymax};
  } else if (u.x > r.xmax) {
    if (u.y < r.ymin)
      cw = {r.xmax, r.ymax}, ccw = {r.xmin, r.ymin};
    else if (u.y > r.ymax)
      cw = {r.xmin, r.ymax}, ccw = {r.xmax, r.ymin};
    else
      cw = {r.xmax, r.ymax}, ccw = {r.xmax, r.ymin};
  } else if (u.y < r.ymin) {
    cw = {r.xmax, r.ymin}, ccw = {r.xmin, r.ymin};
  } else if (u.y > r.ymax) {
    cw = {r.xmin, r.ymax}, ccw = {r.xmax, r.ymax};
  } else {
    return;  // u on or in the rectangle: it blocks no ray for certain
  }
  const double lo = pseudo_angle(cw - u), hi = pseudo_angle(ccw - u);
  coverage.add(lo, hi);
  const double far_x = std::max(std::abs(u.x - r.xmin), std::abs(u.x - r.xmax));
  const double far_y = std::max(std::abs(u.y - r.ymin), std::abs(u.y - r.ymax));
  spans_.push_back({std::sqrt(far_x * far_x + far_y * far_y), lo, hi});
}

void VisibilityGraph::drop_hidden(Vec2 u, std::vector<GraphEdge>& out, std::size_t first) const {
  // A ray strictly inside a rectangle's span enters its interior before the rectangle's
  // farthest corner, so a vertex farther than that in such a direction is hidden. Rectangles
  // and candidates are bucketed into shells a cell wide by distance (no sort); candidates of a
  // shell are tested against the rectangles of all nearer shells.
  const double shell = map_.cell_size();
  auto shell_of = [&](double d) { return static_cast<std::size_t>(d / shell); };
  auto span_shell = [&](const Span& sp) { return shell_of(sp.depth * (1 + kDepthSlack)); };
  // Counting sort: nearer_than_[k] = how many spans lie in shells before k.
  std::size_t shells = 1;
  for (const Span& sp : spans_) shells = std::max(shells, span_shell(sp) + 1);
  nearer_than_.assign(shells + 1, 0);
  for (const Span& sp : spans_) ++nearer_than_[span_shell(sp) + 1];
  for (std::size_t k = 1; k <= shells; ++k) nearer_than_[k] += nearer_than_[k - 1];
  fill_at_.assign(nearer_than_.begin(), nearer_than_.end() - 1);
  by_shell_.resize(spans_.size());
  for (const Span& sp : spans_) by_shell_[fill_at_[span_shell(sp)]++] = sp;
  // Candidates by shell too (a shell past the last span's is treated as that one).
  cand_at_.assign(shells + 2, 0);
  for (std::size_t i = first; i < out.size(); ++i)
    ++cand_at_[std::min(shell_of(out[i].length), shells) + 1];
  for (std::size_t k = 1; k < cand_at_.size(); ++k) cand_at_[k] += cand_at_[k - 1];
  fill_at_.assign(cand_at_.begin(), cand_at_.end() - 1);
  cand_by_shell_.resize(out.size() - first);
  for (std::size_t i = first; i < out.size(); ++i)
    cand_by_shell_[fill_at_[std::min(shell_of(out[i].length), shells)]++] = out[i];
  AngleCoverage nearer;
  std::size_t next_span = 0, kept = first;
  for (std::size_t k = 0; k <= shells; ++k) {
    // Spans in shells before k end nearer than any candidate of shell k starts.
    for (; next_span < nearer_than_[k]; ++next_span)
      nearer.add(by_shell_[next_span].lo, by_shell_[next_span].hi);
    for (std::size_t i = cand_at_[k]; i < cand_at_[k + 1]; ++i)
      if (!nearer.covers(pseudo_angle(vertices_[cand_by_shell_[i].to].p - u)))
        out[kept++] = cand_by_shell_[i];
  }
  out.resize(kept);
}

namespace {

// World bounds of the (unclipped) square of cells within ring k around cell (cx, cy).
Rect ring_square(const ObstacleMap& m, int cx, int cy, int k) {
  return {m.cell_bounds(cx - k, 0).xmin, m.cell_bounds(0, cy - k).ymin,
          m.cell_bounds(cx + k, 0).xmax, m.cell_bounds(0, cy + k).ymax};
}

// The ring beyond which no vertex is visible from u once every ray is blocked within `square`:
// none farther than its farthest corner.
int last_visible_ring(Vec2 u, const Rect& square, double cell_size) {
  double reach = 0;
  for (Vec2 corner : {Vec2{square.xmin, square.ymin}, Vec2{square.xmax, square.ymin},
                      Vec2{square.xmax, square.ymax}, Vec2{square.xmin, square.ymax}})
    reach = std::max(reach, geom::distance(u, corner));
  return static_cast<int>(std::floor(reach / cell_size)) + 1;
}

}  // namespace

// Rectangles reaching past the square count with their part inside it; one the square has grown
// to hold whole counts once more and is done.
void VisibilityGraph::add_big_rect_spans(AngleCoverage& coverage, Vec2 u,
                                         const Rect& square) const {
  const auto& rects = map_.rects();
  std::size_t kept = 0;
  for (std::int32_t i : big_rects_) {
    const Rect& r = rects[i];
    add_span(coverage, u, geom::clipped(r, square));
    if (!geom::holds(square, r)) big_rects_[kept++] = i;
  }
  big_rects_.resize(kept);
}

void VisibilityGraph::scan(Vec2 u, const GraphVertex* self, std::int32_t self_index,
                           std::vector<GraphEdge>& out) const {
  const ObstacleMap& m = map_;
  const auto& rects = m.rects();
  if (++scan_stamp_ == 0) {
    std::fill(rect_seen_.begin(), rect_seen_.end(), 0);
    scan_stamp_ = 1;
  }
  AngleCoverage coverage;
  if (self) {                                  // the corner's own rectangle fills one open quadrant
    const int qx = -self->sx, qy = -self->sy;  // quadrant of the rectangle
    const double lo = qy > 0 ? (qx > 0 ? 0.0 : 1.0) : (qx < 0 ? 2.0 : 3.0);
    coverage.add(lo, lo + 1.0);
  }
  big_rects_.clear();
  spans_.clear();
  const std::size_t first = out.size();
  const int cx0 = m.cell_x(u.x), cy0 = m.cell_y(u.y);
  const int last_ring = std::max({cx0, cy0, m.grid_width() - 1 - cx0, m.grid_height() - 1 - cy0});
  int stop_ring = INT_MAX;

  auto visit_cell = [&](int cx, int cy, const Rect& box) {
    for (std::int32_t w : vertices_in_cell_[static_cast<std::size_t>(cy) * m.grid_width() + cx]) {
      if (w == self_index) continue;
      const GraphVertex& b = vertices_[w];
      const Vec2 d = b.p - u;
      if ((self && !tangent(*self, d)) || !tangent(b, d)) continue;
      out.push_back({w, geom::distance(u, b.p)});
    }
    if (stop_ring != INT_MAX) return;
    for (std::int32_t i : m.rects_in_cell(cx, cy)) {
      if (rect_seen_[i] == scan_stamp_) continue;
      rect_seen_[i] = scan_stamp_;
      const Rect& r = rects[i];
      if (geom::holds(box, r))
        add_span(coverage, u, r);
      else
        big_rects_.push_back(i);
    }
  };

  int k_last = 0;
  for (int k = 0; k <= last_ring && k <= stop_ring; ++k) {
    k_last = k;
    const Rect box = ring_square(m, cx0, cy0, k);
    for (int cy = cy0 - k; cy <= cy0 + k; ++cy) {
      if (cy < 0 || cy >= m.grid_height()) continue;
      const bool edge_row = cy == cy0 - k || cy == cy0 + k;
      for (int cx = cx0 - k; cx <= cx0 + k; cx += (edge_row || k == 0) ? 1 : 2 * k) {
        if (cx >= 0 && cx < m.grid_width()) visit_cell(cx, cy, box);
      }
    }
    if (stop_ring != INT_MAX) continue;
    add_big_rect_spans(coverage, u, box);
    // Every ray blocked within the square: finish the rings that can still hold nearer vertices.
    if (coverage.full()) stop_ring = last_visible_ring(u, box, m.cell_size());
  }
  drop_hidden(u, out, first);
  if (self_index >= 0)
    scan_box_[static_cast<std::size_t>(self_index)] = ring_square(m, cx0, cy0, k_last);
}

}  // namespace plantsim::planner
