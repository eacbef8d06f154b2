// plantsim.nav2_import: `plantsim nav2-import` from Python, the config as a dict.
#include <pybind11/stl.h>

#include "app/nav2_import.h"
#include "python/py_bindings.h"
#include "python/py_convert.h"

namespace plantsim::python {

void bind_nav2(py::module_& m) {
  m.def(
      "nav2_import",
      [](const py::object& path) {
        const app::Nav2Import im = app::import_nav2_params(file_from(path, "path"));
        py::dict d;
        d["config"] = from_json_text(im.config.dump());
        auto rows = [](const std::vector<app::Nav2Parameter>& ps) {
          py::list l;
          for (const auto& p : ps)
            l.append(py::dict(py::arg("nav2") = p.nav2, py::arg("value") = p.value,
                              py::arg("plantsim") = p.plantsim, py::arg("note") = p.note));
          return l;
        };
        d["mapped"] = rows(im.mapped);
        d["world_fields"] = rows(im.world_fields);
        d["not_mapped"] = rows(im.not_mapped);
        d["plugins_not_implemented"] = im.plugins_not_implemented;
        d["report"] = app::nav2_report(im);
        return d;
      },
      py::arg("path"),
      R"(Reads a Nav2 parameter file as `plantsim nav2-import` does. Returns a dict: "config" (pass it
to run(config=...)), "mapped", "world_fields", "not_mapped" (each a list of dicts with nav2, value,
plantsim, note), "plugins_not_implemented" and the printed "report".)");
}

}  // namespace plantsim::python
