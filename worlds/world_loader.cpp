// World JSON reading and validation. Two schemas are recognised by their keys: plantsim's own
// ("floor", "obstacles", "robot", "charger", "start") and the plain benchmark worlds ("W",
// "H", "rects", "start", "goal"), whose goal becomes the charger with a chosen heading.
#include "worlds/world_loader.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "geometry/predicates.h"
#include "worlds/charger_placement.h"
#include "worlds/ros_map.h"
#include "worlds/world_limits.h"

namespace plantsim::worlds {
namespace {

using nlohmann::json;

// Reads typed fields out of JSON, naming the dotted field path in every error.
class FieldReader {
 public:
  explicit FieldReader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& field, const std::string& problem) const {
    throw WorldError(source_, field, problem);
  }

  const json& member(const json& obj, const std::string& key, const std::string& path) const {
    if (!obj.is_object()) fail(path, "expected an object");
    auto it = obj.find(key);
    if (it == obj.end()) fail(join(path, key), "missing");
    return *it;
  }

  double number(const json& value, const std::string& path) const {
    if (!value.is_number()) fail(path, std::string("expected a number, got ") + value.type_name());
    const double v = value.get<double>();
    if (!std::isfinite(v)) fail(path, "must be finite");
    return v;
  }

  double number(const json& obj, const std::string& key, const std::string& path) const {
    return number(member(obj, key, path), join(path, key));
  }

  double number_or(const json& obj, const std::string& key, const std::string& path,
                   double fallback) const {
    if (!obj.contains(key)) return fallback;
    return number(obj, key, path);
  }

  double positive(const json& obj, const std::string& key, const std::string& path) const {
    const double v = number(obj, key, path);
    if (v <= 0) fail(join(path, key), "must be positive");
    return v;
  }

  Rect rect_array(const json& value, const std::string& path) const {
    if (!value.is_array() || value.size() != 4)
      fail(path, "expected [xmin, ymin, xmax, ymax]");
    Rect r{number(value[0], path + "[0]"), number(value[1], path + "[1]"),
           number(value[2], path + "[2]"), number(value[3], path + "[3]")};
    if (r.xmax <= r.xmin || r.ymax <= r.ymin)
      fail(path, "needs xmax > xmin and ymax > ymin (a negative or zero size)");
    return r;
  }

  Vec2 point_array(const json& value, const std::string& path) const {
    if (!value.is_array() || value.size() != 2) fail(path, "expected [x, y]");
    return {number(value[0], path + "[0]"), number(value[1], path + "[1]")};
  }

  Pose2 pose(const json& value, const std::string& path) const {
    return {number(value, "x", path), number(value, "y", path), number(value, "yaw", path)};
  }

  std::vector<Rect> rects(const json& value, const std::string& path) const {
    if (!value.is_array()) fail(path, "expected an array of [xmin, ymin, xmax, ymax]");
    if (value.size() > kMaxObstacles)
      fail(path, "has " + std::to_string(value.size()) + " rectangles, more than the limit of " +
                     std::to_string(kMaxObstacles));
    std::vector<Rect> out;
    out.reserve(value.size());
    for (std::size_t i = 0; i < value.size(); ++i)
      out.push_back(rect_array(value[i], path + "[" + std::to_string(i) + "]"));
    return out;
  }

  static std::string join(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
  }

