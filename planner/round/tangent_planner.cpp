// Tangents between equal circles, the lazy A* over them, and the clearance checks.
#include "planner/round/tangent_planner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <queue>
#include <stdexcept>
#include <string>
#include <tuple>
#include <unordered_set>

#include "geometry/clearance.h"
#include "geometry/predicates.h"
#include "planner/free_point.h"
#include "planner/inflation.h"
#include "util/stopwatch.h"

namespace plantsim::planner {
namespace {

constexpr double kTwoPi = 2.0 * M_PI;
constexpr double kArcSampleRad = 2.0 * M_PI / 180.0;

Vec2 left_of(Vec2 d) { return {-d.y, d.x}; }

// A tangent segment: it leaves `dep` (on the first circle, or the start) and reaches `arr`.
struct Tangent {
  Vec2 dep, arr;
};

// The line leaving circle (ci, sense si) for circle (cj, sj), both of radius r; sense +1 wraps
// a circle counter-clockwise (it lies on the left), -1 clockwise. None when the circles are too
// close for a crossing tangent, or coincide.
std::optional<Tangent> circle_to_circle(Vec2 ci, int si, Vec2 cj, int sj, double r) {
  const Vec2 D = cj - ci;
  const double l = geom::norm(D);
  if (l == 0) return std::nullopt;
  Vec2 d = (1.0 / l) * D;
  if (si != sj) {
    const double s = 2.0 * si * r / l;
    if (std::abs(s) > 1) return std::nullopt;
    d = geom::rotate(d, std::asin(s));
  }
  return Tangent{ci - si * r * left_of(d), cj - sj * r * left_of(d)};
}

std::optional<Tangent> point_to_circle(Vec2 p, Vec2 cj, int sj, double r) {
  const Vec2 D = cj - p;
  const double l = geom::norm(D);
  if (l < r) return std::nullopt;
  const Vec2 d = geom::rotate((1.0 / l) * D, std::asin(-sj * r / l));
  return Tangent{p, cj - sj * r * left_of(d)};
}

std::optional<Tangent> circle_to_point(Vec2 ci, int si, Vec2 p, double r) {
  const Vec2 D = p - ci;
  const double l = geom::norm(D);
  if (l < r) return std::nullopt;
  const Vec2 d = geom::rotate((1.0 / l) * D, std::asin(si * r / l));
  return Tangent{ci - si * r * left_of(d), p};
}

double angle_of(Vec2 p, Vec2 c) { return std::atan2(p.y - c.y, p.x - c.x); }

// The turn along a circle in sense s from angle a to angle b, in [0, 2 pi); a turn within
// rounding of a full circle is none (a tangent that leaves where the last one arrived).
double sweep_between(double a, double b, int s) {
  double t = std::fmod(s > 0 ? b - a : a - b, kTwoPi);
  if (t < 0) t += kTwoPi;
  if (t > kTwoPi - 1e-12) t = 0;
  return t;
}

// True when angle a lies in one of the closed quadrants of `mask`, up to rounding.
bool in_quadrants(double a, unsigned mask) {
  if (mask == 15u) return true;
  constexpr double kSlack = 1e-9;
  for (unsigned q = 0; q < 4; ++q) {
    if (!(mask & (1u << q))) continue;
    double off = std::fmod(a - q * 0.5 * M_PI + kSlack, kTwoPi);
    if (off < 0) off += kTwoPi;
    if (off <= 0.5 * M_PI + 2 * kSlack) return true;
  }
  return false;
}

// Points strictly inside the arc of circle (c, r) from angle `from` in `sense` through `sweep`,
// at most 2 degrees apart (its ends are the tangent points, added by the caller).
void append_arc_samples(Vec2 c, double r, double from, int sense, double sweep,
                        std::vector<Vec2>& out) {
  const int steps = static_cast<int>(std::ceil(sweep / kArcSampleRad));
  for (int i = 1; i < steps; ++i)
    out.push_back(c + r * geom::unit_from_angle(from + sense * sweep * i / steps));
}

}  // namespace

RoundTangentPlanner::RoundTangentPlanner(const PlannerInput& input)
    : raw_(input.obstacles),
      free_floor_(input.floor.inflated(-input.inflation_m)),
      radius_(input.inflation_m) {
  const auto t0 = std::chrono::steady_clock::now();
  if (raw_.size() > kMaxObstacles)
    throw std::invalid_argument(
        "vg-round: " + std::to_string(raw_.size()) + " obstacles; it plans among at most " +
        std::to_string(kMaxObstacles) + " (use vg with --corner-steps for larger worlds)");
  if (!(radius_ > 0))
    throw std::invalid_argument(
        "vg-round: the inflation must be positive (it is the rounding radius)");
  const std::size_t obstacles = raw_.size();
  // The walls as rectangles thick enough that only their inner faces matter: at the clearance
  // from them lies the floor shrunk by it, corners square (the walls are flat).
  for (const Rect& w : geom::surrounding_walls(input.floor, 2 * radius_ + 1)) raw_.push_back(w);
  const Rect reach = input.floor.inflated(radius_);
  // Each corner with the quadrant of directions pointing away from its rectangle (bit q:
  // angles [q pi/2, (q + 1) pi/2]); a degenerate rectangle gives one point two or four bits.
  struct Corner {
    Vec2 c;
    std::size_t rect;
    unsigned quadrants;
  };
  std::vector<Corner> corners;
  for (std::size_t i = 0; i < obstacles; ++i) {
    const Rect& o = raw_[i];
    const Corner own[4] = {{{o.xmax, o.ymax}, i, 1u},
                           {{o.xmin, o.ymax}, i, 2u},
                           {{o.xmin, o.ymin}, i, 4u},
                           {{o.xmax, o.ymin}, i, 8u}};
    for (const Corner& k : own) {
      if (!geom::in_closed_rect(reach, k.c)) continue;
      bool buried = false;  // inside another rectangle: every point around it is too near
      for (const Rect& q : raw_) buried = buried || geom::in_open_rect(q, k.c);
      if (!buried) corners.push_back(k);
    }
  }
  auto by_point = [](const Corner& a, const Corner& b) {
    return a.c.x != b.c.x ? a.c.x < b.c.x : a.c.y != b.c.y ? a.c.y < b.c.y : a.rect < b.rect;
  };
  std::sort(corners.begin(), corners.end(), by_point);
  for (std::size_t i = 0; i < corners.size();) {
    // A point on the circle outside a rectangle's quadrants is nearer to it than the radius:
    // only the quadrants every rectangle cornered there allows can hold a tangent point.
    unsigned common = 15u;
    std::size_t j = i;
    while (j < corners.size() && corners[j].c == corners[i].c) {
      unsigned mine = 0;
      const std::size_t rect = corners[j].rect;
      for (; j < corners.size() && corners[j].c == corners[i].c && corners[j].rect == rect; ++j)
        mine |= corners[j].quadrants;
      common &= mine;
    }
    circles_.push_back(corners[i].c);
    allowed_.push_back(common == 0 ? 15u
                                   : common);  // none in common: touching rectangles; no pruning
    i = j;
  }
  if (input.snap_to_free)
    square_.emplace(inflate(input.obstacles, input.inflation_m), input.floor, input.inflation_m);
  build_ms_ = util::ms_since(t0);
}

bool RoundTangentPlanner::point_clear(Vec2 p) const {
  // The walls alone would refuse a point off the floor, but not a NaN (every comparison false).
  if (!geom::in_closed_rect(free_floor_.inflated(geom::kClearanceTolerance_m), p)) return false;
  for (const Rect& q : raw_)
    if (geom::distance_to_rect(p, q) < radius_ - geom::kClearanceTolerance_m) return false;
  return true;
}

bool RoundTangentPlanner::segment_clear(Vec2 p, Vec2 q) const {
  for (const Rect& o : raw_)
    if (geom::segment_rect_distance(p, q, o) < radius_ - geom::kClearanceTolerance_m) return false;
  return true;
}

void RoundTangentPlanner::append_drive_corners(Vec2 c, double from, int sense, double sweep,
                                               Vec2 arr, Vec2 dep, std::vector<Vec2>& out) const {
  if (sweep <= 0) return;
  // The arc split into k equal turns, each replaced by the corner where the tangents at its
  // ends meet (r / cos(turn / 2) from the center: outside the circle, inside the square
  // inflation's corner), the fewest pieces whose legs all keep the clearance.
  for (int k = std::max(1, static_cast<int>(std::ceil(sweep / (0.5 * M_PI)))); k <= 64; k *= 2) {
    const double turn = sweep / k, reach = radius_ / std::cos(0.5 * turn);
    std::vector<Vec2> corners;
    for (int i = 0; i < k; ++i)
      corners.push_back(c + reach * geom::unit_from_angle(from + sense * turn * (i + 0.5)));
    bool clear = segment_clear(arr, corners.front()) && segment_clear(corners.back(), dep);
    for (std::size_t i = 1; clear && i < corners.size(); ++i)
      clear = segment_clear(corners[i - 1], corners[i]);
    if (clear) {
      out.insert(out.end(), corners.begin(), corners.end());
      return;
    }
  }
  // Nothing around the arc keeps clear (another obstacle hugs it): the arc's own samples.
  append_arc_samples(c, radius_, from, sense, sweep, out);
}

bool RoundTangentPlanner::arc_clear(std::int32_t circle, double from, double sweep) const {
  const Vec2 c = circles_[static_cast<std::size_t>(circle)];
  for (const Rect& o : raw_)
    if (!geom::arc_keeps_clearance(c, radius_, from, sweep, o, radius_)) return false;
  return true;
}

// One query's lazy A* over (circle, sense) states, each reached by a tangent from its parent: a
// tangent and the arc on the parent's circle before it are checked only when popped.
class RoundTangentPlanner::Search {
 public:
  static constexpr std::int32_t kStart = -1, kGoal = -2;
  struct State {
    std::int32_t circle;  // kStart for the start
    std::int8_t sense;
    Vec2 dep, arr;  // the tangent it arrived by: left its parent at dep, reached arr
    double arr_angle;
    std::int32_t parent;
  };
  struct Entry {
    double f, g;
    std::int32_t circle, parent;  // circle kGoal: the goal
    std::int8_t sense;
    Vec2 dep, arr;
    double sweep;  // the turn on the parent's circle before dep
    bool operator>(const Entry& o) const {
      if (f != o.f) return f > o.f;
      if (g != o.g) return g < o.g;
      if (circle != o.circle) return circle > o.circle;
      if (sense != o.sense) return sense > o.sense;
      return parent > o.parent;
    }
  };

