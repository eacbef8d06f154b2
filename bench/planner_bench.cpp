// Planner benchmark. Times are wall-clock medians over fresh planners; the traditional graph
// is the baseline of every fast-planner figure on the same world, measured in the same run.
#include "bench/planner_bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <vector>

#include "bench/bench_report.h"
#include "bench/large_map_bench.h"
#include "bench/sample_median.h"
#include "geometry/clearance.h"
#include "planner/planner.h"
#include "planner/registry.h"
#include "planner/vg/vg_overlay.h"
#include "planner/vg/vg_planner.h"
#include "render/png_io.h"
#include "render/scaling_chart.h"
#include "worlds/random_plant.h"
#include "worlds/world_loader.h"

namespace plantsim::bench {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

struct FirstQuery {
  double build_ms = 0, total_ms = 0;
  planner::PlanResult result;
};

FirstQuery build_and_query(const std::string& name, const worlds::World& w, int reps) {
  std::vector<double> build, total;
  FirstQuery out;
  for (int r = 0; r < reps; ++r) {
    const auto t0 = Clock::now();
    auto p = planner::make_planner(name, planner::planner_input(w, false));
    build.push_back(ms_since(t0));
    out.result = p->plan(w.start.position(), w.charger.position());
    total.push_back(ms_since(t0));
  }
  out.build_ms = median(build);
  out.total_ms = median(total);
  return out;
}

struct Named {
  std::string name;
  worlds::World world;
  bool traditional;  ///< also time the traditional graph (the baseline) here
};

std::vector<Named> bench_worlds(const std::string& shared_data, bool quick) {
  std::vector<Named> worlds;
  for (int n : {10, 50, 200, 1000}) {
    std::string count = std::to_string(n);  // (built stepwise: GCC 12 warns falsely on "N" + ...)
    worlds.push_back({std::string("N").append(count),
                      worlds::load_world(shared_data + "/worlds/world_N" + count + ".json"),
                      !quick || n <= 200});
  }
  worlds::RandomPlantOptions big;
  big.rect_count = 5000;
  big.seed = 6000;
  // Five times N1000's floor, so that rectangles keep N1000's size and density.
  big.width_m = 100.0 * std::sqrt(5.0);
  big.height_m = 60.0 * std::sqrt(5.0);
  worlds.push_back({"N5000", worlds::random_plant(big), false});
  return worlds;
}

struct ScalingCurves {
  render::ScalingSeries vg{"vg (visibility graph, A*)", {}, {}, false, "vg"},
      trad{"vg-traditional (all pairs tested)", {}, {}, false, "vg-traditional"},
      grid{"grid (0.1 m cells, A*)", {}, {}, false, "grid"},
      interval{"interval (mesh, interval search)", {}, {}, false, "interval"};
};

/// The graph's counts against the traditional graph's (none without it).
void report_graph_sizes(const Named& nw, const FirstQuery& fast,
                        const std::optional<FirstQuery>& trad) {
  const auto count = [&](const std::string& what, const std::string& theirs, auto stat) {
    report("planner", {nw.name + "/vg/" + what, static_cast<double>(stat(fast)), "count"},
           trad ? std::optional<Measure>(Measure{nw.name + "/vg-traditional/" + theirs,
                                                 static_cast<double>(stat(*trad)), "count"})
                : std::nullopt);
  };
  count("vertices", "vertices", [](const FirstQuery& q) { return q.result.stats.vertices; });
  count("edges_tested_visible", "edges", [](const FirstQuery& q) { return q.result.stats.edges; });
  count("segment_tests", "segment_tests",
        [](const FirstQuery& q) { return q.result.stats.segment_tests; });
}

/// Build and first query of vg, interval, the traditional graph and (for the chart) the grid;
/// false when two exact planners disagree on the length.
bool bench_first_queries(const Named& nw, int reps, bool quick, bool chart, ScalingCurves& curves,
                         std::optional<Measure>& previous_first, FirstQuery& fast) {
  fast = build_and_query("vg", nw.world, reps);
  // The same question answered by interval search over the free-space mesh.
  const FirstQuery interval = build_and_query("interval", nw.world, reps);
  const Measure first{nw.name + "/vg/build_plus_first_query", fast.total_ms, "ms"};
  report("planner", {nw.name + "/interval/build_plus_first_query", interval.total_ms, "ms"}, first);
  if (std::abs(interval.result.length - fast.result.length) > 1e-9 * (1 + fast.result.length)) {
    std::cerr << "bench: interval and vg lengths differ on " << nw.name << "\n";
    return false;
  }
  std::optional<FirstQuery> trad;
  if (nw.traditional)
    trad = build_and_query("vg-traditional", nw.world, nw.name == "N1000" ? 1 : 3);
  const double obstacles = static_cast<double>(nw.world.obstacles.size());
  curves.vg.size.push_back(obstacles);
  curves.vg.cost.push_back(fast.total_ms);
  curves.interval.size.push_back(obstacles);
  curves.interval.cost.push_back(interval.total_ms);
  if (trad) curves.trad.size.push_back(obstacles), curves.trad.cost.push_back(trad->total_ms);
  if (chart) {
    const FirstQuery grid = build_and_query("grid", nw.world, quick ? 1 : 3);
    report("planner", {nw.name + "/grid/build_plus_first_query", grid.total_ms, "ms"}, first);
    curves.grid.size.push_back(obstacles);
    curves.grid.cost.push_back(grid.total_ms);
  }
  auto base = [&](const std::string& metric, double v) -> std::optional<Measure> {
    if (!trad) return std::nullopt;
    return Measure{nw.name + "/vg-traditional/" + metric, v, "ms"};
  };
  report("planner", {nw.name + "/vg/build", fast.build_ms, "ms"},
         base("build", trad ? trad->build_ms : 0));
  // Without a traditional run (N5000), growth against the previous world size.
  report("planner", first, trad ? base("build_plus_first_query", trad->total_ms) : previous_first);
  previous_first = first;
  report_graph_sizes(nw, fast, trad);
  if (trad && std::abs(trad->result.length - fast.result.length) > 1e-9) {
    std::cerr << "bench: length mismatch on " << nw.name << "\n";
    return false;
  }
  return true;
}

/// Later queries on one planner: the same query again, then random pairs of free points.
void bench_later_queries(const Named& nw, planner::Planner& p, const FirstQuery& fast, bool quick) {
  p.plan(nw.world.start.position(), nw.world.charger.position());
  std::vector<double> again;
  for (int r = 0; r < 20; ++r) {
    const auto t0 = Clock::now();
    p.plan(nw.world.start.position(), nw.world.charger.position());
    again.push_back(ms_since(t0));
  }
  const Measure first{nw.name + "/vg/build_plus_first_query", fast.total_ms, "ms"};
  report("planner", {nw.name + "/vg/repeat_query", median(again), "ms"}, first);
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> ux(nw.world.floor.xmin, nw.world.floor.xmax),
      uy(nw.world.floor.ymin, nw.world.floor.ymax);
  std::vector<double> random_ms;
  const int queries = quick ? 50 : 200;
  while (static_cast<int>(random_ms.size()) < queries) {
    const auto t0 = Clock::now();
    const auto r = p.plan({ux(rng), uy(rng)}, {ux(rng), uy(rng)});
    if (r.status == planner::PlanStatus::kOk) random_ms.push_back(ms_since(t0));
  }
  double mean = 0;
  for (double v : random_ms) mean += v;
  mean /= static_cast<double>(random_ms.size());
  report("planner", {nw.name + "/vg/random_query_mean", mean, "ms"}, first);
}

/// A replan around 1 and 5 sensed boxes on the way (0.6 m, on the optimal path): on the warm
/// map graph with the boxes added on top, against a planner rebuilt with them. False when the
/// two lengths differ.
bool bench_replans_around_boxes(const Named& nw, const planner::VisibilityGraphPlanner& vg,
                                const planner::PlanResult& way, int reps) {
  const planner::PlannerInput in = planner::planner_input(nw.world, false);
  const geom::Vec2 start = nw.world.start.position(), goal = nw.world.charger.position();
  for (const int boxes : {1, 5}) {
    std::vector<geom::Rect> raw, grown;
    for (int k = 1; k <= boxes; ++k) {
      const double f = static_cast<double>(k) / (boxes + 1);
      const std::size_t i =
          std::min(way.path.size() - 2, static_cast<std::size_t>(f * (way.path.size() - 1)));
      const geom::Vec2 c = way.path[i] + 0.5 * (way.path[i + 1] - way.path[i]);
      raw.push_back({c.x - 0.3, c.y - 0.3, c.x + 0.3, c.y + 0.3});
      grown.push_back(raw.back().inflated(in.inflation_m));
    }
    planner::PlannerInput with = in;
    with.obstacles.insert(with.obstacles.end(), raw.begin(), raw.end());
    with.snap_to_free = true;
    std::vector<double> rebuild_ms, overlay_ms;
    double rebuild_len = 0, overlay_len = 0;
    for (int r = 0; r < reps; ++r) {
      auto t0 = Clock::now();
      rebuild_len = planner::make_planner("vg", with)->plan(start, goal).length;
      rebuild_ms.push_back(ms_since(t0));
      t0 = Clock::now();
      overlay_len = planner::plan_with_added(vg, grown, start, goal).length;
      overlay_ms.push_back(ms_since(t0));
    }
    if (std::abs(rebuild_len - overlay_len) > 1e-9 * std::max(1.0, rebuild_len)) {
      std::cerr << "bench: replan length mismatch on " << nw.name << " with " << boxes
                << " boxes\n";
      return false;
    }
    const std::string what =
        "/vg/replan_" + std::to_string(boxes) + (boxes == 1 ? "_box" : "_boxes");
    report("planner", {nw.name + what + "_on_map_graph", median(overlay_ms), "ms"},
           Measure{nw.name + what + "_rebuilt", median(rebuild_ms), "ms"});
  }
  return true;
}

/// A mapped obstacle that is gone (the one nearest the middle of the way): the changed planner
/// takes over what the removal cannot reach, against a planner built for the changed world.
bool bench_replan_removed(const Named& nw, const planner::VisibilityGraphPlanner& vg,
                          const planner::PlanResult& way, int reps) {
  const planner::PlannerInput in = planner::planner_input(nw.world, false);
  if (in.obstacles.empty()) return true;
  const geom::Vec2 start = nw.world.start.position(), goal = nw.world.charger.position();
  const geom::Vec2 mid = way.path[way.path.size() / 2];
  std::size_t gone = 0;
  for (std::size_t i = 1; i < in.obstacles.size(); ++i)
    if (geom::distance_to_rect(mid, in.obstacles[i]) <
        geom::distance_to_rect(mid, in.obstacles[gone]))
      gone = i;
  std::vector<double> changed_ms, rebuild_ms;
  double changed_len = 0, rebuild_len = 0;
  for (int r = 0; r < reps; ++r) {
    auto t0 = Clock::now();
    const auto changed = vg.with_changes({}, {gone});
    changed_len = changed->plan(start, goal).length;
    changed_ms.push_back(ms_since(t0));
    t0 = Clock::now();
    rebuild_len = planner::make_planner("vg", changed->input())->plan(start, goal).length;
    rebuild_ms.push_back(ms_since(t0));
  }
  if (std::abs(rebuild_len - changed_len) > 1e-9 * std::max(1.0, rebuild_len)) {
    std::cerr << "bench: replan length mismatch on " << nw.name << " with an obstacle removed\n";
    return false;
  }
  report("planner", {nw.name + "/vg/replan_1_removed_on_changed_graph", median(changed_ms), "ms"},
         Measure{nw.name + "/vg/replan_1_removed_rebuilt", median(rebuild_ms), "ms"});
  return true;
}

void draw_chart(const ScalingCurves& c, const std::vector<render::ScalingSeries>& plants, int reps,
                bool quick, const std::string& chart_png) {
  std::vector<render::ScalingSeries> series{c.vg, c.trad, c.grid, c.interval};
  series.insert(series.end(), plants.begin(), plants.end());
  const render::Image img = render::draw_scaling_chart(
      series, "Planning time against the number of obstacles",
      "build plus first query, median of " + std::to_string(reps) +
          " runs (grid and vg-traditional fewer); solid: world_N10..N1000, N5000 (vg-traditional " +
          std::string(quick ? "to N200, --quick" : "to N1000") +
          "); dashed: random plants of 1,000 to " + std::string(quick ? "20,000" : "200,000") +
          " rectangles",
      "obstacles (rectangles)", "time (ms)");
  render::write_png(img, chart_png);
  std::cerr << "bench: chart -> " << chart_png << "\n";
}

}  // namespace

