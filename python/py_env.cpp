// plantsim.Env and plantsim.VectorEnv: episodes driven a control period at a time, with the
// Gymnasium API's contract (reset -> (obs, info), step -> (obs, reward, terminated, truncated,
// info)); observations are the robot's perception as numpy arrays, never the truth. Episodes
// come from a world (its start, the batch's random start for the seed, or a pose) or from a
// scenario (its worlds, starts, faults and controllers' configs, episode by episode as a batch
// makes them). The stepping runs with the GIL released; VectorEnv steps its environments on
// C++ threads in one call.
#include <pybind11/stl.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <thread>

#include "batch/batch_spec.h"
#include "batch/episode_runner.h"
#include "batch/episode_space.h"
#include "batch/random_start.h"
#include "batch/scenario_setup.h"
#include "episode/stepped_episode.h"
#include "planner/registry.h"
#include "python/action_check.h"
#include "python/episode_seeds.h"
#include "python/py_arguments.h"
#include "python/py_bindings.h"
#include "python/py_interrupt.h"
#include "python/py_world.h"
#include "render/plant_frame.h"
#include "util/worker_pool.h"
#include "worlds/world_fingerprint.h"
#include "worlds/world_loader.h"

namespace plantsim::python {
namespace {

using episode::SteppedEpisode;

/// Where episodes come from: one world, or a scenario's episodes in the order a batch runs them.
class EpisodeSource {
 public:
  struct Drawn {
    std::shared_ptr<const worlds::World> plant;
    episode::EpisodeConfig config;
    std::string planner, id;
  };
  virtual ~EpisodeSource() = default;
  /// The episode for `seed` (a world: the noise seed and, with random starts, the start; a
  /// scenario: its episode at index seed mod its count), or the scenario's episode `id`.
  virtual Drawn draw(std::uint64_t seed, const std::string& id) = 0;
  /// The robot and lidar the episodes have (a scenario's first world and config), for the spaces.
  virtual const worlds::World& first_world() const = 0;
  virtual const episode::EpisodeConfig& first_config() const = 0;
};

class WorldSource : public EpisodeSource {
 public:
  WorldSource(PyWorld world, episode::EpisodeConfig config, std::string planner, std::string start,
              std::optional<geom::Pose2> pose)
      : world_(std::move(world)),
        config_(std::move(config)),
        planner_(std::move(planner)),
        start_(std::move(start)),
        pose_(pose),
        fingerprint_(worlds::world_fingerprint(*world_.world)) {
    if (pose_) {
      auto moved = std::make_shared<worlds::World>(*world_.world);
      moved->start = *pose_;
      worlds::validate_world(*moved);  // a start in an obstacle or off the floor is refused
      world_.world = moved;
    }
    if (start_ == "random")
      vg_ = planner::make_planner("vg", planner::planner_input(*world_.world, true));
  }
  Drawn draw(std::uint64_t seed, const std::string& id) override {
    if (!id.empty()) throw std::invalid_argument("options['episode'] needs an Env of a scenario");
    Drawn d{world_.world, config_, planner_, world_.world->name + "|" + std::to_string(seed)};
    d.config.seed = seed;
    if (vg_) {
      const auto pose = batch::random_start(*world_.world, *vg_, seed, fingerprint_);
      if (!pose)
        throw std::invalid_argument(world_.world->name +
                                    ": no free start with a path to the charger");
      auto moved = std::make_shared<worlds::World>(*world_.world);
      moved->start = *pose;
      d.plant = moved;
    }
    return d;
  }
  const worlds::World& first_world() const override { return *world_.world; }
  const episode::EpisodeConfig& first_config() const override { return config_; }

 private:
  PyWorld world_;
  episode::EpisodeConfig config_;
  std::string planner_, start_;
  std::optional<geom::Pose2> pose_;
  std::uint64_t fingerprint_;
  std::unique_ptr<planner::Planner> vg_;
};

class ScenarioSource : public EpisodeSource {
 public:
  explicit ScenarioSource(const std::string& path)
      : spec_(batch::load_batch_spec(path)),
        loaded_(batch::load_scenario_worlds(spec_)),
        configs_(batch::episode_configs(spec_)),
        space_(spec_, loaded_.names),
        runner_(spec_, loaded_.worlds, loaded_.contents, configs_) {
    batch::check_charger_offsets(spec_, loaded_.worlds);
  }
  Drawn draw(std::uint64_t seed, const std::string& id) override {
    std::int64_t index =
        static_cast<std::int64_t>(seed % static_cast<std::uint64_t>(space_.size()));
    if (!id.empty()) {
      const auto found = space_.find(id);
      if (!found)
        throw std::invalid_argument("no episode '" + id + "' in " + spec_.source +
                                    " (ids are world|planner|controller|fault|seed)");
      index = *found;
    }
    const batch::Episode e = space_.at(index);
    batch::EpisodeRunner::Run prepared = runner_.prepare(e);
    return {std::make_shared<const worlds::World>(std::move(prepared.plant)), prepared.config,
            spec_.planners[e.planner], e.id};
  }
  const worlds::World& first_world() const override { return loaded_.worlds.front(); }
  const episode::EpisodeConfig& first_config() const override { return configs_.front(); }