 private:
  std::string source_;
};

std::string stem_of(const std::string& path) {
  return std::filesystem::path(path).stem().string();
}

// A box on a scripted path: a moving obstacle or the moving target.
MovingObstacle read_scripted_box(const FieldReader& in, const json& m, const std::string& path) {
  if (!m.is_object()) in.fail(path, "expected an object");
  MovingObstacle mo;
  mo.name = m.contains("name") && m["name"].is_string() ? m["name"].get<std::string>() : path;
  const json& size = in.member(m, "size_m", path);
  const Vec2 wh = in.point_array(size, path + ".size_m");
  if (wh.x <= 0 || wh.y <= 0) in.fail(path + ".size_m", "must be positive");
  mo.width_m = wh.x;
  mo.height_m = wh.y;
  const json& wps = in.member(m, "waypoints", path);
  if (!wps.is_array() || wps.empty()) in.fail(path + ".waypoints", "expected a non-empty array of [x, y]");
  for (std::size_t k = 0; k < wps.size(); ++k)
    mo.waypoints.push_back(in.point_array(wps[k], path + ".waypoints[" + std::to_string(k) + "]"));
  mo.speed_mps = in.number_or(m, "speed_mps", path, 0.0);
  if (mo.speed_mps < 0) in.fail(path + ".speed_mps", "must not be negative");
  mo.start_time_s = in.number_or(m, "start_time_s", path, 0.0);
  if (m.contains("loop")) {
    if (!m["loop"].is_boolean()) in.fail(path + ".loop", "expected true or false");
    mo.loop = m["loop"].get<bool>();
  }
  if (m.contains("yields_to_robot")) {
    if (!m["yields_to_robot"].is_boolean()) in.fail(path + ".yields_to_robot", "expected true or false");
    mo.yields_to_robot = m["yields_to_robot"].get<bool>();
  }
  mo.yield_distance_m = in.number_or(m, "yield_distance_m", path, mo.yield_distance_m);
  if (mo.yield_distance_m < 0) in.fail(path + ".yield_distance_m", "must not be negative");
  return mo;
}

// Seed 003's tunnel lattice: {"origin": [x, y], "pitch_m", "corridor_m", "columns", "rows",
// "corridors": [[[c, r], [c, r]], ...]} with each corridor a straight run between two nodes.
TunnelMaze read_tunnel_maze(const FieldReader& in, const json& m) {
  const std::string path = "tunnel_maze";
  if (!m.is_object()) in.fail(path, "expected an object");
  const Vec2 origin = in.point_array(in.member(m, "origin", path), path + ".origin");
  const double pitch = in.positive(m, "pitch_m", path), corridor = in.positive(m, "corridor_m", path);
  if (corridor >= pitch) in.fail(path + ".corridor_m", "must be less than pitch_m");
  auto count = [&](const char* key) {
    const json& v = in.member(m, key, path);
    if (!v.is_number_integer() || v.get<long>() < 1 || v.get<long>() > 1000)
      in.fail(path + "." + key, "expected a whole number from 1 to 1000");
    return v.get<int>();
  };
  TunnelMaze maze(origin, pitch, corridor, count("columns"), count("rows"));
  const json& runs = in.member(m, "corridors", path);
  if (!runs.is_array() || runs.empty()) in.fail(path + ".corridors", "expected a non-empty array of [[c, r], [c, r]]");
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const std::string where = path + ".corridors[" + std::to_string(i) + "]";
    const json& run = runs[i];
    if (!run.is_array() || run.size() != 2) in.fail(where, "expected [[c, r], [c, r]]");
    LatticeNode ends[2];
    for (int k = 0; k < 2; ++k) {
      const json& e = run[k];
      if (!e.is_array() || e.size() != 2 || !e[0].is_number_integer() || !e[1].is_number_integer())
        in.fail(where, "expected [[c, r], [c, r]] with whole numbers");
      ends[k] = {e[0].get<int>(), e[1].get<int>()};
    }
    try {
      maze.open_run(ends[0], ends[1]);
    } catch (const std::invalid_argument& ex) {
      in.fail(where, ex.what());
    }
  }
  return maze;
}

// The plant's differences from the map (both schemas): unmapped boxes and the charger's offset.
void read_map_mismatch(const json& doc, const FieldReader& in, World& w) {
  if (doc.contains("unmapped")) w.unmapped = in.rects(doc["unmapped"], "unmapped");
  if (doc.contains("charger_map_offset")) {
    const json& o = doc["charger_map_offset"];
    if (!o.is_array() || o.size() != 3) in.fail("charger_map_offset", "expected [dx, dy, dyaw] (m, m, rad)");
    w.charger_map_offset = {in.number(o[0], "charger_map_offset[0]"), in.number(o[1], "charger_map_offset[1]"),
                            in.number(o[2], "charger_map_offset[2]")};
  }
}

