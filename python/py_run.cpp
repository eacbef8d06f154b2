// plantsim.run: one episode as `plantsim run` makes it, optionally steered by a Python
// controller that sees only the robot's perception (plantsim.Observation).
#include <pybind11/stl.h>

#include <atomic>
#include <cmath>
#include <memory>

#include "app/episode_outputs.h"
#include "batch/random_start.h"
#include "episode/episode_config.h"
#include "episode/episode_config_json.h"
#include "episode/episode_result.h"
#include "episode/run_episode.h"
#include "planner/planner.h"
#include "planner/registry.h"
#include "python/py_arguments.h"
#include "python/py_bindings.h"
#include "python/py_interrupt.h"
#include "python/py_world.h"
#include "robot/travel_steered.h"
#include "util/atomic_file.h"
#include "worlds/world_fingerprint.h"
#include "worlds/world_loader.h"

namespace plantsim::python {
namespace {

/// What a Python controller is given: a copy of the robot's perception at one control period
/// (never the simulator's truth), with plantsim's plan, phase and own command.
struct Observation {
  robot::Perception perception;
  std::vector<geom::Vec2> plan;
  controller::DockPhase phase;
  controller::Twist builtin;
  geom::Pose2 staging;
};

py::array_t<double> scan_angles(const robot::LidarScan& s) {
  py::array_t<double> a(static_cast<py::ssize_t>(s.ranges.size()));
  auto v = a.mutable_unchecked<1>();
  for (std::size_t i = 0; i < s.ranges.size(); ++i)
    v(static_cast<py::ssize_t>(i)) = s.mount.yaw + s.angle(i);
  return a;
}

py::array_t<double> covariance_matrix(const Observation& o) {
  py::array_t<double> a({3, 3});
  auto v = a.mutable_unchecked<2>();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      v(i, j) = o.perception.pose_covariance[static_cast<std::size_t>(3 * i + j)];
  return a;
}

py::array_t<double> tracked_obstacles(const Observation& o) {
  py::array_t<double> a({static_cast<py::ssize_t>(o.perception.obstacles.size()), py::ssize_t{6}});
  auto v = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < o.perception.obstacles.size(); ++i) {
    const auto& b = o.perception.obstacles[i];
    const auto k = static_cast<py::ssize_t>(i);
    v(k, 0) = b.box.xmin, v(k, 1) = b.box.ymin, v(k, 2) = b.box.xmax, v(k, 3) = b.box.ymax;
    v(k, 4) = b.velocity.x, v(k, 5) = b.velocity.y;
  }
  return a;
}

void bind_observation(py::module_& m) {
  py::class_<Observation, std::shared_ptr<Observation>>(
      m, "Observation",
      "What the robot perceives at one control period (the estimate, never the truth).")
      .def_property_readonly(
          "time", [](const Observation& o) { return o.perception.t_s; }, "seconds since the start")
      .def_property_readonly(
          "pose", [](const Observation& o) { return pose_array(o.perception.pose); },
          "estimated [x, y, yaw] in the map frame")
      .def_property_readonly("covariance", &covariance_matrix, "3 x 3 covariance of (x, y, yaw)")
      .def_property_readonly("position_sigma",
                             [](const Observation& o) { return o.perception.position_sigma_m; })
      .def_property_readonly(
          "health",
          [](const Observation& o) { return std::string(robot::to_string(o.perception.health)); },
          "the estimator's own verdict: ok, degraded or lost")
      .def_property_readonly(
          "velocity",
          [](const Observation& o) {
            return py::make_tuple(o.perception.speed_mps, o.perception.yaw_rate_radps);
          },
          "(forward speed from the encoders m/s, yaw rate from the gyro rad/s)")
      .def_property_readonly(
          "scan_ranges",
          [](const std::shared_ptr<Observation>& o) {
            if (!o->perception.scan) return py::array_t<double>(0);
            // A read-only view of the observation's own ranges (no copy: a copy through a list
            // took 15 to 40 us a read), keeping the observation alive while it is held.
            const std::vector<double>& r = o->perception.scan->ranges;
            py::array_t<double> a({static_cast<py::ssize_t>(r.size())},
                                  {static_cast<py::ssize_t>(sizeof(double))}, r.data(),
                                  py::cast(o));
            py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
            return a;
          },
          "the newest lidar scan's ranges, read-only (NaN: dropout; max range: nothing there)")
      .def_property_readonly(
          "scan_time",
          [](const Observation& o) { return o.perception.scan ? o.perception.scan->t_s : NAN; },
          "when the newest scan was taken, s (the same value again: the same scan; NaN: none yet)")
      .def_property_readonly(
          "scan_angles",
          [](const Observation& o) {
            return o.perception.scan ? scan_angles(*o.perception.scan) : py::array_t<double>(0);
          },
          "each beam's angle in the robot frame, radians")
      .def_property_readonly("scan_max_range",
                             [](const Observation& o) {
                               return o.perception.scan ? o.perception.scan->max_range_m : 0.0;
                             })
      .def_property_readonly(
          "plan", [](const Observation& o) { return points_array(o.plan); },
          "N x 2 plan plantsim holds now (replanned around what was sensed)")
      .def_property_readonly(
          "staging", [](const Observation& o) { return pose_array(o.staging); },
          "the staging pose on the map: docking takes over within the goal tolerance of it")
      .def_property_readonly(
          "obstacles", &tracked_obstacles,
          "N x 6 tracked obstacles off the map: [xmin, ymin, xmax, ymax, vx, vy]")
      .def_property_readonly(
          "charger",
          [](const Observation& o) -> py::object {
            if (!o.perception.charger_in_robot) return py::none();
            return pose_array(*o.perception.charger_in_robot);
          },
          "the docked pose as the charger detector saw it, robot frame [x, y, yaw], or None")
      .def_property_readonly("charging", [](const Observation& o) { return o.perception.charging; })
      .def_property_readonly("bumper",
                             [](const Observation& o) { return o.perception.bumper.pressed(); })
      .def_property_readonly(
          "phase", [](const Observation& o) { return std::string(controller::to_string(o.phase)); },
          "plantsim's phase: travel, align, approach, back_off, ...")
      .def_property_readonly(
          "builtin",
          [](const Observation& o) {
            return py::make_tuple(o.builtin.v_mps, o.builtin.omega_radps);
          },
          "(v, omega) plantsim's own controller would command now");
}

/// A Python callable as a steering: (v, omega) or None (plantsim's command this period). The
/// episode may run on any thread: the GIL is taken around the call and every Python object.
robot::Steering steering_of(py::object callable, const std::string& role) {
  if (callable.is_none()) return {};
  if (!PyCallable_Check(callable.ptr()))
    throw py::type_error(role + " must be callable: f(observation) -> (v, omega) or None");
  return [f = share_across_threads(std::move(callable)),
          role](const robot::SteeringInput& in) -> std::optional<controller::Twist> {
    py::gil_scoped_acquire gil;
    auto o = std::make_shared<Observation>(
        Observation{in.perception, in.plan, in.phase, in.builtin.twist, in.staging});
    const py::object out = (*f)(o);
    if (out.is_none()) return std::nullopt;
    double v = NAN, w = NAN;
    const auto at = " at t = " + std::to_string(in.perception.t_s) + " s";
    try {
      const auto pair = out.cast<std::pair<double, double>>();
      v = pair.first, w = pair.second;
    } catch (const py::cast_error&) {
      throw std::invalid_argument(role + " returned " + py::repr(out).cast<std::string>() + at +
                                  "; expected (v m/s, omega rad/s) or None");
    }
    if (!std::isfinite(v) || !std::isfinite(w))
      throw std::invalid_argument(role + " returned a non-finite command (" + std::to_string(v) +
                                  ", " + std::to_string(w) + ")" + at);
    return controller::Twist{v, w};
  };
}

struct PyRun {
  py::object summary;
  py::array_t<double> trajectory;
  std::vector<std::string> columns;
  std::string status;
  bool docked = false;
};

const std::vector<std::string>& trajectory_columns() {
  static const std::vector<std::string> c = {
      "t_s",         "x_m",         "y_m",       "yaw_rad",       "est_x_m", "est_y_m",
      "est_yaw_rad", "est_sigma_m", "speed_mps", "cross_track_m", "phase",   "wall_following",
      "target_x_m",  "target_y_m",  "est_status"};
  return c;
}

py::array_t<double> trajectory_array(const episode::EpisodeResult& r) {
  py::array_t<double> a({static_cast<py::ssize_t>(r.trajectory.size()),
                         static_cast<py::ssize_t>(trajectory_columns().size())});
  auto v = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < r.trajectory.size(); ++i) {
    const episode::TrajectorySample& s = r.trajectory[i];
    const double row[] = {s.t_s,
                          s.truth.x,
                          s.truth.y,
                          s.truth.yaw,
                          s.estimate.x,
                          s.estimate.y,
                          s.estimate.yaw,
                          s.position_sigma_m,
                          s.speed_mps,
                          s.cross_track_m,
                          static_cast<double>(s.phase),
                          s.wall_following ? 1.0 : 0.0,
                          s.target.x,
                          s.target.y,
                          static_cast<double>(s.health)};
    for (std::size_t c = 0; c < std::size(row); ++c)
      v(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(c)) = row[c];
  }
  return a;
}

}  // namespace

