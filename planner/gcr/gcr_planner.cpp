// Gradient / coordinate-rotation walk and its local optimisation.
#include "planner/gcr/gcr_planner.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <set>
#include <tuple>

#include "geometry/polyline.h"
#include "planner/inflation.h"
#include "util/c_number.h"
#include "util/stopwatch.h"

namespace plantsim::planner {
using geom::polyline_length;

std::vector<OptionSpec> gcr_planner_options() {
  return {{"step_m", 0.1, 1e-3, 10.0, false, "the walk's unit step, metres"}};
}

GcrPlanner::GcrPlanner(const PlannerInput& input, bool shortcut_pass)
    : map_(inflate(input.obstacles, input.inflation_m, input.corner_steps), input.floor,
           input.inflation_m),
      step_m_(input.options.get(gcr_planner_options()[0])),
      shortcut_pass_(shortcut_pass) {}

Vec2 GcrPlanner::gradient_step(Vec2 p, Vec2 goal, double unit) {
  const Vec2 d = goal - p;
  const double minor = std::min(std::fabs(d.x), std::fabs(d.y));
  // |x| = dx/dy, |y| = 1 (or the other way round): the minor axis advances one unit.
  return minor > unit ? (unit / minor) * d : d;
}

namespace {

// One run of coordinate rotation: the priorities fixed at the point of contact, the axis kept
// while it is free, and the whole steps taken from the contact.
struct RotationRun {
  std::vector<Vec2> priorities;
  int priority_key = 0;
  Vec2 axis{0, 0};
  Vec2 contact{0, 0};  // where the run began
  long steps_x = 0, steps_y = 0;

  RotationRun(Vec2 p, Vec2 to_goal) : contact(p) {
    const double sx = to_goal.x >= 0 ? 1.0 : -1.0, sy = to_goal.y >= 0 ? 1.0 : -1.0;
    const Vec2 tx{sx, 0}, ty{0, sy};
    const bool x_first = std::fabs(to_goal.x) >= std::fabs(to_goal.y);
    priorities = x_first ? std::vector<Vec2>{tx, ty, -1.0 * ty, -1.0 * tx}
                         : std::vector<Vec2>{ty, tx, -1.0 * tx, -1.0 * ty};
    priority_key = (x_first ? 4 : 0) + (sx > 0 ? 2 : 0) + (sy > 0 ? 1 : 0);
  }

  // The chosen axis while it is free; else the best free one, never straight back; (0, 0) when
  // every way is blocked.
  Vec2 next_axis(const ObstacleMap& map, Vec2 p, double step_m) const {
    if (!(axis == Vec2{0, 0}) && map.segment_free(p, p + step_m * axis)) return axis;
    for (const Vec2& a : priorities) {
      if (a == -1.0 * axis) continue;
      if (map.segment_free(p, p + step_m * a)) return a;
    }
    return {0, 0};
  }

  // On the lattice of whole steps from the contact point, so that coming back to a place gives
  // the same coordinates to the bit (a sum of steps would drift in the last digits).
  Vec2 step(double step_m) {
    steps_x += static_cast<int>(axis.x);
    steps_y += static_cast<int>(axis.y);
    return contact + Vec2{step_m * steps_x, step_m * steps_y};
  }

