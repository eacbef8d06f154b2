// The convex mesh: walls from the rectangle mesh, CGAL's constrained Delaunay triangulation of
// them, the free triangles kept, then merged across their shared edges, the pair whose union
// is largest first, as long as the union stays convex and has at most kMaxCorners corners (the
// "M-CDT" of Polyanya's authors, with a bound on a polygon's size theirs does not have).
#include "planner/mesh/convex_mesh.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <queue>

namespace plantsim::planner {

// A polygon while merging: its corners counter-clockwise and, per edge, the triangle that was
// beyond it (-1 for a wall), resolved to the polygon holding that triangle now.
struct ConvexMesh::Piece {
  std::vector<std::int32_t> corner, beyond;
  double area = 0;
  bool alive = true;
};

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<std::int32_t, Kernel>;
using FaceBase = CGAL::Constrained_triangulation_face_base_2<
    Kernel, CGAL::Triangulation_face_base_with_info_2<std::int32_t, Kernel>>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;

// Exact orientation of three mesh points (CGAL's filtered predicate): > 0 counter-clockwise.
int orientation(Vec2 a, Vec2 b, Vec2 c) {
  return static_cast<int>(CGAL::orientation(Kernel::Point_2(a.x, a.y), Kernel::Point_2(b.x, b.y),
                                            Kernel::Point_2(c.x, c.y)));
}

// The walls: every cell's bottom and top, and the parts of its sides no portal covers.
std::vector<std::pair<Vec2, Vec2>> walls_of(const FreeSpaceMesh& m) {
  std::vector<std::pair<Vec2, Vec2>> out;
  const auto side = [&](double x, double ylo, double yhi, FreeSpaceMesh::Span portals) {
    double y = ylo;
    for (const std::int32_t q : portals) {
      const MeshPortal& p = m.portals()[q];
      if (p.y0 > y) out.push_back({{x, y}, {x, p.y0}});
      y = std::max(y, p.y1);
    }
    if (yhi > y) out.push_back({{x, y}, {x, yhi}});
  };
  for (std::size_t i = 0; i < m.cells().size(); ++i) {
    const MeshCell& c = m.cells()[i];
    out.push_back({{c.xlo, c.ylo}, {c.xhi, c.ylo}});
    out.push_back({{c.xlo, c.yhi}, {c.xhi, c.yhi}});
    side(c.xlo, c.ylo, c.yhi, m.left_portals(static_cast<std::int32_t>(i)));
    side(c.xhi, c.ylo, c.yhi, m.right_portals(static_cast<std::int32_t>(i)));
  }
  return out;
}

using Piece = ConvexMesh::Piece;

class Merger {
 public:
  Merger(std::vector<Piece> pieces, const std::vector<Vec2>& points)
      : piece_(std::move(pieces)), points_(points) {
    owner_.resize(piece_.size());
    std::iota(owner_.begin(), owner_.end(), 0);
  }
  std::int32_t owner(std::int32_t t) {
    while (owner_[t] != t) t = owner_[t] = owner_[owner_[t]];
    return t;
  }
  void run() {
    struct Candidate {
      double area;
      std::int32_t a, b;
      bool operator<(const Candidate& o) const { return area < o.area; }
    };
    std::priority_queue<Candidate> queue;
    const auto offer = [&](std::int32_t a) {
      for (const std::int32_t t : piece_[a].beyond)
        if (t >= 0) {
          const std::int32_t b = owner(t);
          if (b != a) queue.push({piece_[a].area + piece_[b].area, a, b});
        }
    };
    for (std::int32_t a = 0; a < static_cast<std::int32_t>(piece_.size()); ++a) offer(a);
    while (!queue.empty()) {
      const Candidate c = queue.top();
      queue.pop();
      if (!piece_[c.a].alive || !piece_[c.b].alive || piece_[c.a].area + piece_[c.b].area != c.area)
        continue;
      if (merge(c.a, c.b)) offer(c.a);
    }
  }
  std::vector<Piece>& pieces() { return piece_; }

