// World JSON reading and validation. Two schemas are recognised by their keys: plantsim's own
// ("floor", "obstacles", "robot", "charger", "start") and the plain benchmark worlds ("W",
// "H", "rects", "start", "goal"), whose goal becomes the charger with a chosen heading.
#include "worlds/world_loader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "geometry/predicates.h"
#include "util/data_dir.h"
#include "util/input_file.h"
#include "worlds/charger_placement.h"
#include "worlds/json_input.h"
#include "worlds/known_keys.h"
#include "worlds/movingai_world.h"
#include "worlds/names.h"
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

  double finite(const json& value, const std::string& path) const {
    if (!value.is_number()) fail(path, std::string("expected a number, got ") + value.type_name());
    const double v = value.get<double>();
    if (!std::isfinite(v)) fail(path, "must be finite");
    return v;
  }

  /// A length or a coordinate.
  double number(const json& value, const std::string& path) const {
    const double v = finite(value, path);
    // Beyond this, differences of coordinates lose the millimetres docking is judged by.
    if (std::fabs(v) > kMaxCoordinate_m) fail(path, "beyond +-1e7 m: no plant is that large");
    return v;
  }

  /// A number from lo to hi (a robot 1e6 m wide, a speed of 1e300 are refused at load).
  double bounded(const json& obj, const std::string& key, const std::string& path, double lo,
                 double hi) const {
    const double v = finite(member(obj, key, path), join(path, key));
    if (v < lo || v > hi)
      fail(join(path, key), "must be from " + short_number(lo) + " to " + short_number(hi));
    return v;
  }

  /// Every key of `obj` must be one of `known`.
  void keys(const json& obj, const std::string& path, const std::vector<std::string>& known) const {
    if (!obj.is_object()) fail(path, "expected an object");
    for (const auto& [key, value] : obj.items())
      if (std::find(known.begin(), known.end(), key) == known.end())
        fail(join(path, key), unknown_key_problem(key, known));
  }

  double number(const json& obj, const std::string& key, const std::string& path) const {
    return number(member(obj, key, path), join(path, key));
  }

  double positive(const json& obj, const std::string& key, const std::string& path,
                  double most) const {
    const double v = number(obj, key, path);
    if (v <= 0) fail(join(path, key), "must be positive");
    if (v > most) fail(join(path, key), "must be at most " + short_number(most));
    return v;
  }

  Rect rect_array(const json& value, const std::string& path) const {
    if (!value.is_array() || value.size() != 4) fail(path, "expected [xmin, ymin, xmax, ymax]");
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

  Pose2 pose(const json& value, const std::string& path,
             const std::vector<std::string>& extra_keys = {}) const {
    std::vector<std::string> known = {"x", "y", "yaw"};
    known.insert(known.end(), extra_keys.begin(), extra_keys.end());
    keys(value, path, known);
    return {number(value, "x", path), number(value, "y", path),
            bounded(value, "yaw", path, -kMaxYaw_rad, kMaxYaw_rad)};
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

  static std::string short_number(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
  }

 private:
  std::string source_;
};

std::string stem_of(const std::string& path) {
  return name_from_file(path,
                        "rename the file, or give the world a \"name\" where it can hold one");
}

// A box on a scripted path: a moving obstacle or the moving target.
MovingObstacle read_scripted_box(const FieldReader& in, const json& m, const std::string& path) {
  in.keys(m, path,
          {"name", "size_m", "waypoints", "speed_mps", "start_time_s", "loop", "yields_to_robot",
           "yield_distance_m"});
  MovingObstacle mo;
  mo.name = path;
  if (m.contains("name")) {
    if (!m["name"].is_string()) in.fail(path + ".name", "expected a string");
    mo.name = m["name"].get<std::string>();
    if (const std::string problem = name_problem(mo.name); !problem.empty())
      in.fail(path + ".name", "the name " + problem);
  }
  const json& size = in.member(m, "size_m", path);
  const Vec2 wh = in.point_array(size, path + ".size_m");
  if (!(wh.x >= 0.01 && wh.y >= 0.01)) in.fail(path + ".size_m", "must be at least 0.01 m");
  mo.width_m = wh.x;
  mo.height_m = wh.y;
  const json& wps = in.member(m, "waypoints", path);
  if (!wps.is_array() || wps.empty())
    in.fail(path + ".waypoints", "expected a non-empty array of [x, y]");
  if (wps.size() > 10000) in.fail(path + ".waypoints", "more than 10000 waypoints");
  for (std::size_t k = 0; k < wps.size(); ++k)
    mo.waypoints.push_back(in.point_array(wps[k], path + ".waypoints[" + std::to_string(k) + "]"));
  if (m.contains("speed_mps")) mo.speed_mps = in.bounded(m, "speed_mps", path, 0.0, 50.0);
  if (m.contains("start_time_s")) mo.start_time_s = in.bounded(m, "start_time_s", path, 0.0, 1e6);
  if (m.contains("loop")) {
    if (!m["loop"].is_boolean()) in.fail(path + ".loop", "expected true or false");
    mo.loop = m["loop"].get<bool>();
  }
  if (m.contains("yields_to_robot")) {
    if (!m["yields_to_robot"].is_boolean())
      in.fail(path + ".yields_to_robot", "expected true or false");
    mo.yields_to_robot = m["yields_to_robot"].get<bool>();
  }
  if (m.contains("yield_distance_m"))
    mo.yield_distance_m = in.bounded(m, "yield_distance_m", path, 0.0, 100.0);
  return mo;
}

// Seed 003's tunnel lattice: {"origin": [x, y], "pitch_m", "corridor_m", "columns", "rows",
// "corridors": [[[c, r], [c, r]], ...]} with each corridor a straight run between two nodes.
TunnelMaze read_tunnel_maze(const FieldReader& in, const json& m) {
  const std::string path = "tunnel_maze";
  in.keys(m, path, {"origin", "pitch_m", "corridor_m", "columns", "rows", "corridors"});
  const Vec2 origin = in.point_array(in.member(m, "origin", path), path + ".origin");
  const double pitch = in.positive(m, "pitch_m", path, 1000.0),
               corridor = in.positive(m, "corridor_m", path, 1000.0);
  if (corridor >= pitch) in.fail(path + ".corridor_m", "must be less than pitch_m");
  auto count = [&](const char* key) {
    const json& v = in.member(m, key, path);
    if (!v.is_number_integer() || v.get<std::int64_t>() < 1 || v.get<std::int64_t>() > 1000)
      in.fail(path + "." + key, "expected a whole number from 1 to 1000");
    return static_cast<int>(v.get<std::int64_t>());
  };
  TunnelMaze maze(origin, pitch, corridor, count("columns"), count("rows"));
  const json& runs = in.member(m, "corridors", path);
  if (!runs.is_array() || runs.empty())
    in.fail(path + ".corridors", "expected a non-empty array of [[c, r], [c, r]]");
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const std::string where = path + ".corridors[" + std::to_string(i) + "]";
    const json& run = runs[i];
    if (!run.is_array() || run.size() != 2) in.fail(where, "expected [[c, r], [c, r]]");
    LatticeNode ends[2];
    for (int k = 0; k < 2; ++k) {
      const json& e = run[k];
      if (!e.is_array() || e.size() != 2 || !e[0].is_number_integer() || !e[1].is_number_integer())
        in.fail(where, "expected [[c, r], [c, r]] with whole numbers");
      // Read wide, then range-checked: 4294967296 must not wrap to column 0.
      for (int axis = 0; axis < 2; ++axis) {
        const bool unsigned_big =
            e[axis].is_number_unsigned() && e[axis].get<std::uint64_t>() > 1000000;
        const std::int64_t v = unsigned_big ? -1 : e[axis].get<std::int64_t>();
        const std::int64_t limit = axis == 0 ? maze.columns() : maze.rows();
        if (v < 0 || v >= limit)
          in.fail(where + "[" + std::to_string(k) + "][" + std::to_string(axis) + "]",
                  std::string("must be a ") + (axis == 0 ? "column" : "row") + " from 0 to " +
                      std::to_string(limit - 1));
      }
      ends[k] = {static_cast<int>(e[0].get<std::int64_t>()),
                 static_cast<int>(e[1].get<std::int64_t>())};
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
    if (!o.is_array() || o.size() != 3)
      in.fail("charger_map_offset", "expected [dx, dy, dyaw] (m, m, rad)");
    w.charger_map_offset = {in.number(o[0], "charger_map_offset[0]"),
                            in.number(o[1], "charger_map_offset[1]"),
                            in.number(o[2], "charger_map_offset[2]")};
    // As in scenarios (docs/batch.md): beyond this it is another charger, not an error of the map.
    if (std::hypot(w.charger_map_offset.x, w.charger_map_offset.y) > 0.5 ||
        std::fabs(w.charger_map_offset.yaw) > 0.5)
      in.fail("charger_map_offset",
              "more than 0.5 m or 0.5 rad: that is a different charger, not a map error");
  }
}

// A world's name labels figures and reports, makes ids and folder names: one rule for all names
// (worlds/names.h).
std::string read_name(const json& doc, const FieldReader& in, const std::string& source) {
  if (!doc.contains("name")) return stem_of(source);
  if (!doc["name"].is_string()) in.fail("name", "expected a string");
  const std::string name = doc["name"].get<std::string>();
  if (const std::string problem = name_problem(name); !problem.empty())
    in.fail("name", "the name " + problem);
  return name;
}

// The floor and the obstacles: given, or a tunnel maze's lattice (to which obstacles may be added).
void read_floor_and_obstacles(const json& doc, const FieldReader& in, World& w) {
  if (doc.contains("tunnel_maze")) {
    if (doc.contains("floor"))
      in.fail("floor", "a tunnel_maze world takes its floor from the lattice");
    w.maze = read_tunnel_maze(in, doc["tunnel_maze"]);
    w.floor = w.maze->floor();
    w.obstacles = w.maze->rock();
    if (doc.contains("obstacles")) {
      const std::vector<Rect> extra = in.rects(doc["obstacles"], "obstacles");
      w.obstacles.insert(w.obstacles.end(), extra.begin(), extra.end());
    }
    return;
  }
  const json& floor = in.member(doc, "floor", "");
  in.keys(floor, "floor", {"xmin", "ymin", "xmax", "ymax"});
  w.floor = {in.number(floor, "xmin", "floor"), in.number(floor, "ymin", "floor"),
             in.number(floor, "xmax", "floor"), in.number(floor, "ymax", "floor")};
  if (w.floor.xmax <= w.floor.xmin || w.floor.ymax <= w.floor.ymin)
    in.fail("floor", "needs xmax > xmin and ymax > ymin (a negative or zero size)");
  w.obstacles = in.rects(in.member(doc, "obstacles", ""), "obstacles");
}

void read_robot(const json& doc, const FieldReader& in, World& w) {
  const json& robot = in.member(doc, "robot", "");
  in.keys(robot, "robot",
          {"radius_m", "footprint", "wheel_base_m", "wheel_radius_m", "max_speed_mps",
           "max_accel_mps2", "mass_kg"});
  if (robot.contains("footprint")) {
    // A rectangle: the planner and the safety checks use its circumscribed radius.
    const json& fp = robot["footprint"];
    in.keys(fp, "robot.footprint", {"length_m", "width_m"});
    w.robot.length_m = in.positive(fp, "length_m", "robot.footprint", 20.0);
    w.robot.width_m = in.positive(fp, "width_m", "robot.footprint", 20.0);
    w.robot.radius_m = 0.5 * std::hypot(w.robot.length_m, w.robot.width_m);
    if (robot.contains("radius_m"))
      in.fail("robot.radius_m", "give either radius_m (a disk) or footprint (a rectangle)");
  } else {
    w.robot.radius_m = in.positive(robot, "radius_m", "robot", 10.0);
  }
  // Lower limits where the physics (Box2D holds single-precision floats) or the drive's
  // arithmetic stops meaning anything: a 1e-300 kg robot never moved, a wheel base of 1e-9 m
  // turned the robot on the spot until the timeout.
  w.robot.wheel_base_m = in.bounded(robot, "wheel_base_m", "robot", 0.01, 20.0);
  w.robot.wheel_radius_m = in.bounded(robot, "wheel_radius_m", "robot", 0.001, 5.0);
  w.robot.max_speed_mps = in.bounded(robot, "max_speed_mps", "robot", 0.01, 20.0);
  w.robot.max_accel_mps2 = in.bounded(robot, "max_accel_mps2", "robot", 0.01, 100.0);
  if (robot.contains("mass_kg"))
    w.robot.mass_kg = in.bounded(robot, "mass_kg", "robot", 0.1, 100000.0);
}

void read_charger(const json& doc, const FieldReader& in, World& w) {
  w.charger = in.pose(in.member(doc, "charger", ""), "charger",
                      {"width_m", "depth_m", "staging_distance_m", "pad_travel_m"});
  const json& charger = doc["charger"];
  // At least a centimetre: a charger 5e-324 m wide loaded and was never seen.
  if (charger.contains("width_m"))
    w.charger_spec.width_m = in.bounded(charger, "width_m", "charger", 0.01, 10.0);
  if (charger.contains("depth_m"))
    w.charger_spec.depth_m = in.bounded(charger, "depth_m", "charger", 0.01, 10.0);
  if (charger.contains("pad_travel_m")) {
    w.charger_spec.pad_travel_m = in.number(charger, "pad_travel_m", "charger");
    if (w.charger_spec.pad_travel_m < 0 || w.charger_spec.pad_travel_m > 0.05)
      in.fail("charger.pad_travel_m", "must be from 0 to 0.05 m");
  }
  if (charger.contains("staging_distance_m"))
    w.charger_spec.staging_distance_m =
        in.positive(charger, "staging_distance_m", "charger", 100.0);
}

// What moves: scripted obstacles and the target a robot may be asked to follow.
void read_movers(const json& doc, const FieldReader& in, World& w) {
  if (doc.contains("moving_obstacles")) {
    const json& list = doc["moving_obstacles"];
    if (!list.is_array()) in.fail("moving_obstacles", "expected an array");
    if (list.size() > 1000) in.fail("moving_obstacles", "more than 1000 moving obstacles");
    for (std::size_t i = 0; i < list.size(); ++i)
      w.moving.push_back(
          read_scripted_box(in, list[i], "moving_obstacles[" + std::to_string(i) + "]"));
  }
  if (doc.contains("target")) {
    w.target = read_scripted_box(in, doc["target"], "target");
    for (std::size_t k = 0; k < w.target->waypoints.size(); ++k) {
      const Vec2 p = w.target->waypoints[k];
      if (p.x < w.floor.xmin || p.x > w.floor.xmax || p.y < w.floor.ymin || p.y > w.floor.ymax)
        in.fail("target.waypoints[" + std::to_string(k) + "]", "lies outside the floor");
    }
  }
}

World read_plantsim_schema(const json& doc, const FieldReader& in, const std::string& source) {
  in.keys(doc, "",
          {"name", "comment", "description", "floor", "obstacles", "robot", "start", "charger",
           "inflation_margin_m", "unmapped", "charger_map_offset", "moving_obstacles", "target",
           "tunnel_maze"});
  World w;
  w.source = source;
  w.name = read_name(doc, in, source);
  read_floor_and_obstacles(doc, in, w);
  read_robot(doc, in, w);
  w.start = in.pose(in.member(doc, "start", ""), "start");
  read_charger(doc, in, w);
  if (doc.contains("inflation_margin_m"))
    w.inflation_margin_m = in.bounded(doc, "inflation_margin_m", "", 0.0, 100.0);
  read_map_mismatch(doc, in, w);
  read_movers(doc, in, w);
  return w;
}

World read_plain_schema(const json& doc, const FieldReader& in, const std::string& source) {
  // n, seed, min_gap, inflation and queries describe how a benchmark world was made and what
  // its optimal lengths are; they are accepted and not used here.
  in.keys(doc, "",
          {"W", "H", "rects", "start", "goal", "unmapped", "charger_map_offset", "comment", "n",
           "seed", "min_gap", "inflation", "queries", "inflated_case"});
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
  if (!std::filesystem::exists(path, ec)) throw WorldError(path, "", "no such file");
  try {
    return util::read_input_file(path, kMaxWorldFileBytes);
  } catch (const util::InputFileError& e) {
    throw WorldError(path, "", e.what());
  }
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
    if (o.xmin < w.floor.xmin || o.ymin < w.floor.ymin || o.xmax > w.floor.xmax ||
        o.ymax > w.floor.ymax)
      throw WorldError(w.source, field, "lies outside the floor");
    for (const auto& [pose, what] :
         {std::pair{w.start, "the start"}, std::pair{w.charger, "the charger's docked pose"}}) {
      const double dx = std::max({o.xmin - pose.x, 0.0, pose.x - o.xmax});
      const double dy = std::max({o.ymin - pose.y, 0.0, pose.y - o.ymax});
      if (dx * dx + dy * dy < r * r)
        throw WorldError(w.source, field, std::string("covers ") + what);
    }
    if (geom::rects_overlap_open(o, charger_box))
      throw WorldError(w.source, field, "covers the charger");
  }
}

