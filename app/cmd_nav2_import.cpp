// `plantsim nav2-import PARAMS.yaml [--out FILE]`: a Nav2 parameter file as a plantsim config;
// the account of every parameter goes to stderr (stdout holds the config when no --out is given).
#include <iostream>

#include "app/commands.h"
#include "app/nav2_import.h"
#include "app/output_kinds.h"
#include "util/atomic_file.h"
#include "util/unicode_text.h"

namespace plantsim::app {

std::function<int()> add_nav2_import_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "nav2-import",
      "Read a Nav2 parameter file (Regulated Pure Pursuit, opennav_docking, costmap footprint) "
      "into a plantsim config; lists every parameter mapped and not mapped (docs/nav2.md)");
  auto params = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  cmd->add_option("params", *params, "Nav2 parameter YAML (e.g. nav2_params.yaml)")->required();
  cmd->add_option("--out", *out, "Write the config here (default: stdout)");
  return [params, out]() {
    refuse_output_over_input(*out, *params);
    if (!out->empty())
      util::check_output_file(*out, "--out", config_file_kind());  // before any work: exit 2
    const Nav2Import im = import_nav2_params(*params);
    const std::string text = im.config.dump(2) + "\n";
    std::cerr << util::printable(nav2_report(im), true);  // names from the file, shown as text
    if (out->empty())
      std::cout << text;
    else
      util::write_file_atomically(*out, text);
    return kExitOk;
  };
}

}  // namespace plantsim::app
