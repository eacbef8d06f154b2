// `plantsim generate`: a random plant world (size, count, density, seed) as world JSON.
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "app/output_kinds.h"
#include "util/atomic_file.h"
#include "worlds/plant_styles.h"
#include "worlds/random_plant.h"

namespace plantsim::app {

std::function<int()> add_generate_command(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("generate", "Write a random plant world (JSON) to stdout or --out");
  auto opt = std::make_shared<worlds::RandomPlantOptions>();
  auto out = std::make_shared<std::string>();
  auto style = std::make_shared<std::string>();
  std::string styles;
  for (const std::string& n : worlds::plant_style_names())
    styles += (styles.empty() ? "" : ", ") + n;
  cmd->add_option("--style", *style,
                  "A plant of a named style (" + styles +
                      "; docs/world_format.md#generated-plants) on --width x --height, "
                      "from --seed; --count, --density, --min-gap and --overlap do not apply")
      ->check(CLI::IsMember(worlds::plant_style_names()));
  cmd->add_option("--count", opt->rect_count, "Number of rectangles")
      ->transform(decimal_whole_number())
      ->check(CLI::Range(0, 200000));
  add_seed_option(cmd, opt->seed, "Random seed");
  cmd->add_option("--width", opt->width_m, "Floor width (m)")->check(CLI::Range(5.0, 10000.0));
  cmd->add_option("--height", opt->height_m, "Floor height (m)")->check(CLI::Range(5.0, 10000.0));
  cmd->add_option("--density", opt->coverage, "Fraction of the floor covered (0 to 0.6)")
      ->check(CLI::Range(0.001, 0.599));
  cmd->add_option("--min-gap", opt->min_gap_m, "Gap between rectangles (m)")
      ->check(CLI::Range(0.0, 100.0));
  cmd->add_flag("--overlap", opt->allow_overlap, "Let rectangles overlap and touch");
  cmd->add_option("--out", *out, "Output file (default: stdout)");
  return [opt, out, style]() {
    if (!out->empty())
      util::check_output_file(*out, "--out", world_file_kind());  // before any work: exit 2
    const worlds::World w =
        style->empty() ? worlds::random_plant(*opt)
                       : worlds::styled_plant(*style, opt->seed, opt->width_m, opt->height_m);
    nlohmann::ordered_json j;
    j["name"] = w.name;
    j["floor"] = {{"xmin", w.floor.xmin},
                  {"ymin", w.floor.ymin},
                  {"xmax", w.floor.xmax},
                  {"ymax", w.floor.ymax}};
    auto rects = nlohmann::json::array();
    for (const auto& r : w.obstacles) rects.push_back({r.xmin, r.ymin, r.xmax, r.ymax});
    j["obstacles"] = rects;
    j["robot"] = {{"radius_m", w.robot.radius_m},
                  {"wheel_base_m", w.robot.wheel_base_m},
                  {"wheel_radius_m", w.robot.wheel_radius_m},
                  {"max_speed_mps", w.robot.max_speed_mps},
                  {"max_accel_mps2", w.robot.max_accel_mps2},
                  {"mass_kg", w.robot.mass_kg}};
    j["start"] = {{"x", w.start.x}, {"y", w.start.y}, {"yaw", w.start.yaw}};
    j["charger"] = {{"x", w.charger.x}, {"y", w.charger.y}, {"yaw", w.charger.yaw}};
    j["inflation_margin_m"] = w.inflation_margin_m;
    const std::string text = j.dump(1) + "\n";
    if (out->empty())
      std::cout << text;
    else
      util::write_file_atomically(*out, text);
    return kExitOk;
  };
}

}  // namespace plantsim::app
