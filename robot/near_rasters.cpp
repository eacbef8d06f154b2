// The process's rasters: a short list, most recently asked first, under a lock.
#include "robot/near_rasters.h"

#include <algorithm>
#include <list>
#include <mutex>
#include <utility>
#include <vector>

namespace plantsim::robot {

std::shared_ptr<const geom::NearRaster> shared_near_raster(const geom::RayGrid& grid,
                                                           double margin_m) {
  // A map's boxes and one margin name a raster. Two threads run two plants at a time, each with
  // the few margins its learnt noise moves between.
  constexpr std::size_t kKept = 8;
  using Key = std::pair<std::vector<geom::Rect>, double>;
  static std::mutex mutex;
  static std::list<std::pair<Key, std::shared_ptr<const geom::NearRaster>>> kept;
  auto same = [&](const Key& k) { return k.second == margin_m && k.first == grid.bounds(); };
  {
    const std::lock_guard lock(mutex);
    for (auto it = kept.begin(); it != kept.end(); ++it)
      if (same(it->first)) {
        kept.splice(kept.begin(), kept, it);
        return kept.front().second;
      }
  }
  // Built outside the lock: another thread's plant need not wait for this one.
  const geom::Rect& a = grid.area();
  const geom::Rect area{a.xmin - margin_m, a.ymin - margin_m, a.xmax + margin_m, a.ymax + margin_m};
  auto raster = std::make_shared<const geom::NearRaster>(grid.bounds(), margin_m, area,
                                                         std::max(0.05, 0.5 * margin_m));
  const std::lock_guard lock(mutex);
  kept.emplace_front(Key{grid.bounds(), margin_m}, raster);
  if (kept.size() > kKept) kept.pop_back();
  return raster;
}

}  // namespace plantsim::robot
