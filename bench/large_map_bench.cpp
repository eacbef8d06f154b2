// Large-map planner cases: the any-angle StarCraft maps against their reference lengths and
// Polyanya's recorded times, and random plants up to 200,000 rectangles.
#include "bench/large_map_bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <optional>
#include <random>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "bench/bench_report.h"
#include "bench/memory_probe.h"
#include "planner/inflation.h"
#include "planner/mesh/convex_mesh.h"
#include "planner/mesh/free_space_mesh.h"
#include "planner/mesh/polygon_search.h"
#include "planner/obstacle_map.h"
#include "planner/planner.h"
#include "planner/registry.h"
#include "worlds/grid_map.h"
#include "worlds/random_plant.h"

namespace plantsim::bench {
namespace {

using Clock = std::chrono::steady_clock;

double us_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
}

// Polyanya's mean and median time per query, as ../shared/data/README.md records them (measured
// there on this machine kind, 2026-11-29, mesh loading excluded): a recorded figure, not one
// measured in this run, so the case names say "recorded".
struct RecordedPolyanya {
  const char* map;
  double mean_us, median_us;
};
constexpr RecordedPolyanya kPolyanya[] = {{"ArcticStation", 543, 378}, {"BigGameHunters", 42, 32}};

struct Query {
  int sx, sy, gx, gy;
  double reference;
};

std::vector<Query> load_reference(const std::string& path, int every) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(path + ": cannot open");
  std::string header;
  std::getline(in, header);
  std::vector<Query> queries;
  Query q{};
  double octile = 0;
  for (int line = 0; in >> q.sx >> q.sy >> q.gx >> q.gy >> q.reference >> octile; ++line)
    if (line % every == 0) queries.push_back(q);
  if (queries.empty()) throw std::invalid_argument(path + ": no queries");
  return queries;
}

struct Spread {
  double mean, median, p99, max;
};
Spread spread(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  double sum = 0;
  for (double x : v) sum += x;
  const auto at = [&](double q) {
    return v[std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size())))];
  };
  return {sum / static_cast<double>(v.size()), at(0.5), at(0.99), v.back()};
}

// Memory the process grew by during a phase: its peak since the reset above where it started.
double grown_mb(double before_mb) {
  return std::max(0.0, peak_memory_mb().value_or(before_mb) - before_mb);
}

using geom::Vec2;

struct AnsweredQuery {
  Vec2 start, goal;
  double length;
};

// The floor under a search guided by the straight-line distance: A* over the corners'
// visibility graph with it expands every corner v with d(start, v) + |v goal| below the optimal
// length (what a consistent heuristic cannot rule out), and Polyanya, bounded the same way,
// reaches each of them as a root or inside a root's interval. Their mean count per query (d from
// a search of the whole mesh from the start) is work no tuning of such a search removes; only a
// stronger bound (landmarks) or a distance oracle does.
double mean_unavoidable_corners(const planner::PlannerInput& in,
                                const std::vector<AnsweredQuery>& queries) {
  const planner::ObstacleMap map(planner::inflate(in.obstacles, in.inflation_m, in.corner_steps),
                                 in.floor, in.inflation_m);
  const planner::FreeSpaceMesh rectangles(map.rects(), map.free_floor());
  const planner::ConvexMesh mesh(rectangles);
  planner::PolygonSearch search(mesh);
  double total = 0;
  for (const AnsweredQuery& q : queries) {
    const std::vector<double> from_start = search.distances_to_vertices(q.start);
    for (std::size_t v = 0; v < from_start.size(); ++v) {
      const double through_v = from_start[v] + geom::distance(mesh.points()[v], q.goal);
      if (mesh.is_corner(static_cast<std::int32_t>(v)) && through_v < q.length) total += 1;
    }
  }
  return queries.empty() ? 0 : total / static_cast<double>(queries.size());
}

}  // namespace