 private:
  // Joins b into a across their shared edge when the union is convex.
  bool merge(std::int32_t a, std::int32_t b) {
    Piece &P = piece_[a], &Q = piece_[b];
    const int n = static_cast<int>(P.corner.size()), m = static_cast<int>(Q.corner.size());
    int i = -1, shared = 0;
    for (int k = 0; k < n; ++k)
      if (P.beyond[k] >= 0 && owner(P.beyond[k]) == b) i = k, ++shared;
    if (shared != 1) return false;  // none, or a boundary of several edges in a row: left apart
    if (n + m - 2 > ConvexMesh::kMaxCorners) return false;
    const std::int32_t u = P.corner[i], v = P.corner[(i + 1) % n];
    int j = -1;
    for (int k = 0; k < m; ++k)
      if (Q.corner[k] == v && Q.corner[(k + 1) % m] == u) j = k;
    if (j < 0) return false;
    const Vec2 before_u = points_[P.corner[(i + n - 1) % n]],
               after_u = points_[Q.corner[(j + 2) % m]];
    const Vec2 before_v = points_[Q.corner[(j + m - 1) % m]],
               after_v = points_[P.corner[(i + 2) % n]];
    if (orientation(before_u, points_[u], after_u) < 0 ||
        orientation(before_v, points_[v], after_v) < 0)
      return false;
    Piece joined;
    // P from v round to u, then Q from u round to v (its corners strictly between).
    for (int k = 0; k < n - 1; ++k) {
      joined.corner.push_back(P.corner[(i + 1 + k) % n]);
      joined.beyond.push_back(P.beyond[(i + 1 + k) % n]);
    }
    for (int k = 0; k < m - 1; ++k) {
      joined.corner.push_back(Q.corner[(j + 1 + k) % m]);
      joined.beyond.push_back(Q.beyond[(j + 1 + k) % m]);
    }
    joined.area = P.area + Q.area;
    P = std::move(joined);
    Q.alive = false;
    Q.corner.clear(), Q.beyond.clear();
    owner_[b] = a;
    return true;
  }

  std::vector<Piece> piece_;
  const std::vector<Vec2>& points_;
  std::vector<std::int32_t> owner_;
};

// The free triangles of a constrained Delaunay triangulation of the walls, as pieces to merge;
// fills `points` with the triangulation's vertices.
std::vector<Piece> free_triangles(const FreeSpaceMesh& rectangles, std::vector<Vec2>& points) {
  // Every cell corner once (portal ends are cell corners too), sorted, so that a wall's ends
  // are found by binary search.
  std::vector<Vec2> sites;
  sites.reserve(4 * rectangles.cells().size());
  for (const MeshCell& c : rectangles.cells())
    for (const Vec2 p :
         {Vec2{c.xlo, c.ylo}, Vec2{c.xhi, c.ylo}, Vec2{c.xlo, c.yhi}, Vec2{c.xhi, c.yhi}})
      sites.push_back(p);
  const auto before = [](Vec2 a, Vec2 b) { return a.x != b.x ? a.x < b.x : a.y < b.y; };
  std::sort(sites.begin(), sites.end(), before);
  sites.erase(std::unique(sites.begin(), sites.end()), sites.end());
  const auto site = [&](Vec2 p) {
    return static_cast<std::size_t>(std::lower_bound(sites.begin(), sites.end(), p, before) -
                                    sites.begin());
  };
  std::vector<std::pair<std::size_t, std::size_t>> walls;
  for (const auto& [a, b] : walls_of(rectangles)) walls.emplace_back(site(a), site(b));
  std::vector<Kernel::Point_2> cgal_sites;
  cgal_sites.reserve(sites.size());
  for (const Vec2 p : sites) cgal_sites.emplace_back(p.x, p.y);
  // Points and walls handed over at once: CGAL sorts the points along a space-filling curve
  // before inserting them, far faster than one at a time.
  Cdt cdt;
  cdt.insert_constraints(cgal_sites.begin(), cgal_sites.end(), walls.begin(), walls.end());

  // A triangle is free when its centroid is on the free floor (no wall crosses a triangle, so
  // it lies wholly on one side).
  std::int32_t next_vertex = 0;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    v->info() = next_vertex++;
    points.push_back({v->point().x(), v->point().y()});
  }
  std::vector<Cdt::Face_handle> faces;
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    const Vec2 a = points[f->vertex(0)->info()], b = points[f->vertex(1)->info()],
               c = points[f->vertex(2)->info()];
    if (rectangles.cells_at({(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3}).empty()) continue;
    f->info() = static_cast<std::int32_t>(faces.size());
    faces.push_back(f);
  }
  std::vector<Piece> pieces(faces.size());
  for (std::size_t t = 0; t < faces.size(); ++t) {
    const Cdt::Face_handle f = faces[t];
    Piece& p = pieces[t];
    for (int k = 0; k < 3; ++k) {
      p.corner.push_back(f->vertex(k)->info());
      // Edge k runs from corner k to corner k + 1: opposite CGAL's vertex k + 2.
      const int opposite = (k + 2) % 3;
      const std::int32_t beyond = f->neighbor(opposite)->info();
      p.beyond.push_back(beyond >= 0 && !f->is_constrained(opposite) ? beyond : -1);
    }
    const Vec2 a = points[p.corner[0]], b = points[p.corner[1]], c = points[p.corner[2]];
    p.area = 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  }
  return pieces;
}