// A mover that covers the robot at t = 0 begins the episode in contact: a world that cannot be
// run, not a collision to count (only definite overlaps: the footprint's inscribed disk).
void check_movers_clear_of_start(const World& w) {
  const double r =
      w.robot.rectangular() ? 0.5 * std::min(w.robot.length_m, w.robot.width_m) : w.robot.radius_m;
  for (std::size_t i = 0; i < w.moving.size(); ++i) {
    const Rect o = w.moving[i].box_at(0.0);
    const double dx = std::max({o.xmin - w.start.x, 0.0, w.start.x - o.xmax});
    const double dy = std::max({o.ymin - w.start.y, 0.0, w.start.y - o.ymax});
    if (dx * dx + dy * dy < r * r)
      throw WorldError(w.source, "moving_obstacles[" + std::to_string(i) + "]",
                       "covers the robot at the start at t = 0 (it would begin in contact)");
  }
}

}  // namespace

void validate_world(const World& w) {
  if (w.floor.width() > kMaxFloorSide_m || w.floor.height() > kMaxFloorSide_m)
    throw WorldError(
        w.source, "floor",
        "larger than " + std::to_string(kMaxFloorSide_m) + " m on a side (huge world)");
  if (w.robot.wheel_base_m > (w.robot.rectangular() ? w.robot.width_m : 2.0 * w.robot.radius_m))
    throw WorldError(w.source, "robot.wheel_base_m", "wheels must fit inside the footprint");
  check_pose_free(w, w.start, "start");
  check_pose_free(w, w.charger, "charger");
  check_movers_clear_of_start(w);
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
      throw WorldError(w.source, "charger_map_offset",
                       std::string("puts the mapped charger where no robot fits: ") + e.what());
    }
    if (!docking_area_clear(map))
      throw WorldError(w.source, "charger_map_offset",
                       "puts the mapped charger where there is no room to dock");
  }
}

World parse_world_json(const std::string& text, const std::string& source) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    throw WorldError(source, "", "file is empty");
  const json doc = parse_json_input(text, source);
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

World load_world(const std::string& written, const PoseOverrides& overrides) {
  const std::string path = util::resolve_input_path(written, "");  // "$data/worlds/x.json"
  const std::string ext = std::filesystem::path(path).extension().string();
  World w;
  if (ext == ".yaml" || ext == ".yml") {
    w = world_from_ros_map(load_ros_map(path), stem_of(path), overrides.start, overrides.charger);
  } else if (ext == ".map") {
    w = world_from_movingai(path,
                            overrides.movingai_scen.empty()
                                ? ""
                                : util::resolve_input_path(overrides.movingai_scen, ""),
                            overrides.movingai_query, overrides.start, overrides.charger);
  } else {
    w = parse_world_json(read_file(path), path);
    if (overrides.start) w.start = *overrides.start;
    if (overrides.charger) w.charger = *overrides.charger;
    if (overrides.start || overrides.charger) validate_world(w);
  }
  return w;
}

}  // namespace plantsim::worlds