 private:
  batch::BatchSpec spec_;
  batch::ScenarioWorlds loaded_;
  std::vector<episode::EpisodeConfig> configs_;
  batch::EpisodeSpace space_;
  batch::EpisodeRunner runner_;
};

/// The default reward (docs/python.md): progress of the estimate along the way still to go (to
/// the staging pose and on to the docked pose while travelling, to the docked pose while
/// docking), a cost of time, the bumper pressed, and the outcome at the end. Settable per
/// environment (Env's reward_weights).
struct RewardWeights {
  double progress = 1.0, per_step = 0.01, bumper = 1.0, docked = 10.0, failed = 10.0;
};

/// `weights` (a dict of some of RewardWeights' names, or None) over the defaults; a name not
/// among them or a value that is not a finite number refused naming it.
RewardWeights reward_weights(const py::object& weights) {
  RewardWeights w;
  if (weights.is_none()) return w;
  if (!py::isinstance<py::dict>(weights))
    throw py::type_error("reward_weights must be a dict of weights by name, or None");
  const std::vector<std::pair<const char*, double*>> named = {{"progress", &w.progress},
                                                              {"per_step", &w.per_step},
                                                              {"bumper", &w.bumper},
                                                              {"docked", &w.docked},
                                                              {"failed", &w.failed}};
  for (const auto& kv : weights.cast<py::dict>()) {
    const std::string key = py::str(kv.first).cast<std::string>();
    const auto it =
        std::find_if(named.begin(), named.end(), [&](const auto& n) { return key == n.first; });
    if (it == named.end())
      throw std::invalid_argument("reward_weights: unknown weight '" + key +
                                  "' (progress, per_step, bumper, docked, failed)");
    if (!py::isinstance<py::float_>(kv.second) && !py::isinstance<py::int_>(kv.second))
      throw py::type_error("reward_weights['" + key + "'] must be a number");
    const double v = kv.second.cast<double>();
    if (!std::isfinite(v))
      throw std::invalid_argument("reward_weights['" + key + "'] must be finite, got " +
                                  py::repr(kv.second).cast<std::string>());
    *it->second = v;
  }
  return w;
}

/// How an environment's episodes step and end (Env's docking, contact and max_steps).
struct EnvRules {
  RewardWeights weights;
  episode::DockingSteps docking = episode::DockingSteps::kBuiltinEachPeriod;
  bool contact_ends = true;    ///< the first contact terminates the episode
  std::int64_t max_steps = 0;  ///< truncate after this many steps (0: only timeout_s)
};

/// One environment: its episode source, the episode at hand and what the last step said.
class EnvCore {
 public:
  EnvCore(std::shared_ptr<EpisodeSource> source, EnvRules rules)
      : source_(std::move(source)), rules_(rules) {}

  /// A new episode; runs to its first steered period (GIL released by the caller).
  void reset(std::uint64_t seed, const std::string& id) {
    draw(seed, id);
    begin();
  }
  /// reset() in two halves: the draw from the shared source (one thread at a time), then the
  /// episode's own planning and first second (any thread: VectorEnv runs them in parallel).
  void draw(std::uint64_t seed, const std::string& id) { drawn_ = source_->draw(seed, id); }
  /// Throws std::invalid_argument when the episode ends before the agent's first step (its plan
  /// failed at the start, most often): reset() cannot hand out a first observation of it, and
  /// there is no perception to observe (stepping on, or observing it, read a null pointer).
  /// The environment is left without an episode, ready for another reset.
  void begin() {
    episode_.reset();
    id_ = drawn_.id;
    auto e = std::make_unique<SteppedEpisode>(drawn_.plant, drawn_.planner, drawn_.config,
                                              rules_.docking);
    reward_ = 0;
    truncated_by_limit_ = false;
    contact_ended_ = false;
    if (!e->start() || e->view().perception == nullptr)
      throw std::invalid_argument(ended_at_start(*e));
    episode_ = std::move(e);
    last_distance_ = still_to_go();
  }

  /// One period's command (checked by the caller: finite): runs to the next period the outside
  /// steers, or to the end.
  void step(controller::Twist command) {
    if (!episode_ || done())
      throw std::invalid_argument("the episode has ended: call reset() first");
    episode_->step(command);
    const double d = still_to_go();
    reward_ = rules_.weights.progress * (last_distance_ - d) - rules_.weights.per_step;
    last_distance_ = d;
    if (episode_->view().perception->bumper.pressed()) reward_ -= rules_.weights.bumper;
    // The first contact ends the episode (unless asked to go on): a crash is terminal.
    if (rules_.contact_ends && !episode_->ended() && episode_->result().collisions > 0)
      contact_ended_ = true;
    if (terminated())
      reward_ += !contact_ended_ && episode_->result().docked ? rules_.weights.docked
                                                              : -rules_.weights.failed;
    if (!episode_->ended() && !contact_ended_ && rules_.max_steps > 0 &&
        episode_->steps() >= rules_.max_steps)
      truncated_by_limit_ = true;
  }

  std::string ended_at_start(const SteppedEpisode& e) const {
    const episode::EpisodeResult& r = e.result();
    const std::string why =
        r.failure && !r.failure->detail.empty() ? r.failure->detail : episode::status_name(r);
    return "episode '" + id_ + "' (world '" + drawn_.plant->name + "', planner '" + drawn_.planner +
           "') ended before the agent's first step: " + why +
           ". Try another seed, start or planner (plantsim.plan(world, planner) shows the plan)";
  }

