// The signed distance field: each outline writes the exact distance into the cells within reach.
#include "robot/likelihood_field.h"

#include <algorithm>
#include <cmath>
#include <list>
#include <mutex>
#include <vector>

#include "geometry/predicates.h"

namespace plantsim::robot {

LikelihoodField::LikelihoodField(const worlds::World& map, double resolution_m, double reach_m,
                                 long max_cells)
    : reach_(reach_m) {
  const geom::Rect area = map.floor.inflated(reach_m);
  res_ = std::max(resolution_m, std::sqrt(area.width() * area.height() /
                                          static_cast<double>(std::max(1L, max_cells))));
  per_m_ = 1.0 / res_;
  origin_ = {area.xmin, area.ymin};
  nx_ = std::max(1L, static_cast<long>(std::ceil(area.width() / res_)));
  ny_ = std::max(1L, static_cast<long>(std::ceil(area.height() / res_)));
  storage_ = util::HugePageBlock(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_) *
                                 sizeof(float));
  cells_ = static_cast<float*>(storage_.data());
  std::fill(cells_, cells_ + nx_ * ny_, static_cast<float>(reach_));
  add_outline(map.floor, false);
  for (const geom::Rect& r : map.obstacles) add_outline(r, true);
  add_outline(worlds::charger_body(map).bounding_box(), true);
}

void LikelihoodField::add_outline(const geom::Rect& r, bool solid) {
  const geom::Rect band = r.inflated(reach_);
  auto first = [&](double v, double o) {
    return static_cast<long>(std::ceil((v - o) / res_ - 0.5));
  };
  auto last = [&](double v, double o) {
    return static_cast<long>(std::floor((v - o) / res_ - 0.5));
  };
  const long j0 = std::max(0L, first(band.ymin, origin_.y)),
             j1 = std::min(ny_ - 1, last(band.ymax, origin_.y));
  const long i0 = std::max(0L, first(band.xmin, origin_.x)),
             i1 = std::min(nx_ - 1, last(band.xmax, origin_.x));
  auto visit = [&](long i, long j) {
    const geom::Vec2 c{origin_.x + (static_cast<double>(i) + 0.5) * res_,
                       origin_.y + (static_cast<double>(j) + 0.5) * res_};
    const bool in = geom::in_closed_rect(r, c);
    const double d = in ? std::min({c.x - r.xmin, r.xmax - c.x, c.y - r.ymin, r.ymax - c.y})
                        : geom::distance(c, geom::closest_point(r, c));
    // The nearest surface's distance, negative once any outline puts the centre inside a block
    // or beyond a wall.
    float& cell = cells_[static_cast<std::size_t>(j * nx_ + i)];
    const float nearest = std::min(std::fabs(cell), static_cast<float>(std::min(d, reach_)));
    cell = std::signbit(cell) || in == solid ? -nearest : nearest;
  };
  for (long j = j0; j <= j1; ++j) {
    const double y = origin_.y + (static_cast<double>(j) + 0.5) * res_;
    // A solid block is visited whole (its inside is signed); the floor only along its walls.
    if (solid || y <= r.ymin + reach_ || y >= r.ymax - reach_) {
      for (long i = i0; i <= i1; ++i) visit(i, j);
      continue;
    }
    const long left_end = std::min(i1, last(r.xmin + reach_, origin_.x));
    const long right_start = std::max(i0, first(r.xmax - reach_, origin_.x));
    for (long i = i0; i <= left_end; ++i) visit(i, j);
    for (long i = std::max(right_start, left_end + 1); i <= i1; ++i) visit(i, j);
  }
}

namespace {

// What a field is built from: the floor, the mapped rectangles, the charger's block, the cells.
struct FieldKey {
  geom::Rect floor, charger;
  std::vector<geom::Rect> obstacles;
  double resolution_m;
  bool operator==(const FieldKey&) const = default;
};

}  // namespace

std::shared_ptr<const LikelihoodField> shared_likelihood_field(const worlds::World& map,
                                                               double resolution_m) {
  // A batch on two threads runs two plants at most at a time; a few more spare a scenario that
  // alternates among its worlds.
  constexpr std::size_t kKept = 4;
  static std::mutex mutex;
  static std::list<std::pair<FieldKey, std::shared_ptr<const LikelihoodField>>> kept;
  FieldKey key{map.floor, worlds::charger_body(map).bounding_box(), map.obstacles, resolution_m};
  {
    const std::lock_guard lock(mutex);
    for (auto it = kept.begin(); it != kept.end(); ++it)
      if (it->first == key) {
        kept.splice(kept.begin(), kept, it);  // the most recently asked first
        return kept.front().second;
      }
  }
  // Built outside the lock: another thread's plant need not wait for this one.
  auto field = std::make_shared<const LikelihoodField>(map, resolution_m);
  const std::lock_guard lock(mutex);
  kept.emplace_front(std::move(key), field);
  if (kept.size() > kKept) kept.pop_back();
  return field;
}

}  // namespace plantsim::robot
