// plantsim.plan: one query of any planner on a world, as `plantsim plan` makes it.
#include <pybind11/stl.h>

#include "planner/planner.h"
#include "planner/registry.h"
#include "python/py_bindings.h"
#include "python/py_world.h"

namespace plantsim::python {
namespace {

struct PyPlan {
  std::string planner, status, note;
  double length = 0;
  std::vector<geom::Vec2> path, drive_path;
  planner::PlanStats stats;
};

PyPlan plan(const py::handle& world_arg, const std::string& name, const py::object& start,
            const py::object& goal) {
  const PyWorld w = world_argument(world_arg);
  const std::vector<std::string> names = planner::planner_names();
  if (std::find(names.begin(), names.end(), name) == names.end())
    throw std::invalid_argument("unknown planner '" + name + "' (plantsim.planners() lists them)");
  const geom::Vec2 from =
      start.is_none() ? w.world->start.position() : pose_from(start, "start").position();
  // As `plantsim plan --goal`: "staging" (where runs plan to, the charger's body an obstacle) or
  // "docked" (the charger's docked position, its body left out so the goal is reachable).
  geom::Vec2 to = worlds::staging_pose(*w.world).position();
  bool charger_body = true;
  if (py::isinstance<py::str>(goal)) {
    const std::string kind = goal.cast<std::string>();
    if (kind == "docked")
      to = w.world->charger.position(), charger_body = false;
    else if (kind != "staging")
      throw std::invalid_argument("goal must be \"staging\", \"docked\" or (x, y)");
  } else if (!goal.is_none()) {
    std::vector<double> g;
    try {
      g = goal.cast<std::vector<double>>();
    } catch (const py::cast_error&) {
    }
    if (g.size() != 2 || !std::isfinite(g[0]) || !std::isfinite(g[1]))
      throw std::invalid_argument("goal expects (x, y)");
    to = {g[0], g[1]};
  }
  std::unique_ptr<planner::Planner> p =
      planner::make_planner(name, planner::planner_input(*w.world, charger_body));
  const planner::PlanResult r = p->plan(from, to);
  return {name,   std::string(planner::to_string(r.status)), r.note, r.length, r.path, r.drive_path,
          r.stats};
}

}  // namespace

void bind_plan(py::module_& m) {
  py::class_<PyPlan>(m, "Plan", "One planner query: status, length (m), path (N x 2), stats.")
      .def_readonly("planner", &PyPlan::planner)
      .def_readonly("status", &PyPlan::status, "\"ok\", or why there is no path")
      .def_readonly("note", &PyPlan::note)
      .def_readonly("length", &PyPlan::length, "metres along the path")
      .def_property_readonly("path", [](const PyPlan& p) { return points_array(p.path); })
      .def_property_readonly(
          "drive_path",
          [](const PyPlan& p) {
            return points_array(p.drive_path.empty() ? p.path : p.drive_path);
          },
          "what a controller follows (vg-round: arcs replaced by their tangents' corners)")
      .def_property_readonly("stats",
                             [](const PyPlan& p) {
                               py::dict d;
                               d["build_ms"] = p.stats.build_ms, d["query_ms"] = p.stats.query_ms,
                               d["vertices"] = p.stats.vertices;
                               d["edges"] = p.stats.edges, d["expanded"] = p.stats.expanded,
                               d["segment_tests"] = p.stats.segment_tests;
                               return d;
                             })
      .def("__repr__", [](const PyPlan& p) {
        return "<plantsim.Plan " + p.planner + ": " + p.status + ", " + std::to_string(p.length) +
               " m>";
      });
  m.def("planners", &planner::planner_names, "The planner names plan() and run() accept.");
  m.def("plan", &plan, py::arg("world"), py::arg("planner") = "vg", py::kw_only(),
        py::arg("start") = py::none(), py::arg("goal") = "staging",
        R"(Plans on a world (a World or a path) with the named planner.

start: (x, y, yaw), default the world's start. goal: "staging" (where the docking manoeuvre
begins, as runs plan; the charger's body is an obstacle), "docked" (the charger's docked position,
its body left out, as `plantsim plan --goal docked`), or (x, y). Returns a Plan with .length,
.path, .stats, .status.)");
}

}  // namespace plantsim::python