episode::EpisodeConfig config_argument(const py::handle& config) {
  if (config.is_none()) return {};
  if (py::isinstance<py::dict>(config))
    return episode::parse_episode_config(to_json_text(config), "<config dict>");
  if (py::isinstance<py::str>(config) || py::hasattr(config, "__fspath__"))
    return episode::load_episode_config(file_from(config, "config"));
  throw py::type_error("config must be a dict or the path of a config file (docs/config.md), got " +
                       py::str(py::type::of(config).attr("__name__")).cast<std::string>());
}

episode::EpisodeSteering steering_argument(const py::object& controller, const py::object& docking,
                                           const std::string& name) {
  if (controller.is_none() && docking.is_none()) return {};
  if (name.empty() || name.find_first_of("|/\\\n\"") != std::string::npos)
    throw std::invalid_argument("controller_name '" + name +
                                "' must be non-empty, without | / \\ or quotes");
  episode::EpisodeSteering s;
  s.name = name;
  s.wrap = [travel = steering_of(controller, "controller"), dock = steering_of(docking, "docking")](
               std::unique_ptr<robot::Travel> builtin, const worlds::World& map,
               const std::vector<geom::Vec2>& first_plan) {
    // Made on the episode's thread, kept by the steerings and released with the travel at the
    // episode's end on the same thread: one Python thread state per episode, not per call.
    auto state = std::make_shared<PythonThreadState>();
    auto kept = [state](const robot::Steering& f) -> robot::Steering {
      if (!f) return {};
      return [f, state](const robot::SteeringInput& in) { return f(in); };
    };
    return robot::steered_by(std::move(builtin), map, first_plan, kept(travel), kept(dock));
  };
  return s;
}