  /// Docked or failed (a first contact too, by default). One truncation rule: the time ran out,
  /// the config's timeout_s or max_steps, whichever first; no terminal reward either way.
  bool terminated() const {
    return episode_ &&
           (contact_ended_ ||
            (episode_->ended() && episode_->result().status != episode::EpisodeStatus::kTimeout));
  }
  bool truncated() const {
    return episode_ && !contact_ended_ &&
           ((episode_->ended() && episode_->result().status == episode::EpisodeStatus::kTimeout) ||
            truncated_by_limit_);
  }
  bool contact_ended() const { return contact_ended_; }
  /// How the ended episode ended, whichever rule ended it: its status ("collision" at a first
  /// contact, "timeout" at max_steps), whether it docked, its failure reason (empty if docked).
  std::string status() const {
    return contact_ended_       ? "collision"
           : !episode_->ended() ? "timeout"
                                : episode::status_name(episode_->result());
  }
  bool docked() const { return !contact_ended_ && episode_->ended() && episode_->result().docked; }
  std::string failure() const {
    const episode::EpisodeResult& r = episode_->result();
    if (contact_ended_) return "collision";
    if (!episode_->ended()) return "timeout";
    return r.failure ? std::string(robot::to_string(r.failure->reason)) : std::string();
  }
  /// Why it was truncated ("timeout_s" or "max_steps"), empty when it was not.
  std::string truncated_by() const {
    return !truncated() ? "" : truncated_by_limit_ ? "max_steps" : "timeout_s";
  }
  bool done() const { return terminated() || truncated(); }
  double reward() const { return reward_; }
  const SteppedEpisode& episode() const { return *episode_; }
  bool has_episode() const { return episode_ != nullptr; }
  void clear() { episode_.reset(); }
  const EpisodeSource& source() const { return *source_; }
  const std::string& id() const { return id_; }

 private:
  /// The way still to go from the estimate: to the staging pose and on to the docked pose while
  /// travelling, to the docked pose from the handover on, so that progress is positive all
  /// along a correct approach (towards the staging pose alone, docking read as going away).
  double still_to_go() const {
    const episode::OutsideView& v = episode_->view();
    const geom::Vec2 at = v.perception->pose.position();
    const geom::Vec2 docked{drawn_.plant->charger.x, drawn_.plant->charger.y};
    if (v.phase == controller::DockPhase::kTravel)
      return geom::distance(at, v.staging.position()) +
             geom::distance(v.staging.position(), docked);
    return geom::distance(at, docked);
  }
  std::shared_ptr<EpisodeSource> source_;
  EnvRules rules_;
  std::unique_ptr<SteppedEpisode> episode_;
  EpisodeSource::Drawn drawn_;
  std::string id_;
  double reward_ = 0, last_distance_ = 0;
  bool truncated_by_limit_ = false;
  bool contact_ended_ = false;
};

constexpr double kWaypointAhead_m = 1.0;

/// The point kWaypointAhead_m along the plan past the plan's point nearest to `at`.
geom::Vec2 waypoint(const std::vector<geom::Vec2>& plan, geom::Vec2 at) {
  if (plan.empty()) return at;
  if (plan.size() == 1) return plan[0];
  std::size_t best = 0;
  double best_d = INFINITY, best_t = 0;
  for (std::size_t i = 0; i + 1 < plan.size(); ++i) {
    const geom::Vec2 a = plan[i], ab = plan[i + 1] - a;
    const double len2 = geom::dot(ab, ab);
    const double t = len2 > 0 ? std::clamp(geom::dot(at - a, ab) / len2, 0.0, 1.0) : 0.0;
    const double d = geom::distance(at, a + t * ab);
    if (d < best_d) best_d = d, best = i, best_t = t;
  }
  double left = kWaypointAhead_m;
  geom::Vec2 from = plan[best] + best_t * (plan[best + 1] - plan[best]);
  for (std::size_t i = best + 1; i < plan.size(); ++i) {
    const double seg = geom::distance(from, plan[i]);
    if (seg >= left) return from + (left / seg) * (plan[i] - from);
    left -= seg;
    from = plan[i];
  }
  return plan.back();
}

/// The fixed-shape observation fields, written into row `row` of arrays of `rows` rows (one
/// environment: rows = 1 and the leading axis dropped by the caller).
struct ObservationArrays {
  ObservationArrays(py::ssize_t rows, py::ssize_t beams)
      : scan({rows, beams}),
        scan_time(rows),
        pose({rows, py::ssize_t{3}}),
        covariance({rows, py::ssize_t{3}, py::ssize_t{3}}),
        velocity({rows, py::ssize_t{2}}),
        odometry({rows, py::ssize_t{3}}),
        staging({rows, py::ssize_t{3}}),
        waypoint({rows, py::ssize_t{2}}),
        charger({rows, py::ssize_t{3}}),
        charger_seen(rows),
        phase(rows),
        health(rows),
        time(rows) {}
  py::array_t<double> scan, scan_time, pose, covariance, velocity, odometry, staging, waypoint,
      charger;
  py::array_t<bool> charger_seen;
  py::array_t<std::int64_t> phase, health;
  py::array_t<double> time;

