// Timing a plugin's calls against the same code built in (see the header). The drive is recorded
// once (the built-in Stanley steering a unicycle along a plan); both then answer exactly those
// queries, in alternating rounds, so that the machine's drift falls on both alike.
#include "bench/plugin_bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <stdexcept>
#include <vector>

#include "bench/bench_report.h"
#include "bench/sample_median.h"
#include "controller/local_controller_registry.h"
#include "examples/plugin/stanley_controller.h"
#include "planner/registry.h"
#include "plugins/guarded_components.h"
#include "util/component_failure.h"
#include "worlds/world.h"
#include "worlds/world_loader.h"

namespace plantsim::bench {
namespace {

using Clock = std::chrono::steady_clock;

/// The queries of a drive along `path`: a unicycle steered by `c` for `cycles` periods of 1/30 s.
std::vector<controller::LocalQuery> recorded_drive(controller::LocalController& c,
                                                   const std::vector<geom::Vec2>& path,
                                                   geom::Pose2 start, int cycles) {
  std::vector<controller::LocalQuery> out;
  c.set_path(path);
  geom::Pose2 pose = start;
  double v = 0;
  const double dt = 1.0 / 30;
  for (int i = 0; i < cycles; ++i) {
    controller::LocalQuery q{pose, v, 0.0, dt, nullptr};
    out.push_back(q);
    const controller::TrackingCommand t = c.step(q);
    if (t.goal_reached) break;
    pose.x += t.twist.v_mps * std::cos(pose.yaw) * dt;
    pose.y += t.twist.v_mps * std::sin(pose.yaw) * dt;
    pose.yaw += t.twist.omega_radps * dt;
    v = t.twist.v_mps;
  }
  return out;
}

/// Nanoseconds per call of a fresh controller of `entry` answering every query, and a checksum of
/// its answers (both must steer alike: the same code).
double ns_per_call(const controller::LocalControllerEntry& entry,
                   const std::vector<geom::Vec2>& path,
                   const std::vector<controller::LocalQuery>& drive, double& checksum) {
  auto c = entry.make({}, util::defaults_of(entry.params));
  c->set_path(path);
  double sum = 0;
  const auto t0 = Clock::now();
  for (const controller::LocalQuery& q : drive) {
    try {  // as the path follower calls it (controller/path_follower.cpp)
      sum += c->step(q).twist.omega_radps;
    } catch (...) {
      if (c->plugin_origin().empty()) throw;
      util::rethrow_as_component_failure(c->plugin_origin());
    }
  }
  const double ns = std::chrono::duration<double, std::nano>(Clock::now() - t0).count();
  checksum = sum;
  return ns / static_cast<double>(drive.size());
}

}  // namespace

int run_plugin_bench(const std::string& shared_data, bool quick) {
  const controller::LocalControllerEntry* plugin = controller::local_controllers().find("stanley");
  if (!plugin || plugin->origin == "built-in") {
    std::cerr << "plantsim: bench plugins: no plugin registered \"stanley\": give the example "
                 "plugin with --plugin (examples/plugin, docs/plugins.md)\n";
    return 2;
  }
  const controller::LocalControllerEntry built_in = example::stanley_entry();
  const worlds::World world = worlds::load_world(shared_data + "/worlds/world_N200.json");
  auto vg = planner::make_planner("vg", planner::planner_input(world, true));
  const planner::PlanResult plan =
      vg->plan(world.start.position(), worlds::staging_pose(world).position());
  if (plan.path.size() < 2) throw std::runtime_error("bench plugins: world_N200 has no plan");
  auto driver = built_in.make({}, util::defaults_of(built_in.params));
  const std::vector<controller::LocalQuery> drive =
      recorded_drive(*driver, plan.path, world.start, 20000);
  const int rounds = quick ? 5 : 41;
  // The built-in copy made through the same guarded factory a plugin's parts get
  // (plugins/guarded_components.h): what the guard costs, apart from where the code was compiled.
  const controller::LocalControllerEntry guarded = plugins::guarded(built_in, "the bench");
  std::vector<double> in_tree, in_guard, loaded;
  double sum_in = 0, sum_guard = 0, sum_loaded = 0;
  for (int r = 0; r < rounds; ++r) {
    in_tree.push_back(ns_per_call(built_in, plan.path, drive, sum_in));
    in_guard.push_back(ns_per_call(guarded, plan.path, drive, sum_guard));
    loaded.push_back(ns_per_call(*plugin, plan.path, drive, sum_loaded));
  }
  if (sum_in != sum_loaded)
    throw std::runtime_error(
        "bench plugins: the plugin's stanley steers otherwise than the "
        "built-in copy: not the same code");
  const Measure base{"stanley_built_in_step", median(in_tree), "ns"};
  report("plugins", base);
  report("plugins", {"stanley_built_in_guarded_step", median(in_guard), "ns"}, base);
  report("plugins", {"stanley_plugin_step", median(loaded), "ns"}, base);
  return 0;
}

}  // namespace plantsim::bench