std::string callable_name(const py::object& f) {
  if (f.is_none()) return "";
  return py::hasattr(f, "__name__") ? py::str(f.attr("__name__")).cast<std::string>()
                                    : py::str(py::type::of(f).attr("__name__")).cast<std::string>();
}

namespace {

/// The world with the start `start` asks for: its own ("world"), the batch's for this seed
/// ("random"), or a pose [x, y, yaw].
PyWorld with_start(const PyWorld& w, const py::object& start, std::uint64_t seed) {
  if (py::isinstance<py::str>(start)) {
    const std::string how = start.cast<std::string>();
    if (how == "world") return w;
    if (how != "random")
      throw std::invalid_argument("start must be \"world\", \"random\" or [x, y, yaw], got '" +
                                  how + "'");
    auto vg = planner::make_planner("vg", planner::planner_input(*w.world, true));
    const auto pose = batch::random_start(*w.world, *vg, seed, worlds::world_fingerprint(*w.world));
    if (!pose)
      throw std::invalid_argument(w.world->name + ": no free start with a path to the charger");
    auto moved = std::make_shared<worlds::World>(*w.world);
    moved->start = *pose;
    return {moved};
  }
  geom::Pose2 pose;
  try {
    pose = pose_from(start, "start");  // the world files' limits: |yaw| <= 100 rad, ...
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(
        std::string("start must be \"world\", \"random\" or [x, y, yaw]: ") + e.what());
  }
  auto moved = std::make_shared<worlds::World>(*w.world);
  moved->start = pose;
  worlds::validate_world(*moved);  // a start in an obstacle or off the floor is refused
  return {moved};
}

PyRun run(const py::handle& world_arg, const py::object& seed_arg, const py::object& config_arg,
          const py::object& controller, const py::object& docking, const std::string& planner_name,
          const py::object& out, const std::string& controller_name, const py::object& start) {
  const std::uint64_t seed = seed_from(seed_arg, "seed");
  const PyWorld w = with_start(world_argument(world_arg), start, seed);
  episode::EpisodeConfig config = config_argument(config_arg);
  config.seed = seed;
  const std::vector<std::string> names = planner::planner_names();
  if (std::find(names.begin(), names.end(), planner_name) == names.end())
    throw std::invalid_argument("unknown planner '" + planner_name +
                                "' (plantsim.planners() lists them)");
  const std::string name =
      controller_name.empty()
          ? "python:" + callable_name(controller.is_none() ? docking : controller)
          : controller_name;
  const episode::EpisodeSteering steering = steering_argument(controller, docking, name);
  std::unique_ptr<util::StagedFolder> staged;  // checked before the run, as `plantsim run` does
  if (!out.is_none())
    staged = std::make_unique<util::StagedFolder>(path_from(out, "out"), app::run_folder_names());
  auto p = planner::make_planner(planner_name, planner::planner_input(*w.world, true));
  const std::string line = "plantsim.run('" + w.world->source + "', seed=" + std::to_string(seed) +
                           (steering ? ", controller=" + steering.name : "") + ")";
  // The episode runs off the GIL (other Python threads run meanwhile); the controller takes it
  // for each call. Ctrl-C stops it within a control period.
  std::atomic<bool> stop{false};
  episode::EpisodeSteering hooks = steering;
  hooks.interrupted = [&stop] { return stop.load(std::memory_order_relaxed); };
  episode::EpisodeResult r;
  Interruptible done =
      run_interruptibly([&] { r = episode::run_episode(*w.world, *p, config, hooks); }, stop);
  if (done.failure) {
    try {
      std::rethrow_exception(done.failure);
    } catch (episode::EpisodeStopped& stopped) {
      const episode::EpisodeResult& part = stopped.partial;
      const py::object partial = py::cast(PyRun{
          from_json_text(app::summary_json(part, w.world->name, line)), trajectory_array(part),
          trajectory_columns(), episode::status_name(part), part.docked});
      // A controller's exception keeps what was driven, as a folder of the run so far; Ctrl-C
      // answers at once (figures take a while) and leaves the folder as it was.
      if (staged && !done.signal) {
        app::write_run_folder(*w.world, part, config, staged->path(), line,
                              "stopped at " + std::to_string(stopped.time_s) + " s", false);
        staged->commit();
      }
      py::error_already_set error = done.signal ? *done.signal : python_error_of(stopped.cause);
      raise_with_partial(error, partial, stopped.time_s);
    }
  }
  if (done.signal) {  // the episode ended by itself as the key was pressed: still interrupted
    done.signal->restore();
    throw py::error_already_set();
  }
  PyRun result{from_json_text(app::summary_json(r, w.world->name, line)), trajectory_array(r),
               trajectory_columns(), episode::status_name(r), r.docked};
  if (staged) {
    app::write_run_folder(*w.world, r, config, staged->path(), line,
                          steering ? "steered by " + steering.name : "", false);
    staged->commit();
  }
  return result;
}

}  // namespace

