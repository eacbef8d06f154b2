// plantsim.load_plugin() and plantsim.components(): a plugin's components loaded into the module,
// then chosen by name in configs and scenarios exactly as from the command line. A bad plugin
// raises plantsim.InputError naming the file.
#include <pybind11/stl.h>

#include "controller/local_controller_registry.h"
#include "planner/registry.h"
#include "plugins/plugin_loader.h"
#include "python/py_bindings.h"
#include "robot/dock_detector.h"
#include "robot/estimator_registry.h"
#include "robot/travel_registry.h"

namespace plantsim::python {

namespace {

py::dict component_dict(const util::ComponentInfo& c) {
  py::dict d;
  d["name"] = c.name;
  d["origin"] = c.origin;
  d["summary"] = c.summary;
  d["capabilities"] = c.capabilities;
  py::list params;
  for (const util::ParamSpec& p : c.params) {
    py::dict row;
    row["key"] = p.path();
    row["default"] = p.default_value;
    row["low"] = p.lo;
    row["high"] = p.hi;
    row["low_excluded"] = p.above;
    row["kind"] = p.kind == util::ParamKind::kFlag    ? "flag"
                  : p.kind == util::ParamKind::kWhole ? "whole"
                                                      : "real";
    row["doc"] = p.doc;
    params.append(row);
  }
  d["parameters"] = params;
  return d;
}

template <typename Registry>
py::list registry_list(const Registry& r) {
  py::list out;
  for (const auto* e : r.entries()) out.append(component_dict(*e));
  return out;
}

}  // namespace

void bind_plugins(py::module_& m) {
  m.def(
      "load_plugin",
      [](const std::string& path) {
        const plugins::LoadedPlugin& p = [&]() -> const plugins::LoadedPlugin& {
          py::gil_scoped_release unlocked;  // its registration may take a while
          return plugins::load_plugin(path);
        }();
        py::dict d;
        d["path"] = p.path;
        d["local_controllers"] = p.local_controllers;
        d["estimators"] = p.estimators;
        d["planners"] = p.planners;
        d["dock_detectors"] = p.dock_detectors;
        return d;
      },
      py::arg("path"),
      "Load a plugin (a shared library built with PLANTSIM_PLUGIN, docs/plugins.md): its "
      "components can then be named in configs and scenarios. Returns what it registered; a bad "
      "plugin raises InputError naming the file. Loading a file twice loads it once.");
  m.def(
      "components",
      []() {
        py::dict d;
        d["travel_modes"] = registry_list(robot::travel_modes());
        d["local_controllers"] = registry_list(controller::local_controllers());
        d["estimators"] = registry_list(robot::estimators());
        d["dock_detectors"] = registry_list(robot::dock_detectors());
        py::list planners;
        for (const auto* e : planner::planners().entries()) {
          py::dict row = component_dict(*e);
          py::list options;
          for (const planner::OptionSpec& o : e->options) {
            py::dict option;
            option["name"] = o.name;
            option["default"] = o.default_value;
            option["low"] = o.min;
            option["high"] = o.max;
            option["whole"] = o.integer;
            option["doc"] = o.meaning;
            options.append(option);
          }
          row["options"] = options;
          planners.append(row);
        }
        d["planners"] = planners;
        return d;
      },
      "Every registered component (built-in and loaded plugins') with its parameters and bounds, "
      "as `plantsim info` lists them.");
}

}  // namespace plantsim::python