  void fill(py::ssize_t r, const episode::OutsideView& v) {
    if (v.perception == nullptr)  // EnvCore never keeps such an episode (begin() refuses it)
      throw std::logic_error("an episode without a perception to observe");
    const robot::Perception& p = *v.perception;
    auto sc = scan.mutable_unchecked<2>();
    const py::ssize_t beams = sc.shape(1);
    for (py::ssize_t i = 0; i < beams; ++i)
      sc(r, i) = p.scan && static_cast<std::size_t>(i) < p.scan->ranges.size()
                     ? p.scan->ranges[static_cast<std::size_t>(i)]
                     : NAN;
    scan_time.mutable_at(r) = p.scan ? p.scan->t_s : NAN;
    auto put3 = [r](py::array_t<double>& a, const geom::Pose2& q) {
      auto m = a.mutable_unchecked<2>();
      m(r, 0) = q.x, m(r, 1) = q.y, m(r, 2) = q.yaw;
    };
    put3(pose, p.pose);
    put3(odometry, p.odom_pose);
    put3(staging, v.staging);
    put3(charger, p.charger_in_robot.value_or(geom::Pose2{NAN, NAN, NAN}));
    charger_seen.mutable_at(r) = p.charger_in_robot.has_value();
    auto c = covariance.mutable_unchecked<3>();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        c(r, i, j) = p.pose_covariance[static_cast<std::size_t>(3 * i + j)];
    auto ve = velocity.mutable_unchecked<2>();
    ve(r, 0) = p.speed_mps, ve(r, 1) = p.yaw_rate_radps;
    const geom::Vec2 w = python::waypoint(v.plan, p.pose.position());
    auto wp = waypoint.mutable_unchecked<2>();
    wp(r, 0) = w.x, wp(r, 1) = w.y;
    phase.mutable_at(r) = static_cast<std::int64_t>(v.phase);
    health.mutable_at(r) = static_cast<std::int64_t>(p.health);
    time.mutable_at(r) = p.t_s;
  }

  /// As a dict; `single` drops the leading axis of one row.
  py::dict as_dict(bool single) const {
    py::dict d;
    auto put = [&](const char* key, const py::array& a) {
      if (!single) {
        d[key] = a;
        return;
      }
      d[key] = a[py::int_(0)];
    };
    put("scan", scan), put("scan_time", scan_time), put("pose", pose);
    put("covariance", covariance), put("velocity", velocity), put("odometry", odometry);
    put("staging", staging), put("waypoint", waypoint), put("charger", charger);
    put("charger_seen", charger_seen), put("phase", phase), put("health", health);
    put("time", time);
    return d;
  }
};

py::dict info_of(const EnvCore& env) {
  py::dict info;
  const SteppedEpisode& e = env.episode();
  info["episode"] = env.id();
  info["time"] = e.view().perception->t_s;
  info["steps"] = e.steps();
  info["builtin"] = py::make_tuple(e.view().builtin.v_mps, e.view().builtin.omega_radps);
  info["plan"] = points_array(e.view().plan);
  // Whether the next step takes the action (false while plantsim's docking drives a period a
  // step: the action is ignored).
  info["action_used"] = e.ended() || e.outside_steers();
  if (env.done()) {  // the same keys however it ended
    info["status"] = env.status();
    info["docked"] = env.docked();
    info["failure"] = env.failure();
    info["collisions"] = e.result().collisions;
    info["truncated_by"] = env.truncated_by();
  }
  return info;
}

std::shared_ptr<EpisodeSource> source_of(const py::object& world, const py::object& scenario,
                                         const py::object& config, const std::string& planner,
                                         const py::object& start) {
  if (world.is_none() == scenario.is_none())
    throw std::invalid_argument("give a world or a scenario (one of them)");
  if (!scenario.is_none()) {
    if (!config.is_none())
      throw std::invalid_argument(
          "a scenario's episodes take its own configs: config must be None");
    return std::make_shared<ScenarioSource>(
        py::str(py::module_::import("os").attr("fspath")(scenario)).cast<std::string>());
  }
  const std::vector<std::string> names = planner::planner_names();
  if (std::find(names.begin(), names.end(), planner) == names.end())
    throw std::invalid_argument("unknown planner '" + planner +
                                "' (plantsim.planners() lists them)");
  std::string how = "pose";
  std::optional<geom::Pose2> pose;
  if (py::isinstance<py::str>(start)) {
    how = start.cast<std::string>();
    if (how != "world" && how != "random")
      throw std::invalid_argument("start must be \"world\", \"random\" or [x, y, yaw], got '" +
                                  how + "'");
  } else {
    pose = pose_from(start, "start");
  }
  return std::make_shared<WorldSource>(world_argument(world), config_argument(config), planner, how,
                                       pose);
}

/// Env's docking, contact and max_steps arguments, checked.
EnvRules env_rules(const std::string& docking, const std::string& contact,
                   const py::object& max_steps, const py::object& weights) {
  EnvRules rules;
  rules.weights = reward_weights(weights);
  if (docking == "agent")
    rules.docking = episode::DockingSteps::kOutside;
  else if (docking == "plantsim")
    rules.docking = episode::DockingSteps::kBuiltinEachPeriod;
  else if (docking == "plantsim-whole")
    rules.docking = episode::DockingSteps::kBuiltinToTheEnd;
  else
    throw std::invalid_argument(
        "docking must be \"plantsim\" (its manoeuvre docks, a control period a step), "
        "\"plantsim-whole\" (it docks to the end within one step) or \"agent\" (the actions "
        "steer the docking too), got '" +
        docking + "'");
  if (contact != "terminate" && contact != "continue")
    throw std::invalid_argument(
        "contact must be \"terminate\" (the first contact ends the episode) or \"continue\", "
        "got '" +
        contact + "'");
  rules.contact_ends = contact == "terminate";
  rules.max_steps = whole_from(max_steps, "max_steps", 0, std::numeric_limits<std::int64_t>::max());
  return rules;
}

/// An action argument as numpy sees it (numpy.asarray: no conversion yet, so that complex,
/// bool, text and object elements are refused, not cast); the values only when the count fits.
ActionInput action_input(const py::handle& action, const std::string& argument, std::size_t count) {
  static const py::object* asarray =
      new py::object(py::module_::import("numpy").attr("asarray"));  // kept for the process
  py::array a;
  try {
    a = (*asarray)(action);
  } catch (const py::error_already_set& e) {  // a ragged nested list, for one
    throw py::type_error(argument + " must be an array of real numbers, got " +
                         py::repr(action).cast<std::string>().substr(0, 80) + " (" + e.what() +
                         ")");
  }
  ActionInput in;
  in.kind = element_kind(a.dtype().kind());
  for (py::ssize_t d = 0; d < a.ndim(); ++d) in.shape.push_back(a.shape(d));
  if ((in.kind == ElementKind::kReal || in.kind == ElementKind::kInteger) &&
      static_cast<std::size_t>(a.size()) == count) {
    const auto values = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    in.values.assign(values.data(), values.data() + count);
  }
  return in;
}

/// The checked actions (python/action_check.h) as commands; throws before anything steps.
std::vector<controller::Twist> twists_of(const py::handle& action, const std::string& argument,
                                         std::size_t envs, const std::string& kind,
                                         const std::vector<double>& wheel_bases) {
  const std::size_t rows = envs == 0 ? 1 : envs;
  const ActionInput in = action_input(action, argument, 2 * rows);
  if (const ActionProblem p = action_problem(in, envs, argument)) {
    if (p.kind == ActionProblem::Kind::kType) throw py::type_error(p.message);
    throw std::invalid_argument(p.message);
  }
  std::vector<controller::Twist> t(rows);
  for (std::size_t i = 0; i < rows; ++i) {
    const double a = in.values[2 * i], b = in.values[2 * i + 1];
    t[i] = kind == "wheels" ? controller::Twist{(a + b) / 2, (b - a) / wheel_bases[i]}
                            : controller::Twist{a, b};
  }
  return t;
}

std::string action_argument(const std::string& action) {
  if (action != "twist" && action != "wheels")
    throw std::invalid_argument("action must be \"twist\" or \"wheels\", got '" + action + "'");
  return action;
}

/// reset()'s options checked: None or a dict whose only key is "episode" (`shape` says what its
/// value is, for the message); its value, or None.
py::object episode_option(const py::object& options, const char* shape) {
  if (options.is_none()) return py::none();
  if (!py::isinstance<py::dict>(options))
    throw py::type_error(std::string("options must be a dict ({\"episode\": ") + shape +
                         "}) or None");
  const py::dict o = options.cast<py::dict>();
  for (const auto& kv : o)
    if (!py::isinstance<py::str>(kv.first) || kv.first.cast<std::string>() != "episode")
      throw std::invalid_argument("unknown option " + py::repr(kv.first).cast<std::string>() +
                                  " (options: episode)");
  return o.contains("episode") ? py::object(o["episode"]) : py::none();
}

std::string options_episode(const py::object& options) {
  const py::object episode = episode_option(options, "id");
  if (episode.is_none()) return "";  // None: the seed's episode, as in VectorEnv's list
  if (!py::isinstance<py::str>(episode))
    throw py::type_error("options['episode'] must be an episode id (str)");
  return episode.cast<std::string>();
}

/// One environment. Calls run one at a time (CallGuard); reset plans in the background,
/// answering Ctrl-C (Background); an interrupted reset leaves no episode: reset() again.
struct PyEnv {
  PyEnv(const py::object& world, const py::object& scenario, const py::object& config,
        const std::string& planner, const py::object& start, const std::string& docking,
        const std::string& contact, const std::string& action, const py::object& reward,
        const py::object& max_steps, const py::object& weights)
      : core(source_of(world, scenario, config, planner, start),
             env_rules(docking, contact, max_steps, weights)),
        action_kind(action_argument(action)),
        reward_fn(reward) {
    if (!reward.is_none() && !PyCallable_Check(reward.ptr()))
      throw py::type_error("reward must be callable: f(obs, info) -> float, or None");
  }