void bind_run(py::module_& m) {
  bind_observation(m);
  py::class_<PyRun>(
      m, "Run",
      "One episode: .summary (summary.json as a dict), .trajectory (rows of trajectory.csv).")
      .def_readonly("summary", &PyRun::summary)
      .def_readonly("trajectory", &PyRun::trajectory,
                    "one row per control period; phase as its index in PHASES")
      .def_readonly("columns", &PyRun::columns)
      .def_readonly("status", &PyRun::status)
      .def_readonly("docked", &PyRun::docked)
      .def("__repr__", [](const PyRun& r) { return "<plantsim.Run " + r.status + ">"; })
      .def(py::pickle(
          [](const PyRun& r) {
            return py::make_tuple(r.summary, r.trajectory, r.columns, r.status, r.docked);
          },
          [](const py::tuple& t) {
            if (t.size() != 5) throw std::invalid_argument("not a pickled plantsim.Run");
            return PyRun{t[0], t[1].cast<py::array_t<double>>(),
                         t[2].cast<std::vector<std::string>>(), t[3].cast<std::string>(),
                         t[4].cast<bool>()};
          }));
  m.attr("PHASES") = py::make_tuple("travel", "align", "approach", "back_off", "docked", "undock",
                                    "undocked", "failed");
  m.def("run", &run, py::arg("world"), py::kw_only(), py::arg("seed") = 1,
        py::arg("config") = py::none(), py::arg("controller") = py::none(),
        py::arg("docking") = py::none(), py::arg("planner") = "vg", py::arg("out") = py::none(),
        py::arg("controller_name") = "", py::arg("start") = "world",
        R"(Simulates one docking episode, as `plantsim run WORLD` does.

world: a World or a world file's path. seed: the noise seed. start: "world" (the world's own
start, the default), "random" (the start `plantsim batch` draws for this world and seed: the
same episode as the batch's with `starts: random`), or [x, y, yaw]. config: a dict or a JSON file with
the keys of docs/config.md. planner: a name from planners().
controller: f(observation) -> (v m/s, omega rad/s), or None to let plantsim command that period;
called at the control rate (config control_period_steps, 30 Hz by default) while plantsim's phase
is "travel", in place of its path following. plantsim's own travel runs beside it as the referee:
it keeps the plan (observation.plan, replanned around what is sensed), hands over to the docking
manoeuvre within the goal tolerance of the staging pose, and judges docked or failed.
docking: the same for the docking phases (align, approach, back off); None: plantsim's manoeuvre.
controller_name: recorded in the summary as "steered_by" (default "python:" + the callable's name).
out: also write the folder `plantsim run --out` writes (summary.json, trajectory.csv, figures).
The episode runs with the GIL released (other Python threads run meanwhile; the controller takes
the GIL for each call). Ctrl-C raises KeyboardInterrupt within a fraction of a second; an
exception from the controller (or a bad command, named with its time and value) ends the
episode; either exception carries .partial (a Run of the episode so far) and .time (seconds).
The robot holds still for its first second (the gyro is calibrated at rest) before the controller
is called. Returns a Run. Bad input raises plantsim.InputError with the command line's message.)");
}

}  // namespace plantsim::python
