// Timing the controllers' cycles (see the header). Each controller drives a unicycle along the
// same plan from the same start, so the cycles timed are those of a drive, not of a standstill.
#include "bench/controller_bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <vector>

#include "bench/bench_report.h"
#include "controller/dwb/dwb_planner.h"
#include "controller/mppi/mppi_optimizer.h"
#include "controller/pure_pursuit.h"
#include "controller/sampling_follow.h"
#include "planner/planner.h"
#include "planner/registry.h"
#include "worlds/world.h"
#include "worlds/world_loader.h"

namespace plantsim::bench {
namespace {

using Clock = std::chrono::steady_clock;

struct CycleTimes {
  double median_ms = 0, p99_ms = 0;
};

/// Drives a unicycle from `start` for `cycles` control periods of 0.05 s with `control`,
/// timing each call.
CycleTimes time_cycles(
    int cycles, geom::Pose2 start,
    const std::function<controller::Twist(const geom::Pose2&, double)>& control) {
  std::vector<double> ms;
  geom::Pose2 pose = start;
  double v = 0;
  for (int i = 0; i < cycles; ++i) {
    const auto t0 = Clock::now();
    const controller::Twist u = control(pose, v);
    ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    pose.x += u.v_mps * std::cos(pose.yaw) * 0.05;
    pose.y += u.v_mps * std::sin(pose.yaw) * 0.05;
    pose.yaw += u.omega_radps * 0.05;
    v = u.v_mps;
  }
  std::sort(ms.begin(), ms.end());
  return {ms[ms.size() / 2], ms[std::min(ms.size() - 1, ms.size() * 99 / 100)]};
}

}  // namespace

int run_controller_bench(const std::string& shared_data, bool quick) {
  const worlds::World world = worlds::load_world(shared_data + "/worlds/world_N200.json");
  auto vg = planner::make_planner("vg", planner::planner_input(world, true));
  const planner::PlanResult plan =
      vg->plan(world.start.position(), worlds::staging_pose(world).position());
  if (plan.path.size() < 2) throw std::runtime_error("bench controllers: world_N200 has no plan");
  const int cycles = quick ? 60 : 400;

  controller::PurePursuit rpp(controller::PurePursuitParams{}, plan.path);
  controller::PurePursuit rpp_again = rpp;  // for the clearance field's drive, below
  const CycleTimes rpp_t = time_cycles(
      cycles, world.start, [&](const geom::Pose2& p, double v) { return rpp.step(p, v).twist; });
  const Measure rpp_median{"rpp_cycle_median", rpp_t.median_ms, "ms"};
  report("controllers", rpp_median);
  report("controllers", {"rpp_cycle_p99", rpp_t.p99_ms, "ms"});

  // MPPI's clearance field: a 6 m window around the robot, made afresh each cycle as the
  // robot's local layer would be (its cost counted with the cycle's), out to the reach the
  // controllers ask of it (their inflation beyond the footprint).
  const double reach = controller::field_reach(world.robot.radius_m, 0.55);
  controller::mppi::MppiOptimizer mppi({}, {}, 1);
  mppi.set_path(plan.path);
  const geom::Pose2 goal = worlds::staging_pose(world);
  const CycleTimes mppi_t = time_cycles(cycles, world.start, [&](const geom::Pose2& p, double v) {
    const controller::ClearanceGrid grid(p.position(), 3.0, 0.05, world.obstacles, world.floor,
                                         reach);
    controller::mppi::RobotState s{static_cast<float>(p.x), static_cast<float>(p.y),
                                   static_cast<float>(p.yaw), static_cast<float>(v), 0.0f};
    return mppi.step({s, goal, &grid, static_cast<float>(world.robot.radius_m)});
  });
  report("controllers", {"mppi_2000x56_cycle_median", mppi_t.median_ms, "ms"}, rpp_median);
  report("controllers", {"mppi_2000x56_cycle_p99", mppi_t.p99_ms, "ms"}, rpp_median);

  controller::dwb::DwbPlanner dwb({});
  dwb.set_path(plan.path);
  double omega = 0;
  const CycleTimes dwb_t = time_cycles(cycles, world.start, [&](const geom::Pose2& p, double v) {
    const controller::ClearanceGrid grid(p.position(), 3.0, 0.05, world.obstacles, world.floor,
                                         reach);
    const controller::Twist u = dwb.step({p, {v, omega}, goal, &grid, world.robot.radius_m});
    omega = u.omega_radps;
    return u;
  });
  report("controllers", {"dwb_20x20_cycle_median", dwb_t.median_ms, "ms"}, rpp_median);
  report("controllers", {"dwb_20x20_cycle_p99", dwb_t.p99_ms, "ms"}, rpp_median);

  // Of each MPPI and DWB cycle above: the clearance field alone, on the same drive as RPP's.
  volatile float sink = 0;  // the field is read, so it is built
  const CycleTimes grid_t = time_cycles(cycles, world.start, [&](const geom::Pose2& p, double v) {
    const controller::ClearanceGrid grid(p.position(), 3.0, 0.05, world.obstacles, world.floor,
                                         reach);
    sink = grid.at(static_cast<float>(p.x), static_cast<float>(p.y));
    return rpp_again.step(p, v).twist;
  });
  report("controllers", {"clearance_grid_6m_cycle_median", grid_t.median_ms, "ms"}, rpp_median);
  return 0;
}

}  // namespace plantsim::bench