  py::tuple reset(const py::object& seed, const py::object& options) {
    const std::string id = options_episode(options);
    const std::optional<std::uint64_t> s =
        seed.is_none() ? std::nullopt : std::optional<std::uint64_t>(seed_from(seed, "seed"));
    const CallGuard::Held held = guard.enter("Env");
    background.settle();
    const std::uint64_t this_seed = seeds.next(s);
    core.clear();  // until the new episode has begun: a failed or interrupted reset leaves none
    background.run([this, this_seed, id] {
      core.draw(this_seed, id);
      if (!background.stopping()) core.begin();
    });
    return py::make_tuple(observation(), info_of(core));
  }

  py::tuple step(const py::handle& action) {
    const CallGuard::Held held = guard.enter("Env");
    if (background.settle()) core.clear();  // an interrupted reset's episode: nobody asked for it
    if (!core.has_episode())
      throw std::invalid_argument(
          "no episode: call reset() before step() (a reset that raised or was interrupted "
          "leaves none)");
    const controller::Twist t =
        twists_of(action, "action", 0, action_kind, {core.episode().plant().robot.wheel_base_m})[0];
    {
      py::gil_scoped_release release;
      core.step(t);
    }
    py::dict obs = observation();
    py::dict info = info_of(core);
    double r = core.reward();
    if (!reward_fn.is_none()) r = reward_fn(obs, info).cast<double>();
    return py::make_tuple(obs, r, core.terminated(), core.truncated(), info);
  }

  py::dict observation() const {
    const std::size_t beams = beams_of(core);
    ObservationArrays a(1, static_cast<py::ssize_t>(beams));
    a.fill(0, core.episode().view());
    return a.as_dict(true);
  }

