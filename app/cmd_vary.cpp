// `plantsim vary`: a world file made to differ from its map, as a plant does: unmapped boxes
// across the optimal path and the charger off its mapped pose. The world's own JSON is kept
// and the two keys added, so that the variant reads like the original.
#include <cmath>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/commands.h"
#include "app/output_kinds.h"
#include "batch/plant_faults.h"
#include "planner/planner.h"
#include "planner/registry.h"
#include "util/atomic_file.h"
#include "util/data_dir.h"
#include "util/input_file.h"
#include "worlds/json_input.h"
#include "worlds/world_error.h"
#include "worlds/world_loader.h"

namespace plantsim::app {

std::function<int()> add_vary_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "vary", "Write a variant of a world whose plant differs from its map (JSON)");
  struct Options {
    std::string world, out, offset;
    int unmapped = 3;
    std::uint64_t seed = 1;
    std::string name;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("world", o->world, "World file (plantsim JSON)")->required();
  cmd->add_option("--unmapped", o->unmapped, "Boxes the map lacks, across the optimal path")
      ->transform(decimal_whole_number())
      ->check(CLI::Range(0, 50));
  cmd->add_option("--charger-offset", o->offset,
                  "The charger's mapped pose minus its real one: dx,dy,dyaw (m, m, rad)");
  add_seed_option(cmd, o->seed, "Random seed for the boxes' sizes and places");
  cmd->add_option("--name", o->name, "Name of the variant (default: <name>_mismatch)");
  cmd->add_option("--out", o->out, "Output file (default: stdout)");
  return [o]() {
    if (!o->out.empty())
      util::check_output_file(o->out, "--out", world_file_kind());  // before any work: exit 2
    refuse_output_over_input(o->out, util::resolve_input_path(o->world, ""));
    worlds::World w = worlds::load_world(o->world);
    const std::string world_path = util::resolve_input_path(o->world, "");
    nlohmann::ordered_json doc =
        worlds::parse_ordered_json_input(util::read_input_file(world_path), world_path);
    if (doc.contains("rects"))
      throw worlds::WorldError(o->world, "",
                               "vary takes plantsim worlds, not plain benchmark worlds");
    if (!o->offset.empty()) {
      double v[3];
      char tail = 0;
      if (std::sscanf(o->offset.c_str(), "%lf,%lf,%lf%c", &v[0], &v[1], &v[2], &tail) != 3)
        throw std::invalid_argument("--charger-offset: expected dx,dy,dyaw");
      w.charger_map_offset = {v[0], v[1], v[2]};
      doc["charger_map_offset"] = {v[0], v[1], v[2]};
    }
    const auto vg = planner::make_planner("vg", planner::planner_input(w, true));
    const planner::PlanResult optimal =
        vg->plan(w.start.position(), worlds::staging_pose(w).position());
    if (optimal.status != planner::PlanStatus::kOk)
      throw worlds::WorldError(o->world, "start",
                               "no path to the charger to place unmapped boxes across");
    w.unmapped = batch::unmapped_across_path(w, optimal.path, o->unmapped, o->seed);
    // Millimetres are enough for a file people read (shrunk inwards, so no box grows).
    for (auto& r : w.unmapped)
      r = {std::ceil(r.xmin * 1000) / 1000, std::ceil(r.ymin * 1000) / 1000,
           std::floor(r.xmax * 1000) / 1000, std::floor(r.ymax * 1000) / 1000};
    auto boxes = nlohmann::json::array();
    for (const auto& r : w.unmapped) boxes.push_back({r.xmin, r.ymin, r.xmax, r.ymax});
    doc["unmapped"] = boxes;
    doc["name"] = o->name.empty() ? w.name + "_mismatch" : o->name;
    worlds::validate_world(w);
    const std::string out = doc.dump(1) + "\n";
    if (o->out.empty())
      std::cout << out;
    else
      util::write_file_atomically(o->out, out);
    if (static_cast<int>(w.unmapped.size()) < o->unmapped)
      std::cerr << "vary: placed " << w.unmapped.size() << " of " << o->unmapped
                << " boxes (the others would have closed every way to the charger)\n";
    return kExitOk;
  };
}

}  // namespace plantsim::app