// Interleaved bits of a point's place in the box (a Z-order key): polygons near each other on
// the floor are near each other in memory, which is what a search's cache wants.
std::uint64_t z_order(Vec2 p, Vec2 lo, Vec2 size) {
  const auto grid = [](double u) {
    return static_cast<std::uint64_t>(std::clamp(u, 0.0, 1.0) * 65535.0);
  };
  const std::uint64_t x = grid((p.x - lo.x) / size.x), y = grid((p.y - lo.y) / size.y);
  std::uint64_t key = 0;
  for (int bit = 0; bit < 16; ++bit)
    key |= ((x >> bit) & 1) << (2 * bit) | ((y >> bit) & 1) << (2 * bit + 1);
  return key;
}

}  // namespace

ConvexMesh::ConvexMesh(const FreeSpaceMesh& rectangles) : eps_(rectangles.tolerance()) {
  first_ = {0};
  if (rectangles.cells().empty()) return;
  Merger merger(free_triangles(rectangles, points_), points_);
  merger.run();
  std::vector<std::int32_t> owner(merger.pieces().size());
  for (std::size_t t = 0; t < owner.size(); ++t)
    owner[t] = merger.owner(static_cast<std::int32_t>(t));
  lay_out(merger.pieces(), owner);
  mark_corners();
  index_polygons();
}

// The merged polygons numbered in Z-order of their first corner, their neighbours resolved,
// each edge's twin found.
void ConvexMesh::lay_out(const std::vector<Piece>& pieces, const std::vector<std::int32_t>& owner) {
  Vec2 lo = points_.front(), hi = points_.front();
  for (const Vec2 p : points_)
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)},
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  const Vec2 extent{std::max(hi.x - lo.x, 1e-300), std::max(hi.y - lo.y, 1e-300)};
  std::vector<std::pair<std::uint64_t, std::int32_t>> order;
  for (std::size_t t = 0; t < pieces.size(); ++t)
    if (pieces[t].alive)
      order.push_back(
          {z_order(points_[pieces[t].corner.front()], lo, extent), static_cast<std::int32_t>(t)});
  std::sort(order.begin(), order.end());
  std::vector<std::int32_t> number(pieces.size(), -1);
  for (std::size_t i = 0; i < order.size(); ++i) {
    number[order[i].second] = static_cast<std::int32_t>(i);
    first_.push_back(first_.back() +
                     static_cast<std::int32_t>(pieces[order[i].second].corner.size()));
  }
  for (const auto& [key, t] : order) {
    const Piece& p = pieces[t];
    corner_.insert(corner_.end(), p.corner.begin(), p.corner.end());
    for (const std::int32_t b : p.beyond) neighbour_.push_back(b >= 0 ? number[owner[b]] : -1);
  }
  corner_point_.reserve(corner_.size());
  for (const std::int32_t v : corner_) corner_point_.push_back(points_[v]);
  twin_.assign(corner_.size(), -1);
  for (std::int32_t p = 0; p < polygon_count(); ++p)
    for (std::int32_t k = 0; k < size(p); ++k) {
      const std::int32_t q = neighbour(p, k);
      if (q < 0) continue;
      if (p < q) ++portals_;
      for (std::int32_t j = 0; j < size(q); ++j)
        if (vertex(q, j) == vertex(p, k + 1) && vertex(q, j + 1) == vertex(p, k))
          twin_[first_[p] + k] = j;
    }
}

