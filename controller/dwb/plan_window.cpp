// The pruned plan and its local goal in sight (see the header).
#include "controller/dwb/plan_window.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace plantsim::controller::dwb {
namespace {

/// Whether the segment a-b keeps the field's distance at least `need` (sampled every half
/// spacing: a straight line of a box's distance field has no dip narrower than that).
bool clear_line(const ClearanceGrid& field, geom::Vec2 a, geom::Vec2 b, double need) {
  const int steps =
      static_cast<int>(std::ceil(geom::distance(a, b) / (0.5 * PlanWindow::kSpacing_m)));
  for (int i = 1; i <= steps; ++i) {
    const geom::Vec2 p = a + (static_cast<double>(i) / steps) * (b - a);
    if (field.interpolated(static_cast<float>(p.x), static_cast<float>(p.y)) < need) return false;
  }
  return true;
}

}  // namespace

void PlanWindow::set_path(const std::vector<geom::Vec2>& plan) {
  path_.clear();
  for (std::size_t i = 0; i < plan.size(); ++i) {
    if (i == 0) {
      path_.push_back(plan[0]);
      continue;
    }
    const double len = geom::distance(plan[i - 1], plan[i]);
    const int pieces = std::max(1, static_cast<int>(std::ceil(len / kSpacing_m)));
    for (int k = 1; k <= pieces; ++k)
      path_.push_back(plan[i - 1] + (static_cast<double>(k) / pieces) * (plan[i] - plan[i - 1]));
  }
  progress_ = 0;
  window_ = path_;
  goal_ = path_.empty() ? geom::Vec2{} : path_.back();
  at_corner_ = false;
}

void PlanWindow::update(geom::Vec2 robot, double forward_prune_distance, const ClearanceGrid* field,
                        double robot_radius_m, double sight_margin_m) {
  if (path_.empty()) return;
  // The nearest point within the next forward_prune_distance (DWB prunes the plan the same
  // way), so that a plan passing the robot twice is not taken for its later pass.
  const auto reach = static_cast<std::size_t>(forward_prune_distance / kSpacing_m);
  double best = std::numeric_limits<double>::infinity();
  const std::size_t from = progress_;
  for (std::size_t k = from; k < path_.size() && k <= from + reach; ++k)
    if (const double d = geom::distance(path_[k], robot); d < best) best = d, progress_ = k;
  window_.assign(
      path_.begin() + static_cast<std::ptrdiff_t>(progress_),
      path_.begin() + static_cast<std::ptrdiff_t>(std::min(path_.size(), progress_ + reach + 1)));
  std::size_t seen = window_.size();
  if (field) {
    const auto clearance = [&](geom::Vec2 p) {
      return static_cast<double>(
          field->interpolated(static_cast<float>(p.x), static_cast<float>(p.y)));
    };
    // Never asking more of the line than the plan or the robot's own place offer: a plan that
    // grazes its margin is still seen along itself.
    double need = std::min(robot_radius_m + sight_margin_m, clearance(robot));
    for (std::size_t k = 1; k < window_.size(); ++k) {
      need = std::min(need, clearance(window_[k]));
      if (!clear_line(*field, robot, window_[k], need - 1e-3)) {
        seen = k;
        break;
      }
    }
  }
  goal_ = window_[seen - 1];
  at_corner_ = seen < window_.size();
}

}  // namespace plantsim::controller::dwb