World read_plantsim_schema(const json& doc, const FieldReader& in, const std::string& source) {
  World w;
  w.source = source;
  w.name = doc.contains("name") && doc["name"].is_string() ? doc["name"].get<std::string>()
                                                          : stem_of(source);
  if (doc.contains("tunnel_maze")) {
    // The floor and the rock come from the lattice; further obstacles may be added.
    if (doc.contains("floor")) in.fail("floor", "a tunnel_maze world takes its floor from the lattice");
    w.maze = read_tunnel_maze(in, doc["tunnel_maze"]);
    w.floor = w.maze->floor();
    w.obstacles = w.maze->rock();
    if (doc.contains("obstacles")) {
      const std::vector<Rect> extra = in.rects(doc["obstacles"], "obstacles");
      w.obstacles.insert(w.obstacles.end(), extra.begin(), extra.end());
    }
  } else {
    const json& floor = in.member(doc, "floor", "");
    w.floor = {in.number(floor, "xmin", "floor"), in.number(floor, "ymin", "floor"),
               in.number(floor, "xmax", "floor"), in.number(floor, "ymax", "floor")};
    if (w.floor.xmax <= w.floor.xmin || w.floor.ymax <= w.floor.ymin)
      in.fail("floor", "needs xmax > xmin and ymax > ymin (a negative or zero size)");
    w.obstacles = in.rects(in.member(doc, "obstacles", ""), "obstacles");
  }

  const json& robot = in.member(doc, "robot", "");
  if (robot.contains("footprint")) {
    // A rectangle: the planner and the safety checks use its circumscribed radius.
    const json& fp = robot["footprint"];
    w.robot.length_m = in.positive(fp, "length_m", "robot.footprint");
    w.robot.width_m = in.positive(fp, "width_m", "robot.footprint");
    w.robot.radius_m = 0.5 * std::hypot(w.robot.length_m, w.robot.width_m);
    if (robot.contains("radius_m")) in.fail("robot.radius_m", "give either radius_m (a disk) or footprint (a rectangle)");
  } else {
    w.robot.radius_m = in.positive(robot, "radius_m", "robot");
  }
  w.robot.wheel_base_m = in.positive(robot, "wheel_base_m", "robot");
  w.robot.wheel_radius_m = in.positive(robot, "wheel_radius_m", "robot");
  w.robot.max_speed_mps = in.positive(robot, "max_speed_mps", "robot");
  w.robot.max_accel_mps2 = in.positive(robot, "max_accel_mps2", "robot");
  if (robot.contains("mass_kg")) w.robot.mass_kg = in.positive(robot, "mass_kg", "robot");

  w.start = in.pose(in.member(doc, "start", ""), "start");
  w.charger = in.pose(in.member(doc, "charger", ""), "charger");
  const json& charger = doc["charger"];
  if (charger.contains("width_m")) w.charger_spec.width_m = in.positive(charger, "width_m", "charger");
  if (charger.contains("depth_m")) w.charger_spec.depth_m = in.positive(charger, "depth_m", "charger");
  if (charger.contains("pad_travel_m")) {
    w.charger_spec.pad_travel_m = in.number(charger, "pad_travel_m", "charger");
    if (w.charger_spec.pad_travel_m < 0 || w.charger_spec.pad_travel_m > 0.05)
      in.fail("charger.pad_travel_m", "must be from 0 to 0.05 m");
  }
  if (charger.contains("staging_distance_m"))
    w.charger_spec.staging_distance_m = in.positive(charger, "staging_distance_m", "charger");
  w.inflation_margin_m = in.number_or(doc, "inflation_margin_m", "", w.inflation_margin_m);
  if (w.inflation_margin_m < 0) in.fail("inflation_margin_m", "must not be negative");
  read_map_mismatch(doc, in, w);
  if (doc.contains("moving_obstacles")) {
    const json& list = doc["moving_obstacles"];
    if (!list.is_array()) in.fail("moving_obstacles", "expected an array");
    for (std::size_t i = 0; i < list.size(); ++i)
      w.moving.push_back(read_scripted_box(in, list[i], "moving_obstacles[" + std::to_string(i) + "]"));
  }
  if (doc.contains("target")) {
    w.target = read_scripted_box(in, doc["target"], "target");
    for (std::size_t k = 0; k < w.target->waypoints.size(); ++k) {
      const Vec2 p = w.target->waypoints[k];
      if (p.x < w.floor.xmin || p.x > w.floor.xmax || p.y < w.floor.ymin || p.y > w.floor.ymax)
        in.fail("target.waypoints[" + std::to_string(k) + "]", "lies outside the floor");
    }
  }
  return w;
}