int run_planner_bench(const std::string& shared_data, bool quick, const std::string& chart_png) {
  const int reps = quick ? 3 : 7;
  std::optional<Measure> previous_first;
  ScalingCurves curves;
  for (const Named& nw : bench_worlds(shared_data, quick)) {
    FirstQuery fast;
    if (!bench_first_queries(nw, reps, quick, !chart_png.empty(), curves, previous_first, fast))
      return 1;
    // The later queries and the replans are the visibility graph's own (its warm graph, its
    // overlay, its changes), so it is built as itself, not through the registry.
    planner::VisibilityGraphPlanner vg(planner::planner_input(nw.world, false));
    bench_later_queries(nw, vg, fast, quick);
    const planner::PlanResult way = vg.plan(nw.world.start.position(), nw.world.charger.position());
    if (way.status != planner::PlanStatus::kOk || way.path.size() < 2) continue;
    if (!bench_replans_around_boxes(nw, vg, way, reps) || !bench_replan_removed(nw, vg, way, reps))
      return 1;
  }
  const int anyangle = run_anyangle_cases(shared_data, quick);
  std::vector<render::ScalingSeries> plant_curves;
  const int plants = run_random_plant_scaling(quick, &plant_curves);
  if (!chart_png.empty()) draw_chart(curves, plant_curves, reps, quick, chart_png);
  return anyangle != 0 ? anyangle : plants;
}

}  // namespace plantsim::bench