  /// The plant now as an RGB array (height, width, 3): the robot where it is, the path it drove,
  /// plantsim's plan and the newest scan placed at the estimate (render_mode "rgb_array").
  py::array_t<std::uint8_t> frame(const py::object& width, const py::object& height) {
    const auto w = static_cast<int>(whole_from(width, "width", 64, 4096));
    const auto h = static_cast<int>(whole_from(height, "height", 64, 4096));
    const CallGuard::Held held = guard.enter("Env");
    background.settle();
    if (!core.has_episode())
      throw std::invalid_argument("no episode to render: call reset() first");
    const SteppedEpisode& e = core.episode();
    const episode::EpisodeResult& r = e.result();
    const robot::Perception& p = *e.view().perception;
    render::PlantInstant at;
    at.t_s = e.time_s();
    at.robot = r.trajectory.empty() ? e.plant().start : r.trajectory.back().truth;
    at.phase = std::string(controller::to_string(e.view().phase));
    at.trajectory = &r.trajectory;
    at.driven = r.trajectory.size();
    at.carries = &r.carries;
    at.plan = e.view().plan;
    robot::ScanView scan;
    if (p.scan) {  // the newest reading placed at the estimate, as the robot would place it
      scan.pose = p.pose;
      const geom::Pose2 sensor = geom::compose(p.pose, p.scan->mount);
      for (std::size_t i = 0; i < p.scan->ranges.size(); ++i)
        if (p.scan->valid(i))
          scan.explained.push_back(
              geom::compose(sensor, {p.scan->ranges[i] * std::cos(p.scan->angle(i)),
                                     p.scan->ranges[i] * std::sin(p.scan->angle(i)), 0})
                  .position());
      at.scan = &scan;
    }
    at.layer = p.layer;
    at.tracked = p.obstacles;
    render::Image image;
    {
      py::gil_scoped_release release;
      image = render::plant_frame(e.plant(), at, w, h);
    }
    py::array_t<std::uint8_t> rgb(
        {static_cast<py::ssize_t>(h), static_cast<py::ssize_t>(w), py::ssize_t{3}});
    auto out = rgb.mutable_unchecked<3>();
    for (int row = 0; row < h; ++row)
      for (int col = 0; col < w; ++col) {
        const render::Rgb c = image.at(col, row);
        out(row, col, 0) = c.r, out(row, col, 1) = c.g, out(row, col, 2) = c.b;
      }
    return rgb;
  }

  static std::size_t beams_of(const EnvCore& c) {
    return static_cast<std::size_t>(std::max(0, c.episode().config().lidar.beam_count));
  }

  EnvCore core;
  std::string action_kind;
  py::object reward_fn;
  EpisodeSeeds seeds;
  CallGuard guard;
  Background background;  // last: destroyed first, waiting for work that uses the members above
};

/// n environments stepped on a worker pool. Calls one at a time; plans (reset, autoreset) in the
/// background, answering Ctrl-C; after an interrupted or failed reset or autoreset, reset().
struct PyVectorEnv {
  PyVectorEnv(const py::object& n_arg, const py::object& world, const py::object& scenario,
              const py::object& config, const std::string& planner, const py::object& start,
              const std::string& docking, const std::string& contact, const std::string& action,
              const py::object& max_steps, const py::object& threads, const py::object& weights)
      : action_kind(action_argument(action)), pool(pool_threads(n_arg, threads)) {
    const auto n = static_cast<int>(whole_from(n_arg, "n", 1, 4096));
    const EnvRules rules = env_rules(docking, contact, max_steps, weights);
    const std::shared_ptr<EpisodeSource> source =
        source_of(world, scenario, config, planner, start);
    for (int i = 0; i < n; ++i) envs.push_back(std::make_unique<EnvCore>(source, rules));
    seeds.resize(envs.size());
    // One source for all: its draws are made one at a time (on one thread, below).
  }

  /// The pool's threads: 0 one per core; at most n and 4 per core (util/worker_pool.h); a
  /// negative or absurd count refused.
  static int pool_threads(const py::object& n, const py::object& threads) {
    const auto envs = static_cast<std::size_t>(whole_from(n, "n", 1, 4096));
    const auto asked = static_cast<int>(whole_from(threads, "threads", 0, 4096));
    return util::WorkerPool::threads_for(asked, envs);
  }

  py::tuple reset(const py::object& seed, const py::object& options) {
    const std::vector<std::optional<std::uint64_t>> asked = seeds_asked(seed);
    const std::vector<std::string> ids = episodes_asked(options);
    const CallGuard::Held held = guard.enter("VectorEnv");
    background.settle();
    ready = false;
    std::vector<std::uint64_t> firsts;
    for (std::size_t i = 0; i < envs.size(); ++i) firsts.push_back(seeds[i].next(asked[i]));
    background.run([this, firsts, ids] {
      for (std::size_t i = 0; i < envs.size() && !background.stopping(); ++i)
        envs[i]->draw(firsts[i], ids[i]);
      begin_all(std::vector<char>(envs.size(), 1), {});
    });
    ready = true;
    return py::make_tuple(observations(), infos());
  }