World read_plain_schema(const json& doc, const FieldReader& in, const std::string& source) {
  World w;
  w.source = source;
  w.name = stem_of(source);
  const double width = in.number(doc, "W", "");
  const double height = in.number(doc, "H", "");
  if (width <= 0) in.fail("W", "must be positive");
  if (height <= 0) in.fail("H", "must be positive");
  w.floor = {0.0, 0.0, width, height};
  w.obstacles = in.rects(in.member(doc, "rects", ""), "rects");
  const Vec2 start = in.point_array(in.member(doc, "start", ""), "start");
  const Vec2 goal = in.point_array(in.member(doc, "goal", ""), "goal");
  // The benchmark's optimal lengths assume 0.3 m square inflation: robot radius plus margin.
  w.robot = RobotSpec{};
  w.inflation_margin_m = kBenchmarkInflation_m - w.robot.radius_m;
  const Vec2 d = goal - start;
  w.start = {start.x, start.y, std::atan2(d.y, d.x)};
  w.charger = {goal.x, goal.y, 0.0};
  read_map_mismatch(doc, in, w);
  return w;
}

}  // namespace

void check_pose_free(const World& w, const Pose2& pose, const std::string& field) {
  const double r = w.robot.radius_m;
  const Vec2 p = pose.position();
  if (!geom::in_closed_rect(w.floor, p))
    throw WorldError(w.source, field, "lies outside the floor");
  if (!geom::in_closed_rect(w.floor.inflated(-r), p))
    throw WorldError(w.source, field, "robot footprint crosses the floor boundary");
  for (std::size_t i = 0; i < w.obstacles.size(); ++i) {
    const Rect& o = w.obstacles[i];
    const double dx = std::max({o.xmin - p.x, 0.0, p.x - o.xmax});
    const double dy = std::max({o.ymin - p.y, 0.0, p.y - o.ymax});
    if (dx * dx + dy * dy < r * r)
      throw WorldError(w.source, field,
                       "robot at (" + std::to_string(p.x) + ", " + std::to_string(p.y) +
                           ") is inside or overlaps obstacle " + std::to_string(i));
  }
}

namespace {

std::string read_file(const std::string& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) throw WorldError(path, "", "no such file");
  if (std::filesystem::is_directory(status))
    throw WorldError(path, "", "is a directory, expected a world file");
  const auto size = std::filesystem::file_size(path, ec);
  if (!ec && size > kMaxWorldFileBytes)
    throw WorldError(path, "", "file too large (" + std::to_string(size) + " bytes)");
  std::ifstream f(path, std::ios::binary);
  if (!f) throw WorldError(path, "", "cannot be opened for reading");
  std::ostringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

}  // namespace