  Search(RoundTangentPlanner& planner, Vec2 start, Vec2 goal)
      : p_(planner),
        r_(planner.radius_),
        n_(static_cast<std::int32_t>(planner.circles_.size())),
        start_(start),
        goal_(goal),
        states_{{kStart, 0, start, start, 0.0, -1}} {}

  // The entry that reached the goal, or none.
  std::optional<Entry> run() {
    expand(0);
    while (!open_.empty()) {
      const Entry e = open_.top();
      open_.pop();
      const std::uint64_t k = e.circle == kGoal ? 0 : key(e.circle, e.sense, e.parent);
      if (e.circle != kGoal && closed_.count(k)) continue;
      if (!clear(e)) continue;
      if (e.circle == kGoal) return e;
      closed_.insert(k);
      const Vec2 c = circle(e.circle);
      states_.push_back({e.circle, e.sense, e.dep, e.arr, angle_of(e.arr, c), e.parent});
      cost_.push_back(e.g);
      expand(static_cast<std::int32_t>(states_.size() - 1));
    }
    return std::nullopt;
  }

  // The path to the goal's entry: back through the states, each arc sampled (path) and turned at
  // its corners (drive_path), then forwards.
  void trace(const Entry& goal_entry, PlanResult& out) const {
    std::vector<std::int32_t> chain;
    for (std::int32_t v = goal_entry.parent; v != -1; v = state(v).parent) chain.push_back(v);
    std::reverse(chain.begin(), chain.end());
    out.path.push_back(start_);
    out.drive_path.push_back(start_);
    auto add_arc = [&](const State& on, Vec2 dep) {
      if (on.circle == kStart) return;
      const Vec2 c = circle(on.circle);
      const double sweep = sweep_between(on.arr_angle, angle_of(dep, c), on.sense);
      append_arc_samples(c, r_, on.arr_angle, on.sense, sweep, out.path);
      p_.append_drive_corners(c, on.arr_angle, on.sense, sweep, on.arr, dep, out.drive_path);
    };
    for (std::size_t i = 1; i < chain.size(); ++i) {
      const State& s = state(chain[i]);
      add_arc(state(chain[i - 1]), s.dep);
      for (auto* line : {&out.path, &out.drive_path}) {
        if (!(line->back() == s.dep)) line->push_back(s.dep);
        line->push_back(s.arr);
      }
    }
    add_arc(state(chain.back()), goal_entry.dep);
    for (auto* line : {&out.path, &out.drive_path}) {
      if (!(line->back() == goal_entry.dep)) line->push_back(goal_entry.dep);
      if (!(line->back() == goal_)) line->push_back(goal_);
    }
  }