int run_anyangle_cases(const std::string& shared_data, bool quick) {
  int failures = 0;
  for (const RecordedPolyanya& ref : kPolyanya) {
    const std::string name = ref.map;
    const std::string base = shared_data + "/anyangle/" + name;
    const worlds::GridMap map = worlds::load_movingai_map(base + ".map");
    const std::vector<Query> queries = load_reference(base + "_anyangle_ref.tsv", quick ? 4 : 1);
    planner::PlannerInput in;
    in.floor = {0, 0, static_cast<double>(map.width), static_cast<double>(map.height)};
    in.obstacles = worlds::merge_blocked_cells(map, worlds::blocked_for_anyangle);
    in.inflation_m = 0;

    struct Method {
      const char* label;  // the case name's
      const char* planner;
      int landmarks;
    };
    for (const Method& m :
         {Method{"vg", "vg", 0}, Method{"interval", "interval", 0},
          Method{"interval_16_landmarks", "interval", 16}, Method{"polyanya", "polyanya", 0},
          Method{"polyanya_16_landmarks", "polyanya", 16}}) {
      const std::string method = m.label;
      in.options = {};
      if (m.landmarks > 0) in.options.set("landmarks", m.landmarks);
      reset_peak_memory();
      const double before = current_memory_mb().value_or(0);
      const auto t0 = Clock::now();
      auto planner = planner::make_planner(m.planner, in);
      const double preprocess_ms = us_since(t0) / 1000;
      const double preprocess_mb = grown_mb(before);

      // Cold: every query once, in the file's order (vg's lazy graph grows as they come); warm:
      // all again on the same planner.
      std::vector<double> cold, warm;
      double expanded = 0;  // per query, cold (vg: vertices; the meshes: intervals)
      reset_peak_memory();
      const double before_queries = current_memory_mb().value_or(0);
      for (int pass = 0; pass < 2; ++pass)
        for (const Query& q : queries) {
          const auto t = Clock::now();
          const planner::PlanResult r = planner->plan(worlds::lattice_point(map, q.sx, q.sy),
                                                      worlds::lattice_point(map, q.gx, q.gy));
          (pass == 0 ? cold : warm).push_back(us_since(t));
          if (pass == 0)
            expanded += static_cast<double>(r.stats.expanded) / static_cast<double>(queries.size());
          if (r.status != planner::PlanStatus::kOk ||
              std::abs(r.length - q.reference) > 5e-6 * q.reference + 1e-5) {
            std::cerr << "bench: " << name << " " << method << " query " << q.sx << " " << q.sy
                      << " -> " << q.gx << " " << q.gy << ": length " << r.length << ", reference "
                      << q.reference << "\n";
            ++failures;
          }
        }
      const double queries_mb = grown_mb(before_queries);
      const Spread c = spread(cold), w = spread(warm);
      const std::string q = std::to_string(queries.size());
      const std::string pre = name + "/polyanya_recorded/";
      const std::string at = name + "/" + method + "/";
      report("planner", {at + "preprocess", preprocess_ms, "ms"});
      report("planner", {at + "preprocess_peak_memory", preprocess_mb, "MB"});
      report("planner", {at + q + "_cold_queries/mean", c.mean, "us"},
             Measure{pre + "mean", ref.mean_us, "us"});
      report("planner", {at + q + "_cold_queries/median", c.median, "us"},
             Measure{pre + "median", ref.median_us, "us"});
      report("planner", {at + q + "_cold_queries/p99", c.p99, "us"});
      report("planner", {at + q + "_cold_queries/max", c.max, "us"});
      report("planner", {at + q + "_warm_queries/mean", w.mean, "us"},
             Measure{pre + "mean", ref.mean_us, "us"});
      report("planner", {at + q + "_warm_queries/median", w.median, "us"},
             Measure{pre + "median", ref.median_us, "us"});
      report("planner", {at + "queries_peak_memory_growth", queries_mb, "MB"});
      report("planner", {at + q + "_cold_queries/expanded_mean", expanded, "nodes"});
    }
  }
  return failures == 0 ? 0 : 1;
}

