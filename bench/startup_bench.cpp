// Whole processes of this binary, timed one after another; the median is the measure (start-up
// is a few milliseconds, where one scheduling hiccup is as long).
#include "bench/startup_bench.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "bench/bench_report.h"
#include "util/process.h"

namespace plantsim::bench {
namespace {

struct StartupCost {
  double median_ms = 0;
  double peak_mib = 0;
};

StartupCost measure(const std::vector<std::string>& argv, const std::vector<std::string>& env,
                    int runs) {
  util::SpawnOptions o;
  o.stdout_path = "/dev/null";
  o.stderr_path = "/dev/null";
  o.environment_additions = env;
  std::vector<double> ms;
  StartupCost c;
  for (int r = 0; r < runs; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    const util::ProgramEnd end = util::run_program_measured(argv, o);
    ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    if (end.exit_code != 0)
      throw std::runtime_error("bench startup: `" + argv[1] + "` exited with " +
                               std::to_string(end.exit_code));
    c.peak_mib = std::max(c.peak_mib, end.peak_resident_mib);
  }
  std::nth_element(ms.begin(), ms.begin() + runs / 2, ms.end());
  c.median_ms = ms[static_cast<std::size_t>(runs / 2)];
  return c;
}

}  // namespace

int run_startup_bench(const std::string& shared_data, bool quick) {
  const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
  const int runs = quick ? 15 : 51;
  const std::vector<std::string> eager_osmesa{"LD_PRELOAD=libOSMesa.so.8"};
  struct Case {
    std::string name;
    std::vector<std::string> argv;
  };
  const std::vector<Case> cases{
      {"version", {self, "--version"}},
      {"plan_world_N200", {self, "plan", shared_data + "/worlds/world_N200.json"}},
  };
  for (const Case& c : cases) {
    const StartupCost now = measure(c.argv, {}, runs);
    const StartupCost eager = measure(c.argv, eager_osmesa, runs);
    report("startup", {c.name + "_ms", now.median_ms, "ms"},
           Measure{c.name + "_ms_osmesa_loaded_at_start", eager.median_ms, "ms"});
    report("startup", {c.name + "_peak_mib", now.peak_mib, "MiB"},
           Measure{c.name + "_peak_mib_osmesa_loaded_at_start", eager.peak_mib, "MiB"});
  }
  return 0;
}

}  // namespace plantsim::bench