  std::int64_t expanded() const { return expanded_; }

 private:
  Vec2 circle(std::int32_t i) const { return p_.circles_[static_cast<std::size_t>(i)]; }
  const State& state(std::int32_t i) const { return states_[static_cast<std::size_t>(i)]; }

  std::uint64_t key(std::int32_t circle, int sense, std::int32_t parent) const {
    const State& p = state(parent);
    const auto from = static_cast<std::uint64_t>(p.circle + 1) * 2 + (p.sense > 0);
    return (static_cast<std::uint64_t>(circle) * 2 + (sense > 0)) *
               (2 * static_cast<std::uint64_t>(n_) + 2) +
           from;
  }

  void push(std::int32_t circle, int sense, std::int32_t parent, const Tangent& t, double sweep,
            double g) {
    const Vec2 target = circle == kGoal ? goal_ : t.arr;
    open_.push({g + geom::distance(target, goal_), g, circle, parent,
                static_cast<std::int8_t>(sense), t.dep, t.arr, sweep});
  }

  bool may_touch(std::int32_t i, Vec2 p) const {
    return in_quadrants(angle_of(p, circle(i)), p_.allowed_[static_cast<std::size_t>(i)]);
  }

  // The turn on the parent's circle, then the segment.
  bool clear(const Entry& e) {
    const State& parent = state(e.parent);
    if (parent.circle != kStart && e.sweep > 0) {
      const double a = parent.arr_angle, from = parent.sense > 0 ? a : a - e.sweep;
      if (!p_.arc_clear(parent.circle, from, e.sweep)) return false;
    }
    ++p_.segment_tests_;
    if (!p_.segment_clear(e.dep, e.arr)) return false;
    ++p_.tangents_kept_;
    return true;
  }

