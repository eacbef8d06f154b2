// plantsim._batch: a scenario run as `plantsim batch SCENARIO --out DIR` runs it, optionally
// with a Python controller in every episode (then on one thread: Python runs one call at a time).
#include <pybind11/stl.h>

#include "batch/batch_runner.h"
#include "batch/summary_tables.h"
#include "python/py_arguments.h"
#include "python/py_bindings.h"
#include "worlds/world.h"

namespace plantsim::python {
namespace {

py::dict batch(const std::string& scenario, const std::string& out, const py::object& controller,
               const py::object& docking, const std::string& controller_name, int threads,
               bool figures, bool fresh, bool progress) {
  batch::RunOptions o;
  o.out_dir = out;
  o.threads = threads;
  o.figures = figures;
  o.fresh = fresh;
  o.progress = progress;
  const std::string name =
      controller_name.empty()
          ? "python:" + callable_name(controller.is_none() ? docking : controller)
          : controller_name;
  o.steering = steering_argument(controller, docking, name);
  batch::BatchOutcome r;
  if (o.steering) {
    o.threads = 1;
    r = batch::run_batch(scenario, o);
  } else {
    py::gil_scoped_release free_python;
    r = batch::run_batch(scenario, o);
  }
  const std::vector<std::string> records = batch::read_episode_records(out);
  py::dict d;
  d["episodes"] = r.episodes, d["ran"] = r.ran, d["skipped"] = r.skipped,
  d["succeeded"] = r.succeeded;
  d["collisions"] = r.collisions, d["fingerprint"] = r.scenario_fingerprint;
  d["summary_csv"] = batch::summary_csv(records);
  return d;
}

}  // namespace

void bind_batch(py::module_& m) {
  m.def("_batch", &batch, py::arg("scenario"), py::arg("out"), py::arg("controller"),
        py::arg("docking"), py::arg("controller_name"), py::arg("threads"), py::arg("figures"),
        py::arg("fresh"), py::arg("progress"));
}

}  // namespace plantsim::python
