// Rejection sampling of rectangles, start and charger.
#include "worlds/random_plant.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "worlds/charger_placement.h"
#include "worlds/world_loader.h"

namespace plantsim::worlds {

RandomPlantOptions as_dense_as_n1000(int rect_count, std::uint64_t seed) {
  RandomPlantOptions o;
  o.rect_count = rect_count;
  o.seed = seed;
  o.width_m = 100.0 * std::sqrt(rect_count / 1000.0);
  o.height_m = 60.0 * std::sqrt(rect_count / 1000.0);
  return o;
}

World random_plant(const RandomPlantOptions& o) {
  if (o.rect_count < 0 || !(o.width_m > 2 * o.min_gap_m + 2) ||
      !(o.height_m > 2 * o.min_gap_m + 2) || !(o.coverage > 0 && o.coverage < 0.6) ||
      !(o.min_gap_m >= 0))
    throw std::invalid_argument("random plant: options out of range");
  std::mt19937_64 rng(o.seed);
  auto uniform = [&](double a, double b) {
    return std::uniform_real_distribution<double>(a, b)(rng);
  };
  World w;
  w.name = "random_n" + std::to_string(o.rect_count) + "_s" + std::to_string(o.seed);
  w.source = w.name;
  w.floor = {0, 0, o.width_m, o.height_m};
  w.inflation_margin_m = kBenchmarkInflation_m - w.robot.radius_m;
  const double side =
      o.rect_count > 0 ? std::sqrt(o.width_m * o.height_m * o.coverage / o.rect_count) : 1.0;
  const double g = o.min_gap_m;
  // The placed rectangles by the cells of a grid they touch: a candidate is checked against its
  // neighbours only (checked against all, placing 200,000 took minutes: quadratic). The same
  // predicate decides, so the same seed gives the same plant.
  const double cell = std::max(1.5 * side + g, std::max(o.width_m, o.height_m) / 4096.0);
  const auto nx = static_cast<long>(std::ceil(o.width_m / cell)) + 1;
  const auto ny = static_cast<long>(std::ceil(o.height_m / cell)) + 1;
  std::vector<std::vector<std::size_t>> grid(static_cast<std::size_t>(nx * ny));
  auto cells_of = [&](double xmin, double ymin, double xmax, double ymax, auto&& visit) {
    const long i0 = std::clamp(static_cast<long>(std::floor(xmin / cell)), 0L, nx - 1);
    const long i1 = std::clamp(static_cast<long>(std::floor(xmax / cell)), 0L, nx - 1);
    const long j0 = std::clamp(static_cast<long>(std::floor(ymin / cell)), 0L, ny - 1);
    const long j1 = std::clamp(static_cast<long>(std::floor(ymax / cell)), 0L, ny - 1);
    for (long j = j0; j <= j1; ++j)
      for (long i = i0; i <= i1; ++i)
        if (!visit(grid[static_cast<std::size_t>(j * nx + i)])) return false;
    return true;
  };
  long tries = 0;
  while (static_cast<int>(w.obstacles.size()) < o.rect_count) {
    if (++tries > 2000L * o.rect_count + 100000)
      throw std::invalid_argument("random plant: could only place " +
                                  std::to_string(w.obstacles.size()) + " of " +
                                  std::to_string(o.rect_count) + " rectangles");
    const double rw = uniform(0.5 * side, 1.5 * side), rh = uniform(0.5 * side, 1.5 * side);
    if (rw > o.width_m - 2 * g - 1 || rh > o.height_m - 2 * g - 1) continue;
    const double x0 = uniform(g, o.width_m - g - rw), y0 = uniform(g, o.height_m - g - rh);
    const Rect r{x0, y0, x0 + rw, y0 + rh};
    const bool ok =
        o.allow_overlap ||
        cells_of(r.xmin - g, r.ymin - g, r.xmax + g, r.ymax + g, [&](const auto& in_cell) {
          for (std::size_t k : in_cell) {
            const Rect& q = w.obstacles[k];
            if (!(r.xmin >= q.xmax + g || q.xmin >= r.xmax + g || r.ymin >= q.ymax + g ||
                  q.ymin >= r.ymax + g))
              return false;
          }
          return true;
        });
    if (!ok) continue;
    cells_of(r.xmin, r.ymin, r.xmax, r.ymax, [&](auto& in_cell) {
      in_cell.push_back(w.obstacles.size());
      return true;
    });
    w.obstacles.push_back(r);
  }
  place_start_and_charger(w, rng);
  return w;
}

void place_start_and_charger(World& w, std::mt19937_64& rng) {
  auto uniform = [&](double a, double b) {
    return std::uniform_real_distribution<double>(a, b)(rng);
  };
  const double width = w.floor.xmax - w.floor.xmin, height = w.floor.ymax - w.floor.ymin;
  auto free_point = [&](double xlo, double xhi) {
    for (int k = 0; k < 100000; ++k) {
      const Vec2 p{uniform(xlo, xhi), uniform(1.0, height - 1.0)};
      bool clear = true;
      for (const Rect& q : w.obstacles)
        if (q.xmin - 0.5 < p.x && p.x < q.xmax + 0.5 && q.ymin - 0.5 < p.y && p.y < q.ymax + 0.5) {
          clear = false;
          break;
        }
      if (clear) return p;
    }
    throw std::invalid_argument("random plant: no free point for the start or the charger");
  };
  for (int attempt = 0; attempt < 1000; ++attempt) {
    const Vec2 s = free_point(1.0, std::min(6.0, width / 4));
    const Vec2 c = free_point(std::max(width - 6.0, 3 * width / 4), width - 1.0);
    w.start = {s.x, s.y, std::atan2(c.y - s.y, c.x - s.x)};
    const auto yaw = choose_docking_heading(w, c);
    if (!yaw) continue;
    w.charger = {c.x, c.y, *yaw};
    validate_world(w);
    return;
  }
  throw std::invalid_argument("random plant: no charger position leaves room to dock");
}

}  // namespace plantsim::worlds
