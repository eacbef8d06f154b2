// The record schema's table and its checks.
#include "batch/record_schema.h"

#include <cstdint>
#include <nlohmann/json.hpp>

#include "worlds/json_input.h"
#include "worlds/world_error.h"

namespace plantsim::batch {
namespace {

using nlohmann::json;

enum class Kind {
  kText,
  kFlag,
  kNumber,        // a finite number (read as such by every summary)
  kNumberOrNull,  // a metric that is NaN, written as null, where it was not measured
  kCount,         // a whole number from 0
  kTextOrNull,    // the failure reason: null when none
  kPose,          // [x, y, yaw]
  kNumberList,    // the driven path, in millimetres
  kBoxList,       // the unmapped boxes, [[xmin, ymin, xmax, ymax], ...]
};

struct Field {
  const char* name;
  Kind kind;
  bool required;
};

// Required: what the readers take without asking (summary tables, report, gate, merge).
constexpr Field kFields[] = {
    {"index", Kind::kCount, true},
    {"id", Kind::kText, true},
    {"scenario", Kind::kText, true},
    {"scenario_episodes", Kind::kCount, false},
    {"scenario_file", Kind::kText, false},
    {"build", Kind::kText, false},  // records before issue 89 have none
    {"key", Kind::kText, false},
    {"world", Kind::kText, true},
    {"planner", Kind::kText, true},
    {"controller", Kind::kText, true},
    {"fault", Kind::kText, true},
    {"sweep_parameter", Kind::kText, false},
    {"sweep_value", Kind::kText, false},
    {"seed", Kind::kCount, true},
    {"start", Kind::kPose, false},
    {"goal", Kind::kText, false},
    {"succeeded", Kind::kFlag, true},
    {"status", Kind::kText, true},
    {"failure", Kind::kTextOrNull, true},
    {"failure_time_s", Kind::kNumberOrNull, false},
    {"failure_pose", Kind::kPose, false},
    {"failure_detail", Kind::kText, false},
    {"docked", Kind::kFlag, true},
    {"charging", Kind::kFlag, false},
    {"undocked", Kind::kFlag, false},
    {"caught", Kind::kFlag, false},
    {"travel", Kind::kText, false},
    {"steered_by", Kind::kText, false},
    {"local_minima", Kind::kCount, false},
    {"wall_follows", Kind::kCount, false},
    {"position_error_m", Kind::kNumber, true},
    {"heading_error_deg", Kind::kNumber, true},
    {"error_measured", Kind::kFlag, false},
    {"collisions", Kind::kCount, true},
    {"collisions_robot_moving", Kind::kCount, false},
    {"retries", Kind::kCount, true},
    {"stops", Kind::kCount, false},
    {"replans", Kind::kCount, false},
    {"recoveries", Kind::kCount, false},
    {"slips", Kind::kCount, false},
    {"time_s", Kind::kNumber, true},
    {"path_length_m", Kind::kNumber, true},
    {"driven_length_m", Kind::kNumber, true},
    {"max_cross_track_m", Kind::kNumberOrNull, false},
    {"perception_mode", Kind::kText, false},
    {"localization_error_max_m", Kind::kNumberOrNull, false},
    {"localization_status", Kind::kText, false},
    {"relocalizations", Kind::kCount, false},
    {"worst_moving_error_m", Kind::kNumber, false},
    {"driven_off_estimate_s", Kind::kNumber, false},
    {"driven_off_estimate_m", Kind::kNumber, false},
    {"ok_while_off_s", Kind::kNumber, false},
    {"localization_not_ok_s", Kind::kNumber, false},
    {"unmapped_seen", Kind::kCount, false},
    {"min_clearance_m", Kind::kNumberOrNull, false},
    {"mean_clearance_m", Kind::kNumberOrNull, false},
    {"near_obstacle_share", Kind::kNumberOrNull, false},
    {"rms_jerk_mps3", Kind::kNumberOrNull, false},
    {"rms_angular_accel_radps2", Kind::kNumberOrNull, false},
    {"controller_cycles", Kind::kCount, false},
    {"controller_ms_median", Kind::kNumberOrNull, false},
    {"controller_ms_p99", Kind::kNumberOrNull, false},
    {"optimal_length_m", Kind::kNumber, true},
    {"optimal_driven_m", Kind::kNumber, false},  // records before shortest_possible_m
    {"shortest_possible_m", Kind::kNumber, false},
    {"path_mm", Kind::kNumberList, false},
    {"unmapped", Kind::kBoxList, false},
};

bool numbers(const json& v, std::size_t size) {
  if (!v.is_array() || (size > 0 && v.size() != size)) return false;
  for (const json& x : v)
    if (!x.is_number()) return false;
  return true;
}

// Empty when `v` is of `kind`; else what was expected.
std::string mismatch(const json& v, Kind kind) {
  switch (kind) {
    case Kind::kText:
      return v.is_string() ? "" : "expected text";
    case Kind::kFlag:
      return v.is_boolean() ? "" : "expected true or false";
    case Kind::kNumber:
      return v.is_number() ? "" : "expected a number";
    case Kind::kNumberOrNull:
      return v.is_number() || v.is_null() ? "" : "expected a number or null";
    case Kind::kCount:
      return v.is_number_unsigned() ? "" : "expected a whole number from 0";
    case Kind::kTextOrNull:
      return v.is_string() || v.is_null() ? "" : "expected text or null";
    case Kind::kPose:
      return numbers(v, 3) ? "" : "expected [x, y, yaw]";
    case Kind::kNumberList:
      return numbers(v, 0) && v.size() % 2 == 0 ? "" : "expected a list of x, y numbers";
    case Kind::kBoxList:
      if (v.is_array()) {
        bool boxes = true;
        for (const json& b : v) boxes = boxes && numbers(b, 4);
        if (boxes) return "";
      }
      return "expected a list of [xmin, ymin, xmax, ymax]";
  }
  return "unknown kind";
}

}  // namespace

std::string record_problem(const std::string& line) {
  json j;
  const std::string source = "record";
  try {
    j = worlds::parse_json_input(line, source);  // refuses a key given twice
  } catch (const worlds::WorldError& e) {
    return std::string(e.what()).substr(source.size() + 2);  // without "record: "
  }
  if (!j.is_object()) return "not a JSON object";
  for (const Field& f : kFields) {
    const auto it = j.find(f.name);
    if (it == j.end()) {
      if (f.required) return std::string("field '") + f.name + "': missing";
      continue;
    }
    const std::string problem = mismatch(*it, f.kind);
    if (!problem.empty()) return std::string("field '") + f.name + "': " + problem;
  }
  // The id names the episode (world|planner|controller|fault|seed, names that hold no '|'):
  // a record whose fields say otherwise is not the episode its id claims.
  const std::string expected =
      j["world"].get<std::string>() + "|" + j["planner"].get<std::string>() + "|" +
      j["controller"].get<std::string>() + "|" + j["fault"].get<std::string>() + "|" +
      std::to_string(j["seed"].get<std::uint64_t>());
  if (j["id"].get<std::string>() != expected)
    return "field 'id': '" + j["id"].get<std::string>() + "' is not the record's own episode ('" +
           expected + "')";
  return "";
}

}  // namespace plantsim::batch
