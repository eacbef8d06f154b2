// Octile A* and the rasterising grid planner.
#include "planner/grid/grid_astar.h"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "geometry/polyline.h"
#include "planner/astar.h"
#include "planner/inflation.h"
#include "util/stopwatch.h"

namespace plantsim::planner {
namespace {

double octile(int dx, int dy) {
  dx = std::abs(dx);
  dy = std::abs(dy);
  return std::max(dx, dy) + (std::sqrt(2.0) - 1.0) * std::min(dx, dy);
}

}  // namespace

GridSearchResult grid_astar(int width, int height, const std::function<bool(int, int)>& free,
                            int sx, int sy, int gx, int gy) {
  GridSearchResult out;
  auto ok = [&](int x, int y) { return x >= 0 && y >= 0 && x < width && y < height && free(x, y); };
  if (!ok(sx, sy) || !ok(gx, gy)) return out;
  const auto n = static_cast<std::int32_t>(static_cast<std::int64_t>(width) * height);
  const std::int32_t s = sy * width + sx, g = gy * width + gx;
  const SearchResult r = best_first_search(
      n, s, g, [&](std::int32_t v) { return octile(v % width - gx, v / width - gy); },
      [&](std::int32_t v, auto&& emit) {
        const int x = v % width, y = v / width;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            if ((dx == 0 && dy == 0) || !ok(x + dx, y + dy)) continue;
            if (dx != 0 && dy != 0 && (!ok(x + dx, y) || !ok(x, y + dy)))
              continue;  // no corner cutting
            emit((y + dy) * width + (x + dx), dx != 0 && dy != 0 ? std::sqrt(2.0) : 1.0);
          }
      });
  out.expanded = r.stats.expanded;
  if (!r.found) return out;
  out.found = true;
  out.length = r.cost;
  for (std::int32_t v : r.nodes) out.cells.push_back({v % width, v / width});
  return out;
}

std::vector<OptionSpec> grid_planner_options() {
  return {{"resolution_m", 0.1, 1e-3, 100.0, false, "the cells' size, metres"}};
}

GridPlanner::GridPlanner(const PlannerInput& input)
    : resolution_(input.options.get(grid_planner_options()[0])) {
  const auto t0 = std::chrono::steady_clock::now();
  free_floor_ = input.floor.inflated(-input.inflation_m);
  origin_ = {input.floor.xmin, input.floor.ymin};
  width_ = static_cast<int>(std::ceil(input.floor.width() / resolution_));
  height_ = static_cast<int>(std::ceil(input.floor.height() / resolution_));
  if (static_cast<double>(width_) * height_ > 64.0e6)
    throw std::invalid_argument(
        "grid planner: more than 64 million cells; use a coarser resolution");
  blocked_.assign(static_cast<std::size_t>(width_) * height_, 0);
  const Rect& f = input.floor;
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      const Rect c{f.xmin + x * resolution_, f.ymin + y * resolution_,
                   f.xmin + (x + 1) * resolution_, f.ymin + (y + 1) * resolution_};
      if (c.xmin < free_floor_.xmin || c.xmax > free_floor_.xmax || c.ymin < free_floor_.ymin ||
          c.ymax > free_floor_.ymax)
        blocked_[static_cast<std::size_t>(y) * width_ + x] = 1;
    }
  for (const Rect& r : inflate(input.obstacles, input.inflation_m, input.corner_steps)) {
    const int x0 = std::max(0, static_cast<int>(std::floor((r.xmin - f.xmin) / resolution_)));
    const int x1 =
        std::min(width_ - 1, static_cast<int>(std::ceil((r.xmax - f.xmin) / resolution_)) - 1);
    const int y0 = std::max(0, static_cast<int>(std::floor((r.ymin - f.ymin) / resolution_)));
    const int y1 =
        std::min(height_ - 1, static_cast<int>(std::ceil((r.ymax - f.ymin) / resolution_)) - 1);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) blocked_[static_cast<std::size_t>(y) * width_ + x] = 1;
  }
  build_ms_ = util::ms_since(t0);
}

std::pair<int, int> GridPlanner::cell_of(Vec2 p) const {
  return {static_cast<int>(std::floor((p.x - origin_.x) / resolution_)),
          static_cast<int>(std::floor((p.y - origin_.y) / resolution_))};
}

PlanResult GridPlanner::plan(Vec2 start, Vec2 goal) {
  const auto t0 = std::chrono::steady_clock::now();
  PlanResult out;
  const auto [sx, sy] = cell_of(start);
  const auto [gx, gy] = cell_of(goal);
  auto free = [&](int x, int y) { return blocked_[static_cast<std::size_t>(y) * width_ + x] == 0; };
  auto inside = [&](int x, int y) { return x >= 0 && y >= 0 && x < width_ && y < height_; };
  if (!inside(sx, sy) || !free(sx, sy)) {
    out.status = PlanStatus::kStartBlocked;
  } else if (!inside(gx, gy) || !free(gx, gy)) {
    out.status = PlanStatus::kGoalBlocked;
  } else {
    const GridSearchResult r = grid_astar(width_, height_, free, sx, sy, gx, gy);
    out.stats.expanded = r.expanded;
    if (!r.found) {
      out.status = PlanStatus::kNoPath;
    } else {
      out.status = PlanStatus::kOk;
      out.path.push_back(start);
      for (std::size_t i = 1; i + 1 < r.cells.size(); ++i)
        out.path.push_back({origin_.x + (r.cells[i].first + 0.5) * resolution_,
                            origin_.y + (r.cells[i].second + 0.5) * resolution_});
      out.path.push_back(goal);
      out.length = geom::polyline_length(out.path);
    }
  }
  out.stats.build_ms = build_ms_;
  out.stats.query_ms = util::ms_since(t0);
  out.stats.vertices = static_cast<std::int64_t>(blocked_.size());
  return out;
}

}  // namespace plantsim::planner
