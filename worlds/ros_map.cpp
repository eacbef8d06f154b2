// PGM (P5 binary, P2 text) and map_server YAML reading; charger placement.
#include "worlds/ros_map.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "geometry/predicates.h"
#include "worlds/charger_placement.h"
#include "worlds/decimal_number.h"
#include "worlds/map_image.h"
#include "worlds/world_error.h"
#include "worlds/world_limits.h"
#include "worlds/world_loader.h"
#include "worlds/yaml_input.h"

namespace plantsim::worlds {
namespace {

YAML::Node required(const YAML::Node& node, const std::string& key, const std::string& path) {
  if (!node) throw WorldError(path, key, "missing");
  return node;
}

// Numbers by plantsim's one rule for YAML (worlds/decimal_number.h): `010` is 10.
double number(const YAML::Node& doc, const std::string& key, const std::string& path) {
  const auto v = decimal_number(required(doc[key], key, path));
  if (!v) throw WorldError(path, key, "expected a decimal number");
  return *v;
}

std::string text(const YAML::Node& doc, const std::string& key, const std::string& path) {
  if (!required(doc[key], key, path).IsScalar())
    throw WorldError(path, key, "expected a single value");
  return doc[key].Scalar();
}

std::vector<double> numbers(const YAML::Node& doc, const std::string& key,
                            const std::string& path) {
  const YAML::Node n = required(doc[key], key, path);
  if (!n.IsSequence()) throw WorldError(path, key, "expected a list of decimal numbers");
  std::vector<double> out;
  for (const YAML::Node& item : n) {
    const auto v = decimal_number(item);
    if (!v) throw WorldError(path, key, "expected a list of decimal numbers");
    out.push_back(*v);
  }
  return out;
}

// map_server's reading of one pixel (Nav2's map_io): its shade from 0 (black) to 1 (white),
// with alpha averaged in as a fourth channel beside red, green and blue in trinary mode; in
// scale and raw modes a pixel not fully opaque is unknown (Nav2 does so in scale mode; in raw
// mode it ignores alpha, and plantsim keeps the unknown: a raw value is an occupancy, and a
// transparent pixel gives none).
struct PixelClass {
  bool occupied = false, free = false;
};

PixelClass classify(const MapImage& img, std::size_t i, const std::string& mode, bool negate,
                    double occupied_thresh, double free_thresh) {
  double shade = img.shade(i);
  if (!img.alpha.empty()) {
    if (mode != "trinary" && img.alpha[i] != img.max_value) return {};
    if (mode == "trinary") shade = (3 * shade + img.opacity(i)) / 4;
  }
  PixelClass c;
  if (mode == "raw") {
    const double v = std::round(shade * 255);  // the value an 8-bit image would hold
    c.occupied = v >= 100.0 * occupied_thresh && v <= 100;
    c.free = v <= 100.0 * free_thresh;
  } else {
    const double p = negate ? shade : 1 - shade;
    c.occupied = p > occupied_thresh;
    c.free = p < free_thresh;
  }
  return c;
}

}  // namespace

RosMap load_ros_map(const std::string& yaml_path) {
  const YAML::Node doc = load_yaml_input(yaml_path);
  if (!doc.IsMap()) throw WorldError(yaml_path, "", "expected a map_server YAML mapping");
  RosMap m;
  const std::string image = text(doc, "image", yaml_path);
  m.resolution_m = number(doc, "resolution", yaml_path);
  const auto origin = numbers(doc, "origin", yaml_path);
  std::optional<std::uint64_t> negate = 0;
  if (doc["negate"]) negate = decimal_whole_number(doc["negate"]);
  const double occupied_thresh = number(doc, "occupied_thresh", yaml_path);
  const double free_thresh = number(doc, "free_thresh", yaml_path);
  const std::string mode = doc["mode"] ? text(doc, "mode", yaml_path) : "trinary";
  // A pixel from a millimetre to 10 m: finer or coarser is a unit mistake, and would make the
  // inflation span thousands of pixels or the floor thousands of kilometres.
  if (!(m.resolution_m >= kMinResolution_m && m.resolution_m <= kMaxResolution_m))
    throw WorldError(yaml_path, "resolution", "must be from 0.001 to 10 m per pixel");
  if (origin.size() != 3 || !std::all_of(origin.begin(), origin.end(), [](double v) {
        return std::isfinite(v) && std::fabs(v) <= kMaxCoordinate_m;
      }))
    throw WorldError(yaml_path, "origin", "expected [x, y, yaw], finite, within +-1e7 m");
  if (origin[2] != 0.0)
    throw WorldError(yaml_path, "origin", "a rotated map (yaw != 0) is not supported");
  if (negate != 0u && negate != 1u) throw WorldError(yaml_path, "negate", "must be 0 or 1");
  if (!(free_thresh >= 0 && free_thresh <= occupied_thresh && occupied_thresh <= 1))
    throw WorldError(yaml_path, "free_thresh", "needs 0 <= free_thresh <= occupied_thresh <= 1");
  if (mode != "trinary" && mode != "scale" && mode != "raw")
    throw WorldError(yaml_path, "mode", "must be trinary, scale or raw");
  m.origin = {origin[0], origin[1]};

  const std::filesystem::path image_path =
      std::filesystem::path(image).is_absolute()
          ? std::filesystem::path(image)
          : std::filesystem::path(yaml_path).parent_path() / image;
  const MapImage pgm = read_map_image(image_path.string());
  if (pgm.width * m.resolution_m > kMaxFloorSide_m || pgm.height * m.resolution_m > kMaxFloorSide_m)
    throw WorldError(yaml_path, "resolution",
                     "makes the map larger than " +
                         std::to_string(static_cast<int>(kMaxFloorSide_m)) +
                         " m on a side (huge world)");
  m.grid.source = yaml_path;
  m.grid.width = pgm.width;
  m.grid.height = pgm.height;
  m.grid.cells.resize(pgm.values.size());
  for (std::size_t i = 0; i < pgm.values.size(); ++i) {
    const PixelClass c = classify(pgm, i, mode, negate == 1u, occupied_thresh, free_thresh);
    m.occupied += c.occupied;
    m.free += c.free;
    m.unknown += !c.occupied && !c.free;
    m.grid.cells[i] = c.free ? '.' : '@';
  }
  return m;
}

std::optional<Pose2> place_charger_against_wall(const World& world,
                                                const std::function<bool(Vec2)>& staging_ok) {
  // Candidates: positions a gap away from an obstacle's face or the floor's wall, facing it,
  // spaced along each face; the valid one with the most room behind its staging pose wins.
  const double gap = world.robot.front_extent_m() + world.charger_spec.depth_m + 0.02;
  std::vector<Rect> faces = world.obstacles;
  const Rect& f = world.floor;
  for (const Rect& wall : geom::surrounding_walls(f, 1.0)) faces.push_back(wall);
  std::optional<Pose2> best;
  double best_room = -1;
  World trial = world;
  auto consider = [&](Vec2 p, double yaw) {
    trial.charger = {p.x, p.y, yaw};
    if (!docking_area_clear(trial)) return;
    if (staging_ok && !staging_ok(staging_pose(trial).position())) return;
    try {
      check_pose_free(trial, trial.charger, "charger");
    } catch (const WorldError&) {
      return;
    }
    // Room: distance from the staging pose to the nearest obstacle, a proxy for easy access.
    const Vec2 s = staging_pose(trial).position();
    double room = std::min({s.x - f.xmin, f.xmax - s.x, s.y - f.ymin, f.ymax - s.y});
    for (const Rect& o : world.obstacles) {
      const double dx = std::max({o.xmin - s.x, 0.0, s.x - o.xmax}),
                   dy = std::max({o.ymin - s.y, 0.0, s.y - o.ymax});
      room = std::min(room, std::hypot(dx, dy));
    }
    if (room > best_room + 1e-9) {
      best_room = room;
      best = trial.charger;
    }
  };
  // Along each face every 0.1 m, keeping clear of its ends by half the charger's width.
  // Counted steps, not `x += spacing`: far from the origin that sum stops advancing. On a
  // huge map the spacing widens so that at most ~100,000 places are tried.
  double perimeter = 0;
  for (const Rect& r : faces) perimeter += 2 * (r.width() + r.height());
  const double spacing = std::max(0.1, perimeter / 100000.0),
               inset = 0.5 * world.charger_spec.width_m;
  auto steps = [&](double lo, double hi) {
    return hi < lo ? 0L : static_cast<long>(std::min(std::floor((hi - lo) / spacing), 1e7)) + 1;
  };
  for (const Rect& r : faces) {
    for (long k = 0, n = steps(r.xmin + inset, r.xmax - inset); k < n; ++k) {
      const double x = r.xmin + inset + k * spacing;
      consider({x, r.ymin - gap}, M_PI / 2);   // below the face, facing up
      consider({x, r.ymax + gap}, -M_PI / 2);  // above, facing down
    }
    for (long k = 0, n = steps(r.ymin + inset, r.ymax - inset); k < n; ++k) {
      const double y = r.ymin + inset + k * spacing;
      consider({r.xmin - gap, y}, 0.0);   // left of it, facing right
      consider({r.xmax + gap, y}, M_PI);  // right of it, facing left
    }
  }
  return best;
}

namespace {

// Free pixels once blocked ones are grown by the planning inflation, labelled by connected
// region (4-neighbours): the planner finds paths exactly within one region.
struct Regions {
  std::vector<int> label;  // -1 blocked
  int largest = -1;
};

Regions free_regions(const RosMap& map, double inflation_m) {
  const GridMap& g = map.grid;
  // A square neighbourhood, as the planner's square-cornered inflation of each pixel reaches;
  // grown one axis at a time with running counts, so the cost does not depend on its size.
  const int grow = static_cast<int>(std::min(std::ceil(inflation_m / map.resolution_m), 1e6)) + 1;
  Regions r;
  r.label.assign(g.cells.size(), 0);
  const auto w = static_cast<std::size_t>(g.width);
  std::vector<char> across(g.cells.size(), 0);  // blocked within `grow` along the row
  for (int y = 0; y < g.height; ++y) {
    int blocked_in_window = 0;
    const std::size_t row = static_cast<std::size_t>(y) * w;
    for (int x = 0; x < g.width + grow; ++x) {
      if (x < g.width) blocked_in_window += g.at(x, y) != '.';
      if (x - 2 * grow - 1 >= 0) blocked_in_window -= g.at(x - 2 * grow - 1, y) != '.';
      const int centre = x - grow;
      if (centre >= 0 && centre < g.width) across[row + centre] = blocked_in_window > 0;
    }
  }
  for (int x = 0; x < g.width; ++x) {
    int blocked_in_window = 0;
    for (int y = 0; y < g.height + grow; ++y) {
      if (y < g.height) blocked_in_window += across[static_cast<std::size_t>(y) * w + x];
      if (y - 2 * grow - 1 >= 0)
        blocked_in_window -= across[static_cast<std::size_t>(y - 2 * grow - 1) * w + x];
      const int centre = y - grow;
      if (centre >= 0 && centre < g.height && blocked_in_window > 0)
        r.label[static_cast<std::size_t>(centre) * w + x] = -1;
    }
  }
  int next = 1;
  std::size_t largest_size = 0;
  std::vector<std::size_t> queue;
  for (std::size_t start = 0; start < r.label.size(); ++start) {
    if (r.label[start] != 0) continue;
    queue.assign(1, start);
    r.label[start] = next;
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const int x = static_cast<int>(queue[head] % g.width),
                y = static_cast<int>(queue[head] / g.width);
      for (const auto& [dx, dy] :
           {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
        if (!g.inside(x + dx, y + dy)) continue;
        const std::size_t k = static_cast<std::size_t>(y + dy) * g.width + x + dx;
        if (r.label[k] != 0) continue;
        r.label[k] = next;
        queue.push_back(k);
      }
    }
    if (queue.size() > largest_size) {
      largest_size = queue.size();
      r.largest = next;
    }
    ++next;
  }
  return r;
}

int label_at(const RosMap& map, const Regions& r, Vec2 p) {
  const double column = std::floor((p.x - map.origin.x) / map.resolution_m);
  const double row_up = std::floor((p.y - map.origin.y) / map.resolution_m);
  // Compared as doubles first: a point far off the map must not overflow an int.
  if (!(column >= 0 && column < map.grid.width && row_up >= 0 && row_up < map.grid.height))
    return -1;
  const int x = static_cast<int>(column), y = map.grid.height - 1 - static_cast<int>(row_up);
  return r.label[static_cast<std::size_t>(y) * map.grid.width + x];
}

// The free pixel farthest from the charger in the region of its staging pose.
Pose2 farthest_start(const RosMap& map, const Regions& r, const World& w) {
  const int region = label_at(map, r, staging_pose(w).position());
  if (region <= 0)
    throw WorldError(map.grid.source, "start",
                     "the charger's staging pose is not in free space; give --start");
  const GridMap& g = map.grid;
  const Rect inner = w.floor.inflated(-w.planning_inflation_m());
  Vec2 best;
  double best_d = -1;
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x) {
      if (r.label[static_cast<std::size_t>(y) * g.width + x] != region) continue;
      const Vec2 c{map.origin.x + map.resolution_m * (x + 0.5),
                   map.origin.y + map.resolution_m * (g.height - y - 0.5)};
      // The floor's edge is a wall too: a map drawn without border walls has free pixels there.
      if (!geom::in_closed_rect(inner, c)) continue;
      const double d = geom::distance(c, w.charger.position());
      if (d > best_d) best_d = d, best = c;
    }
  if (best_d < 0)
    throw WorldError(map.grid.source, "start",
                     "no start was given and no free pixel of the charger's region keeps the robot "
                     "off the map's edge; give --start");
  const Vec2 to_charger = w.charger.position() - best;
  return {best.x, best.y, std::atan2(to_charger.y, to_charger.x)};
}

// Without a wall to dock against (round or diagonal walls give none), the charger stands
// free where the largest region is most open, facing whichever way leaves room to dock.
std::optional<Pose2> place_charger_in_the_open(const RosMap& map, const Regions& r,
                                               const World& w) {
  const GridMap& g = map.grid;
  // Multi-source breadth-first distance (in pixels) from everything outside the region.
  std::vector<int> dist(g.cells.size(), -1);
  std::vector<std::size_t> queue;
  for (std::size_t k = 0; k < dist.size(); ++k)
    if (r.label[k] != r.largest) dist[k] = 0, queue.push_back(k);
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const int x = static_cast<int>(queue[head] % g.width),
              y = static_cast<int>(queue[head] / g.width);
    for (const auto& [dx, dy] :
         {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
      if (!g.inside(x + dx, y + dy)) continue;
      const std::size_t k = static_cast<std::size_t>(y + dy) * g.width + x + dx;
      if (dist[k] >= 0) continue;
      dist[k] = dist[queue[head]] + 1;
      queue.push_back(k);
    }
  }
  // The most open pixels first (the queue ends with them).
  for (std::size_t i = queue.size(); i-- > 0 && i + 50 > queue.size();) {
    const int x = static_cast<int>(queue[i] % g.width), y = static_cast<int>(queue[i] / g.width);
    const Vec2 c{map.origin.x + map.resolution_m * (x + 0.5),
                 map.origin.y + map.resolution_m * (g.height - y - 0.5)};
    World trial = w;
    for (int k = 0; k < 8; ++k) {
      trial.charger = {c.x, c.y, geom::wrap_angle(k * M_PI / 4)};
      if (docking_area_clear(trial) &&
          label_at(map, r, staging_pose(trial).position()) == r.largest)
        return trial.charger;
    }
  }
  return std::nullopt;
}

}  // namespace