  // The walk is deterministic: in rotation its future depends only on where the run began (to
  // the bit), the whole steps taken from there, the axis and the priorities.
  std::tuple<double, double, long, long, int, int, int> state() const {
    return {contact.x,
            contact.y,
            steps_x,
            steps_y,
            static_cast<int>(axis.x),
            static_cast<int>(axis.y),
            priority_key};
  }
};

}  // namespace

GcrPlanner::Walk GcrPlanner::walk(Vec2 start, Vec2 goal) const {
  Walk w;
  w.points.push_back(start);
  Vec2 p = start;
  std::optional<RotationRun> run;
  // 20 times the straight distance in steps, plus room for short trips around large obstacles.
  const long budget = static_cast<long>(20.0 * geom::distance(start, goal) / step_m_) + 20000;
  // The same rotation state again means a loop for ever: no walk that would arrive is stopped.
  // Anything less exact fails walks that do arrive: on the substation yard, counting passes
  // through the same step-sized cell failed walks that arrived after 105 m and 382 m, even when
  // allowed ten passes. A walk that circles with a drift (up and down inside a cup, a little
  // further each time) runs into the step budget instead and says so.
  std::set<std::tuple<double, double, long, long, int, int, int>> rotation_states;

  for (long k = 0; k < budget; ++k) {
    if (p == goal) {
      w.reached = true;
      return w;
    }
    const Vec2 to_goal = goal - p;
    const Vec2 step = gradient_step(p, goal, step_m_);
    const Vec2 grad_next =
        step == to_goal ? goal : p + step;  // the last step ends on the goal exactly
    const bool gradient_free = map_.segment_free(p, grad_next);
    if (!run) {
      if (gradient_free) {
        p = grad_next;
        w.points.push_back(p);
        continue;
      }
      // Blocked: coordinate rotation, with the priorities fixed at the point of contact.
      ++w.rotations;
      run.emplace(p, to_goal);
    } else if (gradient_free) {
      // Clear of the obstacle: back to the gradient from here.
      run.reset();
      w.rotation_ends.push_back(w.points.size() - 1);
      continue;
    }
    const Vec2 chosen = run->next_axis(map_, p, step_m_);
    if (chosen == Vec2{0, 0}) {
      w.failure = "trapped: no free step in any direction";
      return w;
    }
    if (run->axis == Vec2{0, 0}) w.first_rotation_axes.push_back(chosen);
    run->axis = chosen;
    if (!rotation_states.insert(run->state()).second) {
      w.failure =
          "oscillating: coordinate rotation came back to a state it was in (it would loop for "
          "ever)";
      return w;
    }
    p = run->step(step_m_);
    w.points.push_back(p);
  }
  w.failure = "timed out: " + std::to_string(budget) + " steps without arriving (circling)";
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
  if (!shortcut_pass_) return out;
  // plantsim's pass (not the document's): drop a vertex whenever its neighbours see each other.
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
    out.trace.explored = raw.points;  // the raw walk, drawn beside the optimised path
    out.trace.explored_label = "raw walk";
    out.stats.expanded = static_cast<std::int64_t>(raw.points.size());
    out.stats.edges = raw.rotations;
    if (!raw.reached) {
      out.status = PlanStatus::kNoPath;
      out.note = raw.failure;
    } else {
      // The document's optimisation recurses into the walks between a rotation's ends; plantsim
      // caps that at depth 3 (the document sets no cap; deeper levels changed nothing on the
      // plants measured, docs/seeds.md).
      std::vector<Vec2> best = optimise(raw, kOptimisationDepth);
      const double raw_length = polyline_length(raw.points);
      // As written, the optimisation can return a path longer than the walk it started from; gcr
      // keeps it. Only plantsim's variant (gcr-shortcut) falls back to the walk then.
      const bool longer = polyline_length(best) > raw_length * (1 + 1e-12);
      if (shortcut_pass_ && longer) best = raw.points;
      out.status = PlanStatus::kOk;
      out.path = best;
      out.length = polyline_length(best);
      char note[200];
      util::c_snprintf(
          note, sizeof note, "raw walk %.2f m, %d coordinate rotations, optimised %.2f m%s%s",
          raw_length, raw.rotations, out.length,
          longer && !shortcut_pass_ ? " (longer than the walk, as written)" : "",
          shortcut_pass_
              ? (longer ? " (plantsim's variant: the walk, shorter than the optimisation)"
                        : " (with plantsim's shortcut pass)")
              : "");
      out.note = note;
    }
  }
  out.stats.query_ms = util::ms_since(t0);
  return out;
}

}  // namespace plantsim::planner
