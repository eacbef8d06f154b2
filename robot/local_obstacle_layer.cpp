// Marking, clearing and merging the layer's cells.
#include "robot/local_obstacle_layer.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_set>

namespace plantsim::robot {
namespace {

std::int32_t cell_of(double x, double cell_m) {
  return static_cast<std::int32_t>(std::floor(x / cell_m));
}

}  // namespace

LocalObstacleLayer::Key LocalObstacleLayer::key(geom::Vec2 p) const {
  const auto ix = static_cast<std::uint32_t>(cell_of(p.x, p_.cell_m));
  const auto iy = static_cast<std::uint32_t>(cell_of(p.y, p_.cell_m));
  return static_cast<Key>((static_cast<std::uint64_t>(ix) << 32) | iy);
}

geom::Vec2 LocalObstacleLayer::centre(Key k) const {
  const auto ix = static_cast<std::int32_t>(static_cast<std::uint64_t>(k) >> 32);
  const auto iy = static_cast<std::int32_t>(static_cast<std::uint64_t>(k) & 0xffffffffULL);
  return {(ix + 0.5) * p_.cell_m, (iy + 0.5) * p_.cell_m};
}

void LocalObstacleLayer::update(const LidarScan& scan, const geom::Pose2& sensor,
                                const std::vector<geom::Vec2>& marks) {
  if (!p_.enabled || scan.ranges.empty()) return;
  // Clearing first, so that this scan's own returns are not undone by it: a cell whose centre
  // the nearest beam passes by more than a cell's length is seen free.
  const int n = static_cast<int>(scan.ranges.size());
  for (auto it = evidence_.begin(); it != evidence_.end();) {
    const geom::Vec2 rel = geom::rotate(centre(it->first) - sensor.position(), -sensor.yaw);
    const double d = geom::norm(rel);
    bool seen_free = false;
    if (d >= scan.min_range_m && d <= p_.clear_range_m && scan.angle_increment_rad > 0) {
      const long beam =
          std::lround((std::atan2(rel.y, rel.x) - scan.angle_min_rad) / scan.angle_increment_rad);
      if (beam >= 0 && beam < n) {
        const double r = scan.ranges[static_cast<std::size_t>(beam)];
        seen_free = !std::isnan(r) && r >= d + p_.cell_m;  // a max-range reading passes everything
      }
    }
    if (seen_free) it->second.evidence -= p_.clear_evidence;
    if (it->second.evidence <= 0)
      it = evidence_.erase(it);
    else
      ++it;
  }
  std::unordered_set<Key> marked;  // one mark per cell and scan, however many beams hit it
  for (const geom::Vec2& m : marks) {
    const Key k = key(m);
    if (!marked.insert(k).second) continue;
    Cell& c = evidence_[k];
    c.evidence = std::min(p_.max_evidence, c.evidence + p_.mark_evidence);
    c.marks = {std::min(c.marks.xmin, m.x), std::min(c.marks.ymin, m.y),
               std::max(c.marks.xmax, m.x), std::max(c.marks.ymax, m.y)};
  }
}

std::vector<geom::Rect> LocalObstacleLayer::occupied() const {
  // Rows of occupied cells, sorted; runs of neighbours along x; a run continues the rectangle
  // of the row below when it spans the same columns.
  std::map<std::int32_t, std::vector<std::pair<std::int32_t, geom::Rect>>> rows;
  for (const auto& [k, cell] : evidence_) {
    if (cell.evidence < p_.occupied_evidence) continue;
    const geom::Vec2 c = centre(k);
    rows[cell_of(c.y, p_.cell_m)].push_back({cell_of(c.x, p_.cell_m), cell.marks});
  }
  auto join = [](const geom::Rect& a, const geom::Rect& b) {
    return geom::Rect{std::min(a.xmin, b.xmin), std::min(a.ymin, b.ymin), std::max(a.xmax, b.xmax),
                      std::max(a.ymax, b.ymax)};
  };
  struct Open {
    std::int32_t x0, x1, y0, y1;
    geom::Rect extent;
  };
  std::vector<Open> done, open;
  for (auto& [iy, xs] : rows) {
    std::sort(xs.begin(), xs.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<Open> next;
    for (std::size_t i = 0; i < xs.size();) {
      std::size_t j = i;
      geom::Rect extent = xs[i].second;
      while (j + 1 < xs.size() && xs[j + 1].first == xs[j].first + 1)
        extent = join(extent, xs[++j].second);
      Open run{xs[i].first, xs[j].first, iy, iy, extent};
      for (auto o = open.begin(); o != open.end(); ++o)
        if (o->x0 == run.x0 && o->x1 == run.x1 && o->y1 + 1 == iy) {
          run.y0 = o->y0;
          run.extent = join(run.extent, o->extent);
          open.erase(o);
          break;
        }
      next.push_back(run);
      i = j + 1;
    }
    done.insert(done.end(), open.begin(), open.end());
    open = std::move(next);
  }
  done.insert(done.end(), open.begin(), open.end());
  std::vector<geom::Rect> out;
  out.reserve(done.size());
  for (const Open& o : done) out.push_back(o.extent);
  std::sort(out.begin(), out.end(), [](const geom::Rect& a, const geom::Rect& b) {
    return std::tie(a.ymin, a.xmin) < std::tie(b.ymin, b.xmin);
  });
  return out;
}

}  // namespace plantsim::robot