World world_from_ros_map(const RosMap& map, const std::string& name, std::optional<Pose2> start,
                         std::optional<Pose2> charger) {
  World w;
  w.name = name;
  w.source = map.grid.source;
  // A scanned map is uncertain by a pixel (5 cm) or so, and a localiser by a few cm: keep more
  // clearance than for drawn plans (0.12 m still let 1 noisy episode in 504 touch a wall).
  w.inflation_margin_m = 0.13;
  const double res = map.resolution_m;
  w.floor = {map.origin.x, map.origin.y, map.origin.x + res * map.grid.width,
             map.origin.y + res * map.grid.height};
  for (const Rect& r : merge_blocked_cells(map.grid, [](char c) { return c == '@'; }))
    w.obstacles.push_back({map.origin.x + res * r.xmin, map.origin.y + res * r.ymin,
                           map.origin.x + res * r.xmax, map.origin.y + res * r.ymax});
  const Regions regions = free_regions(map, w.planning_inflation_m());
  if (charger) {
    w.charger = *charger;
  } else {
    // In the largest free region, so that most of the map can reach it.
    auto placed = place_charger_against_wall(
        w, [&](Vec2 s) { return label_at(map, regions, s) == regions.largest; });
    if (!placed) placed = place_charger_in_the_open(map, regions, w);
    if (!placed)
      throw WorldError(map.grid.source, "charger", "no place leaves room to dock; give --charger");
    w.charger = *placed;
  }
  if (start) {
    w.start = *start;
  } else {
    w.start = farthest_start(map, regions, w);
  }
  validate_world(w);
  return w;
}

}  // namespace plantsim::worlds
