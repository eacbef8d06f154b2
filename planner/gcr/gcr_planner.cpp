// Gradient / coordinate-rotation walk and its local optimisation.
#include "planner/gcr/gcr_planner.h"

#include <chrono>
#include <cmath>
#include <set>

#include "geometry/polyline.h"
#include "planner/inflation.h"

namespace plantsim::planner {
using geom::polyline_length;

GcrPlanner::GcrPlanner(const PlannerInput& input)
    : map_(inflate(input.obstacles, input.inflation_m, input.corner_steps), input.floor, input.inflation_m),
      step_m_(input.gcr_step_m) {}

GcrPlanner::Walk GcrPlanner::walk(Vec2 start, Vec2 goal) const {
  Walk w;
  w.points.push_back(start);
  Vec2 p = start;
  bool rotating = false;
  Vec2 axis{0, 0};
  std::vector<Vec2> priorities;
  const long budget = static_cast<long>(20.0 * geom::distance(start, goal) / step_m_) + 20000;
  std::set<std::tuple<long, long, int, int>> visited;  // rotation states seen: a repeat is a loop
  for (long k = 0; k < budget; ++k) {
    const Vec2 to_goal = goal - p;
    const double d = geom::norm(to_goal);
    if (d <= step_m_) {
      if (map_.segment_free(p, goal)) {
        w.points.push_back(goal);
        w.reached = true;
      } else {
        w.failure = "trapped next to the goal";
      }
      return w;
    }
    const Vec2 grad_next = p + (step_m_ / d) * to_goal;
    const bool gradient_free = map_.segment_free(p, grad_next);
    if (!rotating) {
      if (gradient_free) {
        p = grad_next;
        w.points.push_back(p);
        continue;
      }
      // Blocked: coordinate rotation, with the priorities fixed at the point of contact.
      rotating = true;
      ++w.rotations;
      const double sx = to_goal.x >= 0 ? 1.0 : -1.0, sy = to_goal.y >= 0 ? 1.0 : -1.0;
      const Vec2 tx{sx, 0}, ty{0, sy};
      priorities = std::fabs(to_goal.x) >= std::fabs(to_goal.y) ? std::vector<Vec2>{tx, ty, -1.0 * ty, -1.0 * tx}
                                                                  : std::vector<Vec2>{ty, tx, -1.0 * tx, -1.0 * ty};
      axis = {0, 0};
    } else if (gradient_free) {
      // Clear of the obstacle: back to the gradient from here.
      rotating = false;
      w.rotation_ends.push_back(w.points.size() - 1);
      continue;
    }
    // Keep the chosen axis while it is free; else the best free one, never straight back.
    Vec2 chosen{0, 0};
    if (!(axis == Vec2{0, 0}) && map_.segment_free(p, p + step_m_ * axis)) {
      chosen = axis;
    } else {
      for (const Vec2& a : priorities) {
        if (a == -1.0 * axis) continue;
        if (map_.segment_free(p, p + step_m_ * a)) {
          chosen = a;
          break;
        }
      }
    }
    if (chosen == Vec2{0, 0}) {
      w.failure = "trapped: no free step in any direction";
      return w;
    }
    axis = chosen;
    p = p + step_m_ * axis;
    w.points.push_back(p);
    const auto key = std::make_tuple(std::lround(p.x / step_m_), std::lround(p.y / step_m_), static_cast<int>(axis.x),
                                     static_cast<int>(axis.y));
    if (!visited.insert(key).second) {
      w.failure = "oscillating: coordinate rotation came back to the same place";
      return w;
    }
  }
  w.failure = "timed out: step budget spent";
  return w;
}

std::vector<Vec2> GcrPlanner::optimise(const Walk& raw, int depth) const {
  // Anchors: where gradient motion began (the start, then each rotation's end) and the goal.
  std::vector<Vec2> anchors = {raw.points.front()};
  for (std::size_t i : raw.rotation_ends) anchors.push_back(raw.points[i]);
  anchors.push_back(raw.points.back());
  std::vector<Vec2> out = {anchors.front()};
  std::size_t raw_index = 0;
  for (std::size_t a = 1; a < anchors.size(); ++a) {
    const Vec2 from = anchors[a - 1], to = anchors[a];
    if (map_.segment_free(from, to)) {
      out.push_back(to);
    } else {
      // The shortcut crosses an obstacle: plan that piece again with the same method.
      const Walk piece = depth > 0 ? walk(from, to) : Walk{};
      if (piece.reached) {
        const auto better = optimise(piece, depth - 1);
        out.insert(out.end(), better.begin() + 1, better.end());
      } else {  // keep what the robot actually walked between the two anchors
        while (raw_index < raw.points.size() && !(raw.points[raw_index] == from)) ++raw_index;
        for (std::size_t i = raw_index + 1; i < raw.points.size(); ++i) {
          out.push_back(raw.points[i]);
          if (raw.points[i] == to) break;
        }
      }
    }
  }
  // Shortcut pass: drop a vertex whenever its neighbours see each other, until nothing changes.
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t i = 1; i + 1 < out.size(); ++i)
      if (map_.segment_free(out[i - 1], out[i + 1])) {
        out.erase(out.begin() + static_cast<std::ptrdiff_t>(i));
        changed = true;
      }
  }
  return out;
}

PlanResult GcrPlanner::plan(Vec2 start, Vec2 goal) {
  const auto t0 = std::chrono::steady_clock::now();
  PlanResult out;
  if (!map_.point_free(start)) {
    out.status = PlanStatus::kStartBlocked;
  } else if (!map_.point_free(goal)) {
    out.status = PlanStatus::kGoalBlocked;
  } else {
    const Walk raw = walk(start, goal);
    out.stats.expanded = static_cast<std::int64_t>(raw.points.size());
    out.stats.edges = raw.rotations;
    if (!raw.reached) {
      out.status = PlanStatus::kNoPath;
      out.note = raw.failure;
    } else {
      std::vector<Vec2> best = optimise(raw, 3);
      const double raw_length = polyline_length(raw.points);
      if (polyline_length(best) > raw_length) best = raw.points;  // never longer than the walk
      out.status = PlanStatus::kOk;
      out.path = best;
      out.length = polyline_length(best);
      out.note = "raw walk " + std::to_string(raw_length) + " m, " + std::to_string(raw.rotations) + " coordinate rotations";
    }
  }
  out.stats.query_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace plantsim::planner
