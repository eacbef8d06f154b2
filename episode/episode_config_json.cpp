// Every parameter, read and written by the same rows: each module declares its own
// (sim/sim_param_rows.h, robot/robot_param_rows.h, controller/controller_param_rows.h); this file
// only assembles them with the episode's own and reads and writes the file.
#include "episode/episode_config_json.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <filesystem>
#include <fstream>
#include <functional>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>

#include "controller/controller_param_rows.h"
#include "controller/local_controller_registry.h"
#include "robot/dock_detector.h"
#include "robot/estimator_registry.h"
#include "robot/robot_param_rows.h"
#include "robot/travel_registry.h"
#include "sim/sim_param_rows.h"
#include "util/choice_table.h"
#include "util/input_file.h"
#include "util/param_table.h"
#include "worlds/json_input.h"
#include "worlds/known_keys.h"
#include "worlds/param_json.h"
#include "worlds/world_error.h"

namespace plantsim::episode {

using namespace plantsim::sim;  // the simulator's parts and the episode's types

using robot::PerceptionMode;

namespace {

using nlohmann::json;

using Field = util::Param<EpisodeConfig>;

/// A name that lives as long as the program (a row's section and key are C strings).
const char* interned(const std::string& text) {
  static std::mutex mutex;
  static std::deque<std::string> kept;
  std::lock_guard<std::mutex> lock(mutex);
  for (const std::string& k : kept)
    if (k == text) return k.c_str();
  kept.push_back(text);
  return kept.back().c_str();
}

/// Every registered component's parameters: travel modes', local controllers', estimators'.
std::vector<util::ParamSpec> registered_specs() {
  std::vector<util::ParamSpec> out;
  for (const auto* e : robot::travel_modes().entries())
    out.insert(out.end(), e->params.begin(), e->params.end());
  for (const auto* e : controller::local_controllers().entries())
    out.insert(out.end(), e->params.begin(), e->params.end());
  for (const auto* e : robot::estimators().entries())
    out.insert(out.end(), e->params.begin(), e->params.end());
  for (const auto* e : robot::dock_detectors().entries())
    out.insert(out.end(), e->params.begin(), e->params.end());
  return out;
}

/// Grows by one with every component registered (registries never shrink).
std::size_t registered_component_count() {
  return robot::travel_modes().entries().size() + controller::local_controllers().entries().size() +
         robot::estimators().entries().size() + robot::dock_detectors().entries().size();
}

// The episode's own rows: the faults, a moving target's pursuit, the loop's period and timeout.
util::ParamRows<KidnapFault> kidnap_param_rows() {
  return {
      PLANTSIM_PARAM("kidnap", at_s, "at_s", -1.0, 86400.0),
      PLANTSIM_PARAM("kidnap", dx_m, "dx_m", -1000.0, 1000.0),
      PLANTSIM_PARAM("kidnap", dy_m, "dy_m", -1000.0, 1000.0),
      PLANTSIM_PARAM("kidnap", dyaw_rad, "dyaw_rad", -M_PI, M_PI),
      PLANTSIM_PARAM("kidnap", distance_min_m, "distance_min_m", 0.0, 1000.0),
      PLANTSIM_PARAM("kidnap", distance_max_m, "distance_max_m", 0.0, 1000.0),
  };
}

/// Every parameter with a struct in EpisodeConfig: each module's rows, assembled (in
/// docs/config.md's section order, which is also the order `plantsim config` writes them in).
const std::vector<Field>& typed_table() {
  static const std::vector<Field> rows = [] {
    std::vector<Field> t;
    util::append_rows_of_part(t, sim::step_param_rows(), PLANTSIM_PART(step));
    t.push_back(PLANTSIM_PARAM("step", control_period_steps, "control_period_steps", 1, 1000));
    util::append_rows_of_part(t, sim::drive_param_rows(), PLANTSIM_PART(drive));
    util::append_rows_of_part(t, sim::odometry_param_rows(), PLANTSIM_PART(odometry));
    util::append_rows_of_part(t, sim::localization_param_rows(), PLANTSIM_PART(localization));
    util::append_rows_of_part(t, sim::detection_param_rows(), PLANTSIM_PART(detection));
    util::append_rows_of_part(t, sim::lidar_param_rows(), PLANTSIM_PART(lidar));
    util::append_rows_of_part(t, sim::imu_param_rows(), PLANTSIM_PART(imu));
    util::append_rows_of_part(t, sim::beacon_param_rows(), PLANTSIM_PART(beacon));
    util::append_rows_of_part(t, robot::ekf_param_rows(), PLANTSIM_PART(perception.ekf));
    util::append_rows_of_part(t, robot::tracker_param_rows(), PLANTSIM_PART(perception.tracker));
    util::append_rows_of_part(t, robot::perception_param_rows(), PLANTSIM_PART(perception));
    util::append_rows_of_part(t, controller::pure_pursuit_param_rows(), PLANTSIM_PART(tracking));
    util::append_rows_of_part(t, controller::docking_param_rows(), PLANTSIM_PART(docking));
    util::append_rows_of_part(t, kidnap_param_rows(), PLANTSIM_PART(kidnap));
    util::append_rows_of_part(t, controller::potential_field_param_rows(), PLANTSIM_PART(field));
    t.push_back(
        PLANTSIM_PARAM("pursuit", catch_distance_m, "catch_distance_m", 0.0, util::kMaxParameter));
    t.push_back(PLANTSIM_PARAM("pursuit", pursuit_replan_period_s, "replan_period_s", 0.0,
                               util::kMaxParameter));
    util::append_rows_of_part(t, sim::tolerance_param_rows(), PLANTSIM_PART(tolerance));
    util::append_rows_of_part(t, controller::traction_param_rows(), PLANTSIM_PART(traction));
    util::append_rows_of_part(t, robot::layer_param_rows(), PLANTSIM_PART(perception.layer));
    util::append_rows_of_part(t, robot::particle_param_rows(), PLANTSIM_PART(perception.particles));
    util::append_rows_of_part(t, robot::lost_search_param_rows(), PLANTSIM_PART(lost_search));
    util::append_rows_of_part(t, robot::coastal_param_rows(), PLANTSIM_PART(coastal));
    t.push_back(PLANTSIM_PARAM_ABOVE("", timeout_s, "timeout_s", 0.0, 86400.0));
    return t;
  }();
  return rows;
}

/// The registered components' parameters (built-in or a plugin's) that no typed row holds, each
/// a row of EpisodeConfig::component_params that reads its declared default until set.
std::vector<Field> component_rows() {
  std::set<std::string> typed;
  for (const Field& f : typed_table()) typed.insert(f.path());
  std::vector<Field> out;
  for (const util::ParamSpec& spec : registered_specs()) {
    const std::string path = spec.path();
    if (!typed.insert(path).second) continue;  // a built-in's typed row, or declared twice
    const double fallback = spec.default_value;
    out.push_back(
        Field{interned(spec.section), interned(spec.name), spec.kind,
              [path, fallback](const EpisodeConfig& c) {
                const double* v = util::find_value(c.component_params, path);
                return v ? *v : fallback;
              },
              [path](EpisodeConfig& c, double v) { util::set_value(c.component_params, path, v); },
              spec.lo, spec.hi, spec.above});
  }
  return out;
}

/// Every parameter: the typed rows, then the components'. Plugins add components while the
/// program starts; each table made stays alive, so a reference handed out earlier stays valid.
const std::vector<Field>& table() {
  static std::mutex mutex;
  static std::deque<std::vector<Field>> made;
  static std::size_t made_for = 0;
  std::lock_guard<std::mutex> lock(mutex);
  const std::size_t generation = registered_component_count();
  if (made.empty() || made_for != generation) {
    std::vector<Field> t = typed_table();
    for (Field& f : component_rows()) t.push_back(std::move(f));
    made.push_back(std::move(t));
    made_for = generation;
  }
  return made.back();
}

/// The rows of one kind, in the table's order: reals, whole numbers and flags are read and
/// written in turn.
std::vector<Field> rows_of(util::ParamKind kind) {
  std::vector<Field> out;
  for (const Field& f : table())
    if (f.kind == kind) out.push_back(f);
  return out;
}
std::vector<Field> fields() { return rows_of(util::ParamKind::kReal); }
std::vector<Field> int_fields() { return rows_of(util::ParamKind::kWhole); }
std::vector<Field> bool_fields() { return rows_of(util::ParamKind::kFlag); }

void read_tables(worlds::ParamDocument& doc, EpisodeConfig& c) {
  doc.read(fields(), c);
  doc.read(int_fields(), c);
  doc.read(bool_fields(), c);
}

/// The choices: the perception's (robot/robot_param_rows.h).
const util::ChoiceRows<EpisodeConfig>& choices() {
  static const util::ChoiceRows<EpisodeConfig> rows = [] {
    util::ChoiceRows<EpisodeConfig> t;
    util::append_choices_of_part(t, robot::perception_choice_rows(), PLANTSIM_PART(perception));
    return t;
  }();
  return rows;
}

/// A component chosen by name: one of its registry's.
template <typename Registry>
std::string chosen_component(worlds::ParamDocument& doc, const std::string& section,
                             const std::string& name, const Registry& registry) {
  const json* v = doc.find(section, name);
  const std::string path = section.empty() ? name : section + "." + name;
  if (!v->is_string()) throw worlds::WorldError(doc.source(), path, "expected a name");
  try {
    return registry.at(v->get<std::string>()).name;
  } catch (const util::RegistryError& e) {
    throw worlds::WorldError(doc.source(), path, e.what());
  }
}

/// The components chosen by name: the travel mode, the local controller, the estimator and the
/// dock detector.
void read_components(worlds::ParamDocument& doc, EpisodeConfig& c) {
  if (doc.find("", "travel")) c.travel = chosen_component(doc, "", "travel", robot::travel_modes());
  if (doc.find("", "local_controller"))
    c.local_controller =
        chosen_component(doc, "", "local_controller", controller::local_controllers());
  if (doc.find("localization", "estimator"))
    c.perception.estimator =
        chosen_component(doc, "localization", "estimator", robot::estimators());
  if (doc.find("docking", "detector"))
    c.perception.dock_detector =
        chosen_component(doc, "docking", "detector", robot::dock_detectors());
}

void read_seed(worlds::ParamDocument& doc, EpisodeConfig& c) {
  if (const json* v = doc.find("", "seed")) {
    if (!v->is_number_unsigned())
      throw worlds::WorldError(doc.source(), "seed", "expected a whole number");
    c.seed = v->get<std::uint64_t>();
  }
}

/// Values each in range that do not fit together.
void check_consistency(const std::string& source, const EpisodeConfig& c) {
  if (c.kidnap.distance_min_m > c.kidnap.distance_max_m)
    throw worlds::WorldError(source, "kidnap.distance_min_m", "must not exceed distance_max_m");
  if (c.field.k_att <= 0)
    throw worlds::WorldError(source, "potential_field.k_att", "must be positive");
  if (c.field.rho0_m <= c.field.rho_min_m)
    throw worlds::WorldError(source, "potential_field.rho0_m", "must exceed rho_min_m");
  if (c.field.slow_force_ratio <= 0)
    throw worlds::WorldError(source, "potential_field.slow_force_ratio", "must be positive");
  if (c.pursuit_replan_period_s <= 0)
    throw worlds::WorldError(source, "pursuit.replan_period_s", "must be positive");
  if (c.perception.mode == PerceptionMode::kSensors && c.localization.period_s > 0)
    throw worlds::WorldError(source, "localization.period_s",
                             "true-pose fixes exist only in perception.mode \"oracle\" (sensors "
                             "mode localises with the EKF)");
  if (c.perception.particles.kld.min_particles > c.perception.particles.kld.max_particles)
    throw worlds::WorldError(source, "particles.min_particles", "must not exceed max_particles");
  if (c.lidar.min_range_m >= c.lidar.max_range_m)
    throw worlds::WorldError(source, "lidar.min_range_m", "must be below lidar.max_range_m");
  if (c.tracking.lookahead_min_m > c.tracking.lookahead_max_m)
    throw worlds::WorldError(source, "tracking.lookahead_min_m", "must not exceed lookahead_max_m");
  // Each value in range can still ask for too much together: work is bounded, not only input.
  if (const double steps = std::ceil(c.timeout_s / c.step.dt_s);
      steps > static_cast<double>(kMaxEpisodeSteps))
    throw worlds::WorldError(
        source, "timeout_s",
        "timeout_s / step.dt_s asks for " + std::to_string(static_cast<long long>(steps)) +
            " physics steps, more than the limit of " + std::to_string(kMaxEpisodeSteps) +
            " (docs/config.md): shorten the timeout or lengthen the step");
}

}  // namespace

EpisodeConfig parse_episode_config(const std::string& text, const std::string& source,
                                   EpisodeConfig c) {
  const json parsed = worlds::parse_json_input(text, source);
  worlds::ParamDocument doc(parsed, source);
  read_tables(doc, c);
  doc.read(choices(), c);
  read_components(doc, c);
  read_seed(doc, c);
  doc.refuse_unknown();
  check_consistency(source, c);
  return c;
}

EpisodeConfig load_episode_config(const std::string& path) {
  return load_episode_config(path, EpisodeConfig());
}
EpisodeConfig parse_episode_config(const std::string& text, const std::string& source) {
  return parse_episode_config(text, source, EpisodeConfig());
}

EpisodeConfig load_episode_config(const std::string& path, EpisodeConfig base) {
  std::string text;
  try {
    text = util::read_input_file(path, 16u << 20);
  } catch (const util::InputFileError& e) {
    throw worlds::WorldError(path, "", e.what());
  }
  return parse_episode_config(text, path, base);
}

util::ParamValues component_values(const EpisodeConfig& c,
                                   const std::vector<util::ParamSpec>& specs) {
  util::ParamValues out;
  const std::vector<Field>& rows = table();
  for (const util::ParamSpec& spec : specs) {
    const std::string path = spec.path();
    const auto row =
        std::find_if(rows.begin(), rows.end(), [&](const Field& f) { return f.path() == path; });
    out.set(path, row == rows.end() ? spec.default_value : row->get(c));
  }
  return out;
}

double number_value(const EpisodeConfig& c, const std::string& path) {
  for (const Field& f : table())
    if (f.path() == path) return f.get(c);
  throw std::invalid_argument("'" + path + "': not a parameter");
}

std::vector<NumberParameter> number_parameters() {
  const EpisodeConfig defaults;
  std::vector<NumberParameter> out;
  auto add = [&](const Field& f, bool whole) {
    out.push_back({f.path(), f.lo, f.hi, f.above, whole, f.get(defaults)});
  };
  for (const Field& f : fields()) add(f, false);
  for (const Field& f : int_fields()) add(f, true);
  return out;
}

NumberParameter number_parameter(const std::string& path) {
  std::vector<std::string> known;
  for (const NumberParameter& p : number_parameters()) {
    if (p.path == path) return p;
    known.push_back(p.path);
  }
  throw std::invalid_argument("'" + path + "': " + worlds::unknown_key_problem(path, known) +
                              " (a number parameter of docs/config.md, as section.key)");
}

std::string default_config_json() { return config_json(EpisodeConfig{}); }

std::string config_json(const EpisodeConfig& c) {
  nlohmann::ordered_json j;
  worlds::write_param_rows(j, fields(), c);
  worlds::write_param_rows(j, int_fields(), c);
  worlds::write_param_rows(j, bool_fields(), c);
  worlds::write_param_rows(j, choices(), c);
  j["travel"] = c.travel;
  j["local_controller"] = c.local_controller;
  j["localization"]["estimator"] = c.perception.estimator;
  j["docking"]["detector"] = c.perception.dock_detector;
  j["seed"] = c.seed;
  return j.dump(2) + "\n";
}

}  // namespace plantsim::episode