namespace {

/// One planner on one random plant: build, first query, random queries, memory.
struct PlantRun {
  double build_ms = 0, total_ms = 0, memory_mb = 0, random_expanded = 0;
  std::vector<double> random_ms;
  std::vector<AnsweredQuery> answered;
};

std::optional<PlantRun> measure_plant(const std::string& method, const worlds::World& w, int n,
                                      bool quick) {
  PlantRun run;
  reset_peak_memory();
  const double before = current_memory_mb().value_or(0);
  const auto t0 = Clock::now();
  auto planner = planner::make_planner(method, planner::planner_input(w, false));
  run.build_ms = us_since(t0) / 1000;
  const planner::PlanResult first = planner->plan(w.start.position(), w.charger.position());
  run.total_ms = us_since(t0) / 1000;
  if (first.status != planner::PlanStatus::kOk) {
    std::cerr << "bench: random plant of " << n << " rectangles: no path from start to charger\n";
    return std::nullopt;
  }
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> ux(w.floor.xmin, w.floor.xmax),
      uy(w.floor.ymin, w.floor.ymax);
  for (int tries = 0; tries < 200 && run.random_ms.size() < (quick ? 10u : 20u); ++tries) {
    const Vec2 from{ux(rng), uy(rng)}, to{ux(rng), uy(rng)};
    const auto t = Clock::now();
    const planner::PlanResult r = planner->plan(from, to);
    if (r.status != planner::PlanStatus::kOk) continue;
    run.random_ms.push_back(us_since(t) / 1000);
    run.answered.push_back({from, to, r.length});
    run.random_expanded += static_cast<double>(r.stats.expanded);
  }
  run.memory_mb = grown_mb(before);
  return run;
}

/// The whole exact reduced visibility graph (every vertex's edges found), what a distance oracle
/// over the corners (contraction, hub labels) would be built on: its edges and the time to find
/// them, on a fresh planner. Not on 200,000 rectangles (about a minute).
void report_whole_graph(const worlds::World& w, int n, const std::string& name,
                        const Measure& first_query) {
  if (n > 50000) return;
  const auto t = Clock::now();
  const std::size_t edges =
      planner::make_planner("vg", planner::planner_input(w, false))->graph_edges().size();
  const double whole_ms = us_since(t) / 1000;
  report("planner", {name + "whole_reduced_graph_edges", static_cast<double>(edges), "edges"});
  report("planner", {name + "whole_reduced_graph_build", whole_ms, "ms"}, first_query);
}

/// Why a random query on a large plant costs what it does (README, `bench`): the corners any
/// straight-line-guided search must expand, against what polyanya expands, and what one expansion
/// per such corner would cost at polyanya's measured time per expansion. Each count is a search
/// of the whole mesh per query: not done on 200,000 rectangles.
void report_unavoidable_corners(const worlds::World& w, const PlantRun& run,
                                const std::string& name, const Measure& random) {
  const double queries = static_cast<double>(run.random_ms.size());
  const Measure floor{name + "random_query_unavoidable_corners",
                      mean_unavoidable_corners(planner::planner_input(w, false), run.answered),
                      "corners"};
  const double expanded = run.random_expanded / queries;
  report("planner", floor);
  report("planner", {name + "random_query_expanded_mean", expanded, "intervals"}, floor);
  const double per_interval_ms = random.value / expanded;
  report("planner",
         {name + "random_query_one_expansion_per_unavoidable_corner", floor.value * per_interval_ms,
          "ms"},
         random);
}

/// Least-squares slope of log time against log count: time ~ N^exponent.
void report_growth(const std::string& method, const std::vector<int>& sizes,
                   const std::vector<double>& log_n, const std::vector<double>& log_ms) {
  const double k = static_cast<double>(log_n.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < log_n.size(); ++i)
    sx += log_n[i], sy += log_ms[i], sxx += log_n[i] * log_n[i], sxy += log_n[i] * log_ms[i];
  report("planner",
         {"plant_" + std::to_string(sizes.front()) + "_to_" + std::to_string(sizes.back()) + "/" +
              method + "/build_plus_first_query_growth_exponent",
          (k * sxy - sx * sy) / (k * sxx - sx * sx), "exponent"});
}

}  // namespace

int run_random_plant_scaling(bool quick, std::vector<render::ScalingSeries>* curves) {
  std::vector<int> sizes{1000, 5000, 20000};
  if (!quick) sizes.insert(sizes.end(), {50000, 200000});
  // vg first; the mesh searches' figures are printed against vg's at the same size.
  std::vector<Measure> vg_first, vg_random;
  std::vector<worlds::World> plants;  // made once: generating 200,000 rectangles takes minutes
  for (int n : sizes) plants.push_back(worlds::random_plant(worlds::as_dense_as_n1000(n, 6000)));
  for (const std::string method : {"vg", "interval", "polyanya"}) {
    std::vector<double> log_n, log_ms;
    render::ScalingSeries curve{method + ", random plants as dense as N1000", {}, {}, true, method};
    std::optional<Measure> smallest;
    for (std::size_t i = 0; i < sizes.size(); ++i) {
      const int n = sizes[i];
      const worlds::World& w = plants[i];
      const std::optional<PlantRun> run = measure_plant(method, w, n, quick);
      if (!run) return 1;
      const std::string name = "plant_" + std::to_string(n) + "/" + method + "/";
      const Measure first_query{name + "build_plus_first_query", run->total_ms, "ms"};
      const Measure random{name + "random_query_mean",
                           run->random_ms.empty() ? 0 : spread(run->random_ms).mean, "ms"};
      report("planner", {name + "build", run->build_ms, "ms"});
      if (method == "vg") {
        report("planner", first_query, smallest);
        if (!run->random_ms.empty()) report("planner", random);
        vg_first.push_back(first_query);
        vg_random.push_back(random);
        report_whole_graph(w, n, name, first_query);
      } else {
        report("planner", first_query, vg_first[i]);
        if (!run->random_ms.empty()) report("planner", random, vg_random[i]);
      }
      report("planner", {name + "peak_memory_growth", run->memory_mb, "MB"});
      if (method == "polyanya" && !run->random_ms.empty() && n <= 50000)
        report_unavoidable_corners(w, *run, name, random);
      if (!smallest) smallest = first_query;
      log_n.push_back(std::log(n));
      log_ms.push_back(std::log(run->total_ms));
      curve.size.push_back(n);
      curve.cost.push_back(run->total_ms);
    }
    report_growth(method, sizes, log_n, log_ms);
    if (curves) curves->push_back(std::move(curve));
  }
  return 0;
}

}  // namespace plantsim::bench