  py::tuple step(const py::handle& actions) {
    const CallGuard::Held held = guard.enter("VectorEnv");
    background.settle();
    if (!ready)
      throw std::invalid_argument(
          "call reset() before step() (a reset or autoreset that raised or was interrupted "
          "needs a new reset())");
    std::vector<double> wheel_bases;
    for (const auto& e : envs) wheel_bases.push_back(e->episode().plant().robot.wheel_base_m);
    // Every action checked before any environment steps.
    std::vector<controller::Twist> twists =
        twists_of(actions, "actions", envs.size(), action_kind, wheel_bases);
    std::vector<char> was_done(envs.size());
    bool any_done = false;
    for (std::size_t i = 0; i < envs.size(); ++i)
      any_done |= (was_done[i] = static_cast<char>(envs[i]->done())) != 0;
    if (!any_done) {
      py::gil_scoped_release release;  // a step is one control period: no planning to wait for
      pool.run(envs.size(), [&](std::size_t i) { envs[i]->step(twists[i]); });
    } else {
      // Gymnasium's next-step autoreset: an environment that ended at the last step starts its
      // next episode now (reward 0, not terminated), planning in the background; the others
      // take their actions.
      ready = false;
      std::vector<std::uint64_t> next(envs.size());
      for (std::size_t i = 0; i < envs.size(); ++i)
        if (was_done[i]) next[i] = seeds[i].next(std::nullopt);  // an autoreset: no seed
      background.run([this, was_done, next, twists = std::move(twists)] {
        for (std::size_t i = 0; i < envs.size(); ++i)
          if (was_done[i]) envs[i]->draw(next[i], "");
        begin_all(was_done, twists);
      });
      ready = true;
    }
    py::array_t<double> rewards(static_cast<py::ssize_t>(envs.size()));
    py::array_t<bool> terminated(static_cast<py::ssize_t>(envs.size())),
        truncated(static_cast<py::ssize_t>(envs.size()));
    for (std::size_t i = 0; i < envs.size(); ++i) {
      const auto k = static_cast<py::ssize_t>(i);
      rewards.mutable_at(k) = was_done[i] ? 0.0 : envs[i]->reward();
      terminated.mutable_at(k) = !was_done[i] && envs[i]->terminated();
      truncated.mutable_at(k) = !was_done[i] && envs[i]->truncated();
    }
    return py::make_tuple(observations(), rewards, terminated, truncated, infos());
  }

  /// Begins the environments marked in `begin` and steps the others with `twists` (empty: none
  /// to step), on the pool; a begin not yet started when Ctrl-C came is skipped. The first
  /// failure is rethrown naming its environment.
  void begin_all(const std::vector<char>& begin, const std::vector<controller::Twist>& twists) {
    pool.run(envs.size(), [&](std::size_t i) {
      if (!begin[i]) return envs[i]->step(twists[i]);
      if (background.stopping()) return;
      try {
        envs[i]->begin();
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("VectorEnv environment " + std::to_string(i) + ": " + e.what());
      }
    });
  }

  /// What reset(options=...) asks of each environment: {"episode": [id or None, ...]}, one per
  /// environment (a scenario's episodes by id, as Env's option), or nothing.
  std::vector<std::string> episodes_asked(const py::object& options) const {
    std::vector<std::string> out(envs.size());
    const py::object each = episode_option(options, "[id, ...]");
    if (each.is_none()) return out;
    if (!py::isinstance<py::list>(each) && !py::isinstance<py::tuple>(each))
      throw py::type_error("options['episode'] must be a list of " + std::to_string(envs.size()) +
                           " episode ids (str, or None for a seed's episode)");
    const py::list ids(each);
    if (ids.size() != envs.size())
      throw std::invalid_argument("options['episode']: " + std::to_string(envs.size()) +
                                  " ids (one per environment) expected, got " +
                                  std::to_string(ids.size()));
    for (std::size_t i = 0; i < envs.size(); ++i) {
      if (ids[i].is_none()) continue;
      if (!py::isinstance<py::str>(ids[i]))
        throw py::type_error("options['episode'][" + std::to_string(i) +
                             "] must be an episode id (str) or None");
      out[i] = ids[i].cast<std::string>();
    }
    return out;
  }

  /// What reset(seed=...) asks of each environment: None, a whole number s (s + i for the i-th:
  /// the same episodes as Env.reset(seed=s + i)), or one seed per environment (a list, tuple or
  /// one-dimensional array of n whole numbers).
  std::vector<std::optional<std::uint64_t>> seeds_asked(const py::object& seed) const {
    std::vector<std::optional<std::uint64_t>> out(envs.size());
    if (seed.is_none()) return out;
    if (py::isinstance<py::list>(seed) || py::isinstance<py::tuple>(seed) ||
        py::isinstance<py::array>(seed)) {
      const py::list each = py::list(seed);
      if (each.size() != envs.size())
        throw std::invalid_argument("seed: a list of " + std::to_string(envs.size()) +
                                    " seeds (one per environment) expected, got " +
                                    std::to_string(each.size()));
      for (std::size_t i = 0; i < envs.size(); ++i)
        out[i] = seed_from(each[i], "seed[" + std::to_string(i) + "]");
      return out;
    }
    const std::uint64_t s = seed_from(seed, "seed");
    for (std::size_t i = 0; i < envs.size(); ++i) {
      if (s > std::numeric_limits<std::uint64_t>::max() - i)
        throw std::invalid_argument("seed: s + i must stay below 2**64 for every environment i");
      out[i] = s + i;
    }
    return out;
  }
  py::dict observations() const {
    ObservationArrays a(static_cast<py::ssize_t>(envs.size()),
                        static_cast<py::ssize_t>(PyEnv::beams_of(*envs.front())));
    for (std::size_t i = 0; i < envs.size(); ++i)
      a.fill(static_cast<py::ssize_t>(i), envs[i]->episode().view());
    return a.as_dict(false);
  }

