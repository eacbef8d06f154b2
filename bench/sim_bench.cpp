// Steps per second, best of several repetitions (the least disturbed by the machine).
#include "bench/sim_bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "bench/bench_report.h"
#include "planner/planner.h"
#include "sim/episode.h"
#include "sim/physics_world.h"
#include "sim/wheel_drive.h"
#include "worlds/world_loader.h"

namespace plantsim::bench {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

}  // namespace

int run_sim_bench(const std::string& shared_data, bool quick) {
  const int reps = quick ? 2 : 5;
  for (int n : {10, 200, 1000}) {
    std::string count = std::to_string(n);
    const std::string name = std::string("N").append(count);
    const worlds::World w = worlds::load_world(shared_data + "/worlds/world_N" + count + ".json");
    auto planner = planner::make_planner("vg", planner::planner_input(w, true));
    sim::EpisodeConfig config;

    // Whole episodes; the planning time (measured alone) is taken out to count steps only.
    double best_full = 0, best_with_plan = 0;
    std::size_t steps = 0;
    for (int r = 0; r < reps; ++r) {
      auto fresh = planner::make_planner("vg", planner::planner_input(w, true));
      const auto tp = Clock::now();
      fresh->plan(w.start.position(), worlds::staging_pose(w).position());
      const double plan_s = seconds_since(tp);
      auto for_episode = planner::make_planner("vg", planner::planner_input(w, true));
      const auto t0 = Clock::now();
      const sim::EpisodeResult e = sim::run_episode(w, *for_episode, config);
      const double total = seconds_since(t0);
      steps = static_cast<std::size_t>(e.physics_steps);
      best_full = std::max(best_full, steps / std::max(total - plan_s, 1e-9));
      best_with_plan = std::max(best_with_plan, steps / total);
      if (!e.docked) {
        std::cerr << "bench sim: episode on " << name << " did not dock\n";
        return 1;
      }
    }

    // Bare Box2D: the same world and robot body, awake and driven round a slow circle by
    // setting its velocity directly each step; then the same with the tyre model instead.
    double best_bare = 0, best_drive = 0;
    for (int r = 0; r < reps; ++r) {
      sim::PhysicsWorld bare(w);
      const auto t0 = Clock::now();
      for (std::size_t k = 0; k < steps; ++k) {
        const double yaw = w.start.yaw + 0.2 * k * config.step.dt_s;
        bare.set_robot_velocity({0.1 * std::cos(yaw), 0.1 * std::sin(yaw)}, 0.2);
        bare.step(config.step);
      }
      best_bare = std::max(best_bare, steps / seconds_since(t0));
      sim::PhysicsWorld driven(w);
      sim::WheelDrive drive(w.robot, config.drive);
      const auto t1 = Clock::now();
      for (std::size_t k = 0; k < steps; ++k) {
        drive.command({0.1 - 0.1 * w.robot.wheel_base_m, 0.1 + 0.1 * w.robot.wheel_base_m}, config.step.dt_s);  // same circle
        drive.apply(driven, config.step.dt_s);
        driven.step(config.step);
      }
      best_drive = std::max(best_drive, steps / seconds_since(t1));
    }
    const Measure bare{name + "/bare_box2d_steps_per_s", best_bare, "steps/s"};
    report("sim", bare);
    report("sim", {name + "/box2d_with_wheel_model_steps_per_s", best_drive, "steps/s"}, bare);
    report("sim", {name + "/episode_steps_per_s", best_full, "steps/s"}, bare);
    report("sim", {name + "/episode_steps_per_s_including_planning", best_with_plan, "steps/s"}, bare);
  }
  return 0;
}

}  // namespace plantsim::bench
