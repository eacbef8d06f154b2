// plantsim._batch: a scenario run as `plantsim batch SCENARIO --out DIR` runs it, optionally
// with a Python controller in every episode (then on one thread: Python runs one call at a time).
#include <pybind11/stl.h>

#include <atomic>
#include <nlohmann/json.hpp>

#include "batch/batch_gate.h"
#include "batch/batch_runner.h"
#include "batch/summary_tables.h"
#include "python/py_arguments.h"
#include "python/py_bindings.h"
#include "python/py_convert.h"
#include "python/py_interrupt.h"
#include "util/input_file.h"
#include "worlds/world.h"

namespace plantsim::python {
namespace {

py::dict batch(const py::object& scenario_arg, const std::string& out, const py::object& controller,
               const py::object& docking, const std::string& controller_name,
               const py::object& threads, bool figures, bool fresh, bool progress) {
  const std::string scenario = file_from(scenario_arg, "scenario");
  batch::RunOptions o;
  o.out_dir = out;
  o.threads = static_cast<int>(whole_from(threads, "threads", 0, 4096));  // 0: one per core
  o.figures = figures;
  o.fresh = fresh;
  o.progress = progress;
  const std::string name =
      controller_name.empty()
          ? "python:" + callable_name(controller.is_none() ? docking : controller)
          : controller_name;
  o.steering = steering_argument(controller, docking, name);
  // One thread with a Python controller: its state sees one episode at a time. The batch runs
  // off the GIL either way (the controller takes it for each call); Ctrl-C stops it between
  // control periods, the finished episodes kept in episodes.jsonl for a resume.
  if (o.steering) o.threads = 1;
  std::atomic<bool> stop{false};
  o.steering.interrupted = [&stop] { return stop.load(std::memory_order_relaxed); };
  batch::BatchOutcome r;
  Interruptible done = run_interruptibly([&] { r = batch::run_batch(scenario, o); }, stop);
  if (done.signal) {
    done.signal->restore();
    throw py::error_already_set();
  }
  if (done.failure) {
    try {
      std::rethrow_exception(done.failure);
    } catch (const episode::EpisodeStopped& stopped) {
      py::error_already_set error = python_error_of(stopped.cause);
      raise_with_partial(error, py::none(), stopped.time_s);
    }
  }
  const std::vector<std::string> records = batch::read_episode_records(out);
  // Over the whole folder, as the rows count: after a resume this call ran only some of them.
  std::int64_t succeeded = 0;
  for (const std::string& line : records)
    succeeded += batch::record_succeeded(nlohmann::json::parse(line));
  py::dict d;
  d["episodes"] = r.episodes, d["ran"] = r.ran, d["skipped"] = r.skipped,
  d["succeeded"] = succeeded, d["succeeded_now"] = r.succeeded;
  d["collisions"] = r.collisions, d["fingerprint"] = r.scenario_fingerprint;
  d["summary_csv"] = util::read_input_file(out + "/summary.csv");  // with the gate's columns
  return d;
}

}  // namespace

void bind_batch(py::module_& m) {
  m.def("_batch", &batch, py::arg("scenario"), py::arg("out"), py::arg("controller"),
        py::arg("docking"), py::arg("controller_name"), py::arg("threads"), py::arg("figures"),
        py::arg("fresh"), py::arg("progress"));
}

}  // namespace plantsim::python