namespace {

// Unmapped obstacles lie on the floor and leave the start, the docked pose and the charger
// body free (a pallet dropped on the charger is a different test from a map that is wrong).
void validate_unmapped(const World& w) {
  const double r = w.robot.radius_m;
  const Rect charger_box = charger_body(w).bounding_box();
  for (std::size_t i = 0; i < w.unmapped.size(); ++i) {
    const Rect& o = w.unmapped[i];
    const std::string field = "unmapped[" + std::to_string(i) + "]";
    if (o.xmin < w.floor.xmin || o.ymin < w.floor.ymin || o.xmax > w.floor.xmax || o.ymax > w.floor.ymax)
      throw WorldError(w.source, field, "lies outside the floor");
    for (const auto& [pose, what] : {std::pair{w.start, "the start"}, std::pair{w.charger, "the charger's docked pose"}}) {
      const double dx = std::max({o.xmin - pose.x, 0.0, pose.x - o.xmax});
      const double dy = std::max({o.ymin - pose.y, 0.0, pose.y - o.ymax});
      if (dx * dx + dy * dy < r * r) throw WorldError(w.source, field, std::string("covers ") + what);
    }
    if (geom::rects_overlap_open(o, charger_box)) throw WorldError(w.source, field, "covers the charger");
  }
}

}  // namespace

void validate_world(const World& w) {
  if (w.floor.width() > kMaxFloorSide_m || w.floor.height() > kMaxFloorSide_m)
    throw WorldError(w.source, "floor",
                     "larger than " + std::to_string(kMaxFloorSide_m) + " m on a side (huge world)");
  if (w.robot.wheel_base_m > (w.robot.rectangular() ? w.robot.width_m : 2.0 * w.robot.radius_m))
    throw WorldError(w.source, "robot.wheel_base_m", "wheels must fit inside the footprint");
  check_pose_free(w, w.start, "start");
  check_pose_free(w, w.charger, "charger");
  if (!docking_area_clear(w))
    throw WorldError(w.source, "charger",
                     "no room to dock: the charger body, staging pose or final approach is "
                     "blocked by an obstacle or the floor boundary");
  validate_unmapped(w);
  if (differs_from_map(w)) {
    // The map's charger must itself be a place the robot could dock at, or nothing plans.
    const World map = robot_map(w);
    try {
      check_pose_free(map, map.charger, "charger");
    } catch (const WorldError& e) {
      throw WorldError(w.source, "charger_map_offset", std::string("puts the mapped charger where no robot fits: ") + e.what());
    }
    if (!docking_area_clear(map))
      throw WorldError(w.source, "charger_map_offset", "puts the mapped charger where there is no room to dock");
  }
}

World parse_world_json(const std::string& text, const std::string& source) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    throw WorldError(source, "", "file is empty");
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::exception& e) {
    throw WorldError(source, "", std::string("malformed JSON: ") + e.what());
  }
  if (!doc.is_object()) throw WorldError(source, "", "expected a JSON object at the top level");
  FieldReader in(source);
  World w;
  if (doc.contains("rects")) {
    w = read_plain_schema(doc, in, source);
    check_pose_free(w, w.start, "start");
    check_pose_free(w, w.charger, "goal");
    const auto heading = choose_docking_heading(w, w.charger.position());
    if (!heading) throw WorldError(source, "goal", "no heading leaves room for a charger here");
    w.charger.yaw = *heading;
  } else {
    w = read_plantsim_schema(doc, in, source);
  }
  validate_world(w);
  return w;
}

World load_world(const std::string& path, const PoseOverrides& overrides) {
  const std::string ext = std::filesystem::path(path).extension().string();
  World w;
  if (ext == ".yaml" || ext == ".yml") {
    w = world_from_ros_map(load_ros_map(path), stem_of(path), overrides.start, overrides.charger);
  } else {
    w = parse_world_json(read_file(path), path);
    if (overrides.start) w.start = *overrides.start;
    if (overrides.charger) w.charger = *overrides.charger;
    if (overrides.start || overrides.charger) validate_world(w);
  }
  return w;
}

}  // namespace plantsim::worlds
