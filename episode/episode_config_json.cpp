// Every parameter, read and written by the same rows: each module declares its own
// (sim/sim_param_rows.h, robot/robot_param_rows.h, controller/controller_param_rows.h); this file
// only assembles them with the episode's own and reads and writes the file.
#include "episode/episode_config_json.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>

#include "controller/controller_param_rows.h"
#include "robot/robot_param_rows.h"
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

/// Every parameter: each module's rows, assembled (in docs/config.md's section order, which is
/// also the order `plantsim config` writes them in).
const std::vector<Field>& table() {
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

/// The rows of one kind, in the table's order: reals, whole numbers and flags are read and
/// written in turn.
std::vector<Field> rows_of(util::ParamKind kind) {
  std::vector<Field> out;
  for (const Field& f : table())
    if (f.kind == kind) out.push_back(f);
  return out;
}
const std::vector<Field>& fields() {
  static const std::vector<Field> rows = rows_of(util::ParamKind::kReal);
  return rows;
}
const std::vector<Field>& int_fields() {
  static const std::vector<Field> rows = rows_of(util::ParamKind::kWhole);
  return rows;
}
const std::vector<Field>& bool_fields() {
  static const std::vector<Field> rows = rows_of(util::ParamKind::kFlag);
  return rows;
}

void read_tables(worlds::ParamDocument& doc, EpisodeConfig& c) {
  doc.read(fields(), c);
  doc.read(int_fields(), c);
  doc.read(bool_fields(), c);
}

/// The choices: the perception's (robot/robot_param_rows.h) and how the robot travels.
const util::ChoiceRows<EpisodeConfig>& choices() {
  static const util::ChoiceRows<EpisodeConfig> rows = [] {
    util::ChoiceRows<EpisodeConfig> t;
    util::append_choices_of_part(t, robot::perception_choice_rows(), PLANTSIM_PART(perception));
    t.push_back(PLANTSIM_CHOICE("", travel, "travel", TravelMode, {"path", TravelMode::kPath},
                                {"potential-field", TravelMode::kPotentialField}));
    return t;
  }();
  return rows;
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
  read_seed(doc, c);
  doc.refuse_unknown();
  check_consistency(source, c);
  return c;
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
  j["seed"] = c.seed;
  return j.dump(2) + "\n";
}

}  // namespace plantsim::episode