  void expand(std::int32_t at) {
    ++expanded_;
    const State s = state(at);
    const double g = cost_[static_cast<std::size_t>(at)];
    if (s.circle == kStart) {
      push(kGoal, 0, at, {start_, goal_}, 0, geom::distance(start_, goal_));
      for (std::int32_t j = 0; j < n_; ++j)
        for (int sj : {1, -1})
          if (const auto t = point_to_circle(start_, circle(j), sj, r_))
            if (may_touch(j, t->arr)) push(j, sj, at, *t, 0, g + geom::distance(t->dep, t->arr));
      return;
    }
    const Vec2 ci = circle(s.circle);
    auto leave = [&](std::int32_t to, int sense, const Tangent& t) {
      if (!may_touch(s.circle, t.dep) || (to != kGoal && !may_touch(to, t.arr))) return;
      const double sweep = sweep_between(s.arr_angle, angle_of(t.dep, ci), s.sense);
      if (sweep > M_PI) return;  // around one corner a shortest path turns by at most half a turn
      push(to, sense, at, t, sweep, g + r_ * sweep + geom::distance(t.dep, t.arr));
    };
    if (const auto t = circle_to_point(ci, s.sense, goal_, r_)) leave(kGoal, 0, *t);
    for (std::int32_t j = 0; j < n_; ++j) {
      if (j == s.circle) continue;
      for (int sj : {1, -1})
        if (const auto t = circle_to_circle(ci, s.sense, circle(j), sj, r_)) leave(j, sj, *t);
    }
  }

  RoundTangentPlanner& p_;
  const double r_;
  const std::int32_t n_;
  const Vec2 start_, goal_;
  std::vector<State> states_;
  std::vector<double> cost_{0.0};
  std::unordered_set<std::uint64_t> closed_;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open_;
  std::int64_t expanded_ = 0;
};

PlanResult RoundTangentPlanner::plan(Vec2 start, Vec2 goal) {
  const auto t0 = std::chrono::steady_clock::now();
  PlanResult out;
  out.stats.build_ms = build_ms_;
  out.stats.vertices = static_cast<std::int64_t>(circles_.size());
  auto finish = [&] {
    out.stats.query_ms = util::ms_since(t0);
    out.stats.segment_tests = segment_tests_;
    out.stats.edges = tangents_kept_;
    return out;
  };
  // A blocked end moves to the square inflation's nearest free point (free here too: the square
  // grows every obstacle at least as far as the disk does), when snapping is on.
  for (auto [p, snapped, blocked] :
       {std::tuple{&start, &out.start_snapped, PlanStatus::kStartBlocked},
        std::tuple{&goal, &out.goal_snapped, PlanStatus::kGoalBlocked}}) {
    if (point_clear(*p)) continue;
    const auto moved = square_ ? nearest_free_point(*square_, *p) : std::nullopt;
    if (!moved) {
      out.status = blocked;
      return finish();
    }
    *p = *moved;
    *snapped = true;
  }
  Search search(*this, start, goal);
  const auto reached = search.run();
  out.stats.expanded = search.expanded();
  if (!reached) {
    out.status = PlanStatus::kNoPath;
    return finish();
  }
  search.trace(*reached, out);
  out.status = PlanStatus::kOk;
  out.length = reached->g;
  out.note = "segments and arcs of radius " + std::to_string(radius_) +
             " m around corners; arcs sampled every 2 degrees, length exact";
  return finish();
}

}  // namespace plantsim::planner