  /// Env's info keys stacked as Gymnasium's vector environments give them: info[key] an array
  /// over the environments (numbers as numbers, text and plans as objects) and info["_" + key]
  /// which environments have it: every one for what each step says, those whose episode ended
  /// at this step for how it ended.
  py::dict infos() const {
    const auto n = static_cast<py::ssize_t>(envs.size());
    // An array of Python objects (text, plans) holding `items`.
    auto object_array = [](const py::list& items) {
      py::array a(py::dtype("O"), std::vector<py::ssize_t>{static_cast<py::ssize_t>(items.size())},
                  std::vector<py::ssize_t>{});
      auto** slots = static_cast<PyObject**>(a.mutable_data());
      for (std::size_t i = 0; i < items.size(); ++i) {
        PyObject* old = slots[i];
        slots[i] = py::object(items[i]).release().ptr();  // the array owns a reference
        Py_XDECREF(old);
      }
      return a;
    };
    py::list episode, plan, status, failure, truncated_by;
    py::array_t<double> time(n), builtin({n, py::ssize_t{2}});
    py::array_t<std::int64_t> steps(n), collisions(n);
    py::array_t<bool> action_used(n), docked(n), every(n), ended(n);
    for (py::ssize_t i = 0; i < n; ++i) {
      const EnvCore& env = *envs[static_cast<std::size_t>(i)];
      const SteppedEpisode& e = env.episode();
      const bool done = env.done();
      episode.append(env.id());
      plan.append(points_array(e.view().plan));
      time.mutable_at(i) = e.view().perception->t_s;
      steps.mutable_at(i) = e.steps();
      builtin.mutable_at(i, 0) = e.view().builtin.v_mps;
      builtin.mutable_at(i, 1) = e.view().builtin.omega_radps;
      action_used.mutable_at(i) = e.ended() || e.outside_steers();
      every.mutable_at(i) = true;
      ended.mutable_at(i) = done;
      status.append(done ? env.status() : std::string());
      failure.append(done ? env.failure() : std::string());
      truncated_by.append(done ? env.truncated_by() : std::string());
      docked.mutable_at(i) = done && env.docked();
      collisions.mutable_at(i) = done ? e.result().collisions : 0;
    }
    py::dict d;
    auto put = [&d](const char* key, const py::object& value, const py::array_t<bool>& mask) {
      d[key] = value;
      d[(std::string("_") + key).c_str()] = mask;
    };
    put("episode", object_array(episode), every);
    put("time", time, every);
    put("steps", steps, every);
    put("builtin", builtin, every);
    put("plan", object_array(plan), every);
    put("action_used", action_used, every);
    put("status", object_array(status), ended);
    put("docked", docked, ended);
    put("failure", object_array(failure), ended);
    put("collisions", collisions, ended);
    put("truncated_by", object_array(truncated_by), ended);
    return d;
  }

  std::vector<std::unique_ptr<EnvCore>> envs;
  std::string action_kind;
  util::WorkerPool pool;
  std::vector<EpisodeSeeds> seeds;  ///< each environment's
  bool ready = false;  // every environment holds an episode begun by a finished reset or step
  CallGuard guard;
  Background background;  // last: destroyed first, waiting for work that uses the members above
};

/// (max speed m/s, wheel base m, lidar beams, lidar max range m) for the spaces.
py::tuple limits_of(const EpisodeSource& s) {
  const worlds::World& w = s.first_world();
  const episode::EpisodeConfig& c = s.first_config();
  return py::make_tuple(w.robot.max_speed_mps, w.robot.wheel_base_m, c.lidar.beam_count,
                        c.lidar.max_range_m);
}

}  // namespace

void bind_env(py::module_& m) {
  py::class_<PyEnv>(m, "_Env")
      .def(py::init<const py::object&, const py::object&, const py::object&, const std::string&,
                    const py::object&, const std::string&, const std::string&, const std::string&,
                    const py::object&, const py::object&, const py::object&>(),
           py::arg("world"), py::arg("scenario"), py::arg("config"), py::arg("planner"),
           py::arg("start"), py::arg("docking"), py::arg("contact"), py::arg("action"),
           py::arg("reward"), py::arg("max_steps"), py::arg("reward_weights"))
      .def("reset", &PyEnv::reset, py::arg("seed"), py::arg("options"))
      .def("frame", &PyEnv::frame, py::arg("width"), py::arg("height"))
      .def("step", &PyEnv::step, py::arg("action"))
      .def_property_readonly("limits", [](const PyEnv& e) { return limits_of(e.core.source()); });
  py::class_<PyVectorEnv>(m, "_VectorEnv")
      .def(py::init<const py::object&, const py::object&, const py::object&, const py::object&,
                    const std::string&, const py::object&, const std::string&, const std::string&,
                    const std::string&, const py::object&, const py::object&, const py::object&>(),
           py::arg("n"), py::arg("world"), py::arg("scenario"), py::arg("config"),
           py::arg("planner"), py::arg("start"), py::arg("docking"), py::arg("contact"),
           py::arg("action"), py::arg("max_steps"), py::arg("threads"), py::arg("reward_weights"))
      .def("reset", &PyVectorEnv::reset, py::arg("seed"), py::arg("options"))
      .def_property_readonly(
          "limits", [](const PyVectorEnv& e) { return limits_of(e.envs.front()->source()); })
      .def("step", &PyVectorEnv::step, py::arg("actions"));
}

}  // namespace plantsim::python
