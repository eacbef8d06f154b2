// Render timings; the baseline of every case is "render only" at the same supersampling.
#include "bench/render_bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "bench/bench_report.h"
#include "render/gl_canvas.h"
#include "render/layers.h"
#include "render/palette.h"
#include "render/png_io.h"
#include "render/png_pipeline.h"
#include "render/run_figure.h"
#include "worlds/world_loader.h"

namespace plantsim::bench {
namespace {

using Clock = std::chrono::steady_clock;

/// Frames per second of `frames` runs of body, the best of three tries after a warm-up (the
/// first call compiles llvmpipe's shaders).
template <class Body>
double best_fps(int frames, Body&& body) {
  body();
  double best = 1e9;
  for (int r = 0; r < 3; ++r) {
    const auto t0 = Clock::now();
    for (int i = 0; i < frames; ++i) body();
    best = std::min(best, std::chrono::duration<double>(Clock::now() - t0).count() / frames);
  }
  return 1.0 / best;
}

/// A 2000-point trajectory across the floor: a slow wave from the start to the charger, with a
/// plan point every 100.
void wave_trajectory(const worlds::World& w, std::vector<episode::TrajectorySample>& traj,
                     std::vector<geom::Vec2>& plan) {
  for (int i = 0; i < 2000; ++i) {
    const double f = i / 1999.0;
    const geom::Vec2 p = w.start.position() + f * (w.charger.position() - w.start.position()) +
                         geom::Vec2{0, 3.0 * std::sin(12 * f)};
    traj.push_back({0.1 * i,
                    {p.x, p.y, 0},
                    {p.x, p.y, 0},
                    0,
                    0.6 * std::fabs(std::sin(5 * f)),
                    0,
                    controller::DockPhase::kTravel,
                    false,
                    {}});
    if (i % 100 == 0) plan.push_back(p);
  }
}

/// The bare layers at 1280 x 720 with `ss` x `ss` supersampling: drawn, read back, encoded.
void bench_layers(const worlds::World& w, const std::vector<episode::TrajectorySample>& traj,
                  const std::vector<geom::Vec2>& plan, int ss, int frames) {
  render::GlCanvas canvas(1280, 720, ss);
  canvas.set_transform(render::PixelTransform::fit(w.floor, 10, 10, 1270, 710, 720));
  auto draw = [&]() {
    canvas.clear(render::palette::kBackground);
    render::draw_floor(canvas, w);
    render::draw_obstacles(canvas, w);
    render::draw_plan(canvas, plan, render::palette::kPlan);
    render::draw_trajectory_by_speed(canvas, traj, w.robot.max_speed_mps);
    render::draw_start(canvas, w);
    render::draw_charger(canvas, w);
    render::draw_footprint(canvas, w.robot, traj.back().truth, render::palette::kRobot);
  };
  auto fps = [&](auto&& body) { return best_fps(frames, body); };
  const std::string tag = "1280x720_N1000_2000pts_ss" + std::to_string(ss);
  const Measure render_only{tag + "/render_only_fps", fps([&] {
                              draw();
                              canvas.finish();
                            }),
                            "frames/s"};
  report("render", render_only);
  report("render",
         {tag + "/render_readback_fps", fps([&] {
            draw();
            (void)canvas.read();
          }),
          "frames/s"},
         render_only);
  report("render",
         {tag + "/render_png_default_fps", fps([&] {
            draw();
            (void)render::encode_png(canvas.read());
          }),
          "frames/s"},
         render_only);
  report("render",
         {tag + "/render_png_fast_fps", fps([&] {
            draw();
            (void)render::encode_png(canvas.read(), render::PngSettings::fast());
          }),
          "frames/s"},
         render_only);
  // Frame sequences (animations): the next frame is drawn while the last is encoded.
  {
    auto pipelined = [&] {
      render::PngPipeline pipe(render::PngSettings::fast(), 2,
                               [](const std::string&, const std::string&) {});
      for (int i = 0; i < frames; ++i) {
        draw();
        pipe.push(canvas.read(), "");
      }
      pipe.close();
    };
    report("render",
           {tag + "/render_png_fast_pipelined_fps", frames * best_fps(1, pipelined), "frames/s"},
           render_only);
  }
}

/// The whole run figure as `plantsim run` writes it (layers, legend, text, docking close-up),
/// encoded by the pipeline: its baseline is the bare layers at the same size.
void bench_run_figure(const worlds::World& w, const std::vector<episode::TrajectorySample>& traj,
                      const std::vector<geom::Vec2>& plan, int frames) {
  episode::EpisodeResult run;
  run.status = episode::EpisodeStatus::kDocked;
  run.trajectory = traj;
  run.plan = plan;
  run.first_plan = plan;
  run.error_measured = true;
  run.measured_pose = traj.back().truth;
  render::RunFigureOptions o;
  o.width_px = 1280;
  o.height_px = 720;
  auto figures = [&] {
    render::PngPipeline pipe(render::PngSettings::fast(), 2,
                             [](const std::string&, const std::string&) {});
    for (int i = 0; i < frames; ++i) pipe.push(render::draw_run_figure(w, run, o), "");
    pipe.close();
  };
  const Measure target{"target_fps", 100.0, "frames/s"};
  report("render",
         {"1280x720_N1000_2000pts/run_figure_png_fast_pipelined_fps", frames * best_fps(1, figures),
          "frames/s"},
         target);
  // The two halves the pipeline overlaps, each alone: the pipeline cannot beat the slower,
  // and on two cores both share them with llvmpipe's rasterizer threads.
  const render::Image figure = render::draw_run_figure(w, run, o);
  report("render",
         {"1280x720_N1000_2000pts/run_figure_draw_only_fps",
          best_fps(frames, [&] { (void)render::draw_run_figure(w, run, o); }), "frames/s"},
         target);
  report("render",
         {"1280x720_N1000_2000pts/run_figure_png_fast_encode_only_fps",
          best_fps(frames, [&] { (void)render::encode_png(figure, render::PngSettings::fast()); }),
          "frames/s"},
         target);
}

}  // namespace

int run_render_bench(const std::string& shared_data, bool quick) {
  const worlds::World w = worlds::load_world(shared_data + "/worlds/world_N1000.json");
  std::vector<episode::TrajectorySample> traj;
  std::vector<geom::Vec2> plan;
  wave_trajectory(w, traj, plan);
  const int frames = quick ? 10 : 40;
  for (int ss : {1, 2}) bench_layers(w, traj, plan, ss, frames);
  bench_run_figure(w, traj, plan, frames);
  return 0;
}

}  // namespace plantsim::bench