void ConvexMesh::mark_corners() {
  std::vector<std::uint8_t> wedges(points_.size(), 0);
  pinch_flag_.assign(points_.size(), 0);
  // A corner: some wedge between consecutive walls around the vertex, on the free side, is
  // wider than a half-turn. Each polygon adds its angle at the vertex to the wedge it lies in;
  // wedges are found by walking round the vertex from a wall through the polygons.
  corner_flag_.assign(points_.size(), 0);
  for (std::int32_t p = 0; p < polygon_count(); ++p)
    for (std::int32_t k = 0; k < size(p); ++k) {
      if (neighbour(p, k - 1) >= 0) continue;  // start only where a wall ends at the vertex
      const std::int32_t v = vertex(p, k);
      const Vec2 o = points_[v];
      double angle = 0;
      std::int32_t q = p, i = k;
      for (std::size_t steps = 0; steps <= corner_.size(); ++steps) {
        const Vec2 a = points_[vertex(q, i - 1)], b = points_[vertex(q, i + 1)];
        double turn = std::atan2((a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x),
                                 (a.x - o.x) * (b.x - o.x) + (a.y - o.y) * (b.y - o.y));
        if (turn < 0) turn += 2 * std::numbers::pi;
        angle += 2 * std::numbers::pi - turn;  // the polygon's interior angle at the vertex
        const std::int32_t next = neighbour(q, i);
        if (next < 0) break;
        i = twin(q, i) + 1;  // in `next`, the edge runs from corner twin + 1 (this vertex)
        q = next;
        if (q == p && i % size(q) == k) break;
      }
      if (angle > std::numbers::pi + 1e-9) corner_flag_[v] = 1;
      ++wedges[v];
    }
  for (std::size_t v = 0; v < points_.size(); ++v) pinch_flag_[v] = wedges[v] > 1;
}

void ConvexMesh::index_polygons() {
  std::vector<BoxBuckets::Box> boxes;
  boxes.reserve(polygon_count());
  for (std::int32_t p = 0; p < polygon_count(); ++p) {
    BoxBuckets::Box b{points_[vertex(p, 0)].x, points_[vertex(p, 0)].y, points_[vertex(p, 0)].x,
                      points_[vertex(p, 0)].y};
    for (std::int32_t k = 1; k < size(p); ++k) {
      const Vec2 q = points_[vertex(p, k)];
      b.xlo = std::min(b.xlo, q.x), b.ylo = std::min(b.ylo, q.y), b.xhi = std::max(b.xhi, q.x),
      b.yhi = std::max(b.yhi, q.y);
    }
    boxes.push_back(b);
  }
  buckets_ = BoxBuckets(boxes, eps_);
}

bool ConvexMesh::polygon_holds(std::int32_t polygon, Vec2 p) const {
  for (std::int32_t k = 0; k < size(polygon); ++k) {
    const Vec2 a = points_[vertex(polygon, k)], b = points_[vertex(polygon, k + 1)];
    const double len = std::sqrt((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y));
    if ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x) < -eps_ * len) return false;
  }
  return true;
}

std::vector<std::int32_t> ConvexMesh::polygons_at(Vec2 p) const {
  std::vector<std::int32_t> out;
  for (const std::int32_t q : buckets_.near(p))
    if (polygon_holds(q, p)) out.push_back(q);
  return out;
}

}  // namespace plantsim::planner
