// The planners by name (see the header): the built-in families' entries.
#include "planner/registry.h"

#include <stdexcept>
#include <utility>

#include "planner/coverage/coverage_planner.h"
#include "planner/gcr/gcr_planner.h"
#include "planner/grid/grid_astar.h"
#include "planner/maze/maze_planner.h"
#include "planner/mesh/interval_planner.h"
#include "planner/round/tangent_planner.h"
#include "planner/vg/vg_planner.h"

namespace plantsim::planner {

namespace {

using Make = std::function<std::unique_ptr<Planner>(const PlannerInput&)>;

PlannerEntry entry(std::string name, std::string summary, Make make,
                   std::vector<OptionSpec> options = {},
                   std::vector<std::string> capabilities = {}) {
  PlannerEntry e;
  e.name = std::move(name);
  e.summary = std::move(summary);
  e.make = std::move(make);
  e.options = std::move(options);
  e.capabilities = std::move(capabilities);
  return e;
}

template <typename P, typename... Args>
Make made(Args... args) {
  return [=](const PlannerInput& in) { return std::make_unique<P>(in, args...); };
}

void add_path_planners(PlannerRegistry& r) {
  const std::string b = "built-in";
  r.add(entry("vg", "seed 000 improved: reduced visibility graph of the grown boxes, A*",
              made<VisibilityGraphPlanner>()),
        b);
  r.add(entry("vg-traditional",
              "seed 000's traditional visibility graph: every corner pair, Dijkstra",
              made<TraditionalVisibilityPlanner>()),
        b);
  r.add(entry("vg-round", "shortest paths around the boxes grown by a disk (tangents and arcs)",
              made<RoundTangentPlanner>(), {}, {capability::kRoundMargin}),
        b);
  r.add(entry("interval", "vg's shortest paths by interval search over a mesh of rectangles",
              made<IntervalPlanner>(), mesh_planner_options(), {capability::kSearchesAMesh}),
        b);
  r.add(entry("polyanya", "interval search over a mesh of convex polygons (Polyanya)",
              made<IntervalPlanner>(MeshKind::kConvexPolygons), mesh_planner_options(),
              {capability::kSearchesAMesh}),
        b);
  r.add(entry("grid", "A* through the centres of a grid's free cells", made<GridPlanner>(),
              grid_planner_options()),
        b);
  r.add(entry("gcr", "seed 002: gradient and coordinate-rotation walk, optimised locally",
              made<GcrPlanner>(), gcr_planner_options()),
        b);
  r.add(entry("gcr-shortcut", "seed 002 and plantsim's last shortcut pass", made<GcrPlanner>(true),
              gcr_planner_options()),
        b);
}

void add_maze_planners(PlannerRegistry& r) {
  struct Variant {
    const char* suffix;
    const char* what;
    bool explore;
    ThirdString third;
  };
  const Variant variants[] = {
      {"", "the path string simplified", false, ThirdString::kAsRecorded},
      {"-explore", "driving its whole exploration", true, ThirdString::kAsRecorded},
      {"-resimplified", "the third string simplified again", false, ThirdString::kResimplified}};
  for (const Variant& v : variants)
    for (Hand hand : {Hand::kLeft, Hand::kRight}) {
      const std::string side = hand == Hand::kLeft ? "left" : "right";
      r.add(entry("maze-" + side + v.suffix,
                  "seed 003: the " + side + "-hand rule in the tunnel maze, " + v.what,
                  made<MazePlanner>(hand, v.explore, v.third)),
            "built-in");
    }
}

void add_coverage_planners(PlannerRegistry& r) {
  const std::pair<const char*, const char*> methods[] = {
      {"coverage", "seed 004: full coverage, sub-regions ordered by its Hopfield network"},
      {"coverage-chnn", "seed 004's Hopfield (CHNN) ordering, as `coverage`"},
      {"coverage-potts", "full coverage ordered by plantsim's annealed Potts network"},
      {"coverage-exact", "full coverage in the proven optimum order"},
      {"coverage-greedy", "full coverage, the nearest sweep next"},
      {"coverage-cells", "seed 004's cell-by-cell comparison method"}};
  for (const auto& [name, summary] : methods) {
    const std::string n = name;
    r.add(entry(n, summary,
                [n](const PlannerInput& in) { return std::make_unique<CoveragePlanner>(in, n); },
                {}, {capability::kCoverage}),
          "built-in");
  }
}

}  // namespace

PlannerRegistry& planners() {
  static PlannerRegistry* registry = [] {
    auto* r = new PlannerRegistry("planner");
    add_path_planners(*r);
    add_maze_planners(*r);
    add_coverage_planners(*r);
    return r;
  }();
  return *registry;
}

std::vector<std::string> planner_names() { return planners().names(); }

std::vector<OptionSpec> planner_option_specs(std::string_view name) {
  try {
    return planners().at(name).options;
  } catch (const util::RegistryError&) {
    throw std::invalid_argument("unknown planner '" + std::string(name) + "'");
  }
}

bool planner_can(std::string_view name, std::string_view capability) {
  const PlannerEntry* e = planners().find(name);
  return e && e->can(std::string(capability));
}

std::unique_ptr<Planner> make_planner(std::string_view name, const PlannerInput& input) {
  const std::vector<OptionSpec> specs = planner_option_specs(name);
  check_options(name, input.options, specs);
  return planners().at(name).make(input);
}

}  // namespace plantsim::planner
