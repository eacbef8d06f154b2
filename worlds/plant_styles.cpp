// The style generators: each lays out rectangles its own way, then random_plant's placement of
// the start and the charger.
#include "worlds/plant_styles.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <random>
#include <stdexcept>

#include "worlds/random_plant.h"

namespace plantsim::worlds {
namespace {

using Rng = std::mt19937_64;

double uniform(Rng& rng, double a, double b) {
  return std::uniform_real_distribution<double>(a, b)(rng);
}
int uniform_int(Rng& rng, int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng); }

bool clear_of(const Rect& r, const std::vector<Rect>& placed, double gap) {
  for (const Rect& q : placed)
    if (!(r.xmin >= q.xmax + gap || q.xmin >= r.xmax + gap || r.ymin >= q.ymax + gap ||
          q.ymin >= r.ymax + gap))
      return false;
  return true;
}

/// Up to `count` boxes with sides in [lo, hi], at least `gap` from each other, the walls and
/// what is already placed; gives up on a box after many tries (dense floors fill up).
void scatter(Rng& rng, World& w, int count, double lo, double hi, double gap) {
  const double width = w.floor.xmax, height = w.floor.ymax;
  for (int placed = 0, tries = 0; placed < count && tries < 400 * count; ++tries) {
    const double rw = uniform(rng, lo, hi), rh = uniform(rng, lo, hi);
    if (rw > width - 2 * gap - 1 || rh > height - 2 * gap - 1) continue;
    const double x0 = uniform(rng, gap, width - gap - rw),
                 y0 = uniform(rng, gap, height - gap - rh);
    const Rect r{x0, y0, x0 + rw, y0 + rh};
    if (!clear_of(r, w.obstacles, gap)) continue;
    w.obstacles.push_back(r);
    ++placed;
  }
}

void sparse(Rng& rng, World& w) { scatter(rng, w, uniform_int(rng, 5, 20), 1.0, 6.0, 2.0); }

void dense(Rng& rng, World& w) {
  // About a quarter of the floor under boxes of 1 to 4 m, passages from 0.9 m.
  const double area = w.floor.xmax * w.floor.ymax;
  scatter(rng, w, static_cast<int>(0.25 * area / 6.25), 1.0, 4.0, 0.9);
}

void racks(Rng& rng, World& w) {
  // Rows of shelving along x, 1 to 1.5 m deep, aisles 2 to 3.5 m, broken by cross-aisles.
  const double width = w.floor.xmax, height = w.floor.ymax;
  const double end_aisle = uniform(rng, 5.0, 8.0);  // free space for the start and the charger
  double y = uniform(rng, 2.0, 4.0);
  while (true) {
    const double depth = uniform(rng, 1.0, 1.5);
    if (y + depth > height - 2.0) break;
    double x = end_aisle;
    while (x < width - end_aisle - 3.0) {
      const double run = std::min(uniform(rng, 10.0, 25.0), width - end_aisle - x);
      w.obstacles.push_back({x, y, x + run, y + depth});
      x += run + uniform(rng, 2.0, 3.0);  // a cross-aisle
    }
    y += depth + uniform(rng, 2.0, 3.5);
  }
}

void corridors(Rng& rng, World& w) {
  // Solid blocks on a grid of corridors 1.2 to 2 m wide (cable tunnels, mine roadways); the
  // two ends are left open for the start and the charger.
  const double width = w.floor.xmax, height = w.floor.ymax;
  const double margin = 6.0;
  std::vector<std::pair<double, double>> columns, rows;  // [begin, end) of each block band
  for (double x = margin; x < width - margin - 3.0;) {
    const double span = std::min(uniform(rng, 4.0, 14.0), width - margin - x);
    columns.push_back({x, x + span});
    x += span + uniform(rng, 1.2, 2.0);
  }
  for (double y = uniform(rng, 1.2, 2.0); y < height - 3.0;) {
    const double span = std::min(uniform(rng, 3.0, 10.0), height - 1.2 - y);
    rows.push_back({y, y + span});
    y += span + uniform(rng, 1.2, 2.0);
  }
  for (const auto& [x0, x1] : columns)
    for (const auto& [y0, y1] : rows)
      if (x1 - x0 > 0.5 && y1 - y0 > 0.5) w.obstacles.push_back({x0, y0, x1, y1});
}

void yard(Rng& rng, World& w) {
  // Open ground crossed by a few long walls (fences, building sides), each with room to pass.
  const double width = w.floor.xmax, height = w.floor.ymax;
  const int walls = uniform_int(rng, 2, 5);
  for (int i = 0, tries = 0; i < walls && tries < 200; ++tries) {
    const bool vertical = uniform(rng, 0, 1) < 0.5;
    const double thickness = uniform(rng, 0.3, 1.0);
    const double span = vertical ? height : width - 16.0;
    const double length = uniform(rng, 0.3, 0.7) * span;
    Rect r;
    if (vertical) {
      const double x = uniform(rng, 10.0, width - 10.0 - thickness);
      const double y =
          uniform(rng, 0, 1) < 0.5 ? 0.0 : height - length;  // from a wall, a gap at the other end
      r = {x, y, x + thickness, y + length};
    } else {
      const double x = uniform(rng, 8.0, width - 8.0 - length),
                   y = uniform(rng, 3.0, height - 3.0 - thickness);
      r = {x, y, x + length, y + thickness};
    }
    if (!clear_of(r, w.obstacles, 3.0)) continue;
    w.obstacles.push_back(r);
    ++i;
  }
}

void mixed(Rng& rng, World& w) {
  // A few buildings, some machines, much small clutter.
  scatter(rng, w, uniform_int(rng, 2, 4), 8.0, 18.0, 3.0);
  scatter(rng, w, uniform_int(rng, 10, 25), 2.0, 5.0, 1.5);
  scatter(rng, w, uniform_int(rng, 30, 60), 0.3, 1.2, 1.0);
}

const std::map<std::string, std::function<void(Rng&, World&)>>& generators() {
  static const std::map<std::string, std::function<void(Rng&, World&)>> table = {
      {"sparse", sparse},       {"dense", dense}, {"racks", racks},
      {"corridors", corridors}, {"yard", yard},   {"mixed", mixed}};
  return table;
}

}  // namespace

const std::vector<std::string>& plant_style_names() {
  static const std::vector<std::string> names = {"sparse",    "dense", "racks",
                                                 "corridors", "yard",  "mixed"};
  return names;
}

World styled_plant(const std::string& style, std::uint64_t seed, double width_m, double height_m) {
  const auto it = generators().find(style);
  if (it == generators().end()) {
    std::string known;
    for (const std::string& n : plant_style_names()) known += (known.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown plant style '" + style + "' (known: " + known + ")");
  }
  if (!(width_m >= 40.0 && height_m >= 20.0))
    throw std::invalid_argument("styled plants need a floor of at least 40 x 20 m");
  // The style in the seed, so that two styles of one seed differ in every draw.
  const auto& names = plant_style_names();
  const auto index =
      static_cast<std::uint64_t>(std::find(names.begin(), names.end(), style) - names.begin());
  Rng rng(seed ^ ((index + 1) * 0x9E3779B97F4A7C15ULL));
  World w;
  w.name = style + "_s" + std::to_string(seed);
  w.source = w.name;
  w.floor = {0, 0, width_m, height_m};
  w.inflation_margin_m = kBenchmarkInflation_m - w.robot.radius_m;
  it->second(rng, w);
  place_start_and_charger(w, rng);
  return w;
}

}  // namespace plantsim::worlds
