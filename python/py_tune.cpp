// plantsim._tune: a tuning run as `plantsim tune SCENARIO --out DIR` runs it, off the GIL and
// stoppable by Ctrl-C between episodes (the finished evaluations kept for a resume).
#include <pybind11/stl.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <optional>

#include "python/py_bindings.h"
#include "python/py_convert.h"
#include "python/py_interrupt.h"
#include "tune/run_tune.h"
#include "util/input_file.h"

namespace plantsim::python {
namespace {

py::object tune(const py::object& scenario_arg, const std::string& out,
                const std::vector<std::string>& params, const py::object& budget_arg,
                std::optional<std::string> objective, std::optional<std::string> method,
                std::optional<double> min_wilson, const py::object& seed_arg,
                const py::object& threads_arg, bool figures, bool fresh, bool progress) {
  const std::string scenario = file_from(scenario_arg, "scenario");
  std::optional<int> budget;
  if (!budget_arg.is_none())  // its range checked by the tuning's own rule (tune_spec.cpp)
    budget = static_cast<int>(whole_from(budget_arg, "budget", std::numeric_limits<int>::min(),
                                         std::numeric_limits<int>::max()));
  const std::uint64_t seed = seed_from(seed_arg, "seed");
  const int threads = static_cast<int>(whole_from(threads_arg, "threads", 0, 4096));
  if (min_wilson && !std::isfinite(*min_wilson))
    throw std::invalid_argument("min_wilson must be a finite number from 0 to 1");
  tune::TuneRequest r;
  r.scenario = scenario;
  r.parameters = params;
  r.budget = budget;
  r.objective = objective;
  r.method = method;
  r.min_wilson = min_wilson;
  r.seed = seed;
  r.threads = threads;
  tune::TuneOptions o;
  o.out_dir = out;
  o.fresh = fresh;
  o.figures = figures;
  o.progress = progress;
  o.command = "plantsim.tune(" + scenario + ")";
  std::atomic<bool> stop{false};
  o.interrupted = [&stop] { return stop.load(std::memory_order_relaxed); };
  Interruptible done = run_interruptibly([&] { tune::run_tune(tune::load_tune_spec(r), o); }, stop);
  if (done.signal) {
    done.signal->restore();
    throw py::error_already_set();
  }
  if (done.failure) std::rethrow_exception(done.failure);
  return from_json_text(util::read_input_file(out + "/summary.json"));
}

}  // namespace

void bind_tune(py::module_& m) {
  m.def("_tune", &tune, py::arg("scenario"), py::arg("out"), py::arg("params"), py::arg("budget"),
        py::arg("objective"), py::arg("method"), py::arg("min_wilson"), py::arg("seed"),
        py::arg("threads"), py::arg("figures"), py::arg("fresh"), py::arg("progress"));
}

}  // namespace plantsim::python
