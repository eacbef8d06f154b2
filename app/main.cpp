// plantsim command line: parses arguments with CLI11 and dispatches to a subcommand.
// Bad input of any kind ends with a one-line message on stderr and exit code 2.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "app/commands.h"
#include "util/build_stamp.h"
#include "util/c_number.h"
#include "util/data_dir.h"
#include "util/shell_word.h"
#include "util/unicode_text.h"
#include "worlds/world_error.h"

namespace plantsim::app {

using util::shell_word;

void add_world_options(CLI::App* cmd, std::string& world, std::string& scen, int& query) {
  cmd->add_option("world", world,
                  "World file: plantsim JSON, a plain world, a ROS map YAML or a MovingAI .map")
      ->required();
  cmd->add_option(
      "--scen", scen,
      "For a MovingAI .map: the .scen file whose query gives the start and the charger");
  cmd->add_option("--query", query, "That query's number, from 0")
      ->transform(decimal_whole_number())
      ->check(CLI::Range(0, 100000000));
}

const CLI::Validator& decimal_whole_number() {
  static const CLI::Validator whole_number(
      [](std::string& text) -> std::string {
        static const std::string kMax = "18446744073709551615";
        const std::size_t first = text.find_first_not_of('0');
        const std::string digits = first == std::string::npos ? "0" : text.substr(first);
        const bool plain =
            !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
        if (!plain || digits.size() > kMax.size() ||
            (digits.size() == kMax.size() && digits > kMax))
          return "expects a whole number from 0 to " + kMax + ", got '" + text + "'";
        text = digits;  // CLI11 would read a leading 0 as octal: "010" as 8
        return "";
      },
      "");
  return whole_number;
}

const CLI::Validator& finite_number() {
  static const CLI::Validator finite(
      [](std::string& text) -> std::string {
        char* end = nullptr;
        const double v = util::c_strtod(text.c_str(), &end);
        if (end != text.c_str() && !std::isfinite(v))
          return "expects a finite number, got '" + text + "'";
        return "";
      },
      "");
  return finite;
}

std::pair<int, int> parse_shard(const std::string& text) {
  int i = 0, n = 0;
  char slash = 0;
  std::istringstream in(text);
  if (!(in >> i >> slash >> n) || slash != '/' || !in.eof() || n < 1 || i < 0 || i >= n)
    throw std::invalid_argument("--shard expects i/n with 0 <= i < n, got '" + text + "'");
  return {i, n};
}

void refuse_output_over_input(const std::string& out, const std::string& input) {
  std::error_code ec;
  if (!out.empty() && std::filesystem::equivalent(out, input, ec))
    throw std::invalid_argument("--out: '" + out + "' is the input '" + input +
                                "' itself; write the output elsewhere");
}

void add_seed_option(CLI::App* cmd, std::uint64_t& seed, const std::string& description) {
  cmd->add_option("--seed", seed, description)->transform(decimal_whole_number());
}

std::string command_line(const CLI::App* sub) {
  // Re-runs exactly: each option once, flags without values, values quoted for the shell.
  std::string line = "plantsim";
  if (!util::chosen_data_dir().empty()) line += " --data " + shell_word(util::chosen_data_dir());
  line += " " + sub->get_name();
  for (const CLI::Option* o : sub->get_options()) {
    if (o->count() == 0 || o->get_name() == "--help") continue;
    const bool positional = o->get_lnames().empty();
    if (positional) {
      for (const std::string& v : o->results()) line += " " + shell_word(v);
    } else if (o->get_expected_max() == 0) {
      line += " --" + o->get_lnames().front();
    } else {
      for (const std::string& v : o->results())
        line += " --" + o->get_lnames().front() + " " + shell_word(v);
    }
  }
  return line;
}

}  // namespace plantsim::app

int main(int argc, char** argv) {
  CLI::App app{"plantsim: drive a wheeled robot through a plant to its charger, in Box2D"};
  app.require_subcommand(1);
  app.fallthrough();  // --data may follow the subcommand
  app.set_version_flag("--version", plantsim::util::build_stamp().text());
  std::string data_dir;
  app.add_option("--data", data_dir,
                 "Folder of the shared data (default: $PLANTSIM_DATA, else ../shared/data beside "
                 "the checkout)");
  std::vector<std::pair<CLI::App*, std::function<int()>>> commands;
  auto remember = [&](std::function<int()> action) {
    commands.emplace_back(app.get_subcommands({}).back(), std::move(action));
  };
  remember(plantsim::app::add_plan_command(app));
  remember(plantsim::app::add_run_command(app));
  remember(plantsim::app::add_summarize_command(app));
  remember(plantsim::app::add_bench_command(app));
  remember(plantsim::app::add_config_command(app));
  remember(plantsim::app::add_compare_command(app));
  remember(plantsim::app::add_planners_command(app));
  remember(plantsim::app::add_batch_command(app));
  remember(plantsim::app::add_merge_command(app));
  remember(plantsim::app::add_generate_command(app));
  remember(plantsim::app::add_vary_command(app));
  remember(plantsim::app::add_nav2_import_command(app));
  remember(plantsim::app::add_tune_command(app));
  remember(plantsim::app::add_diff_command(app));
  remember(plantsim::app::add_info_command(app));
  remember(plantsim::app::add_coverage_command(app));
  remember(plantsim::app::add_coverage_study_command(app));
  for (CLI::App* sub : app.get_subcommands({}))
    for (CLI::Option* o : sub->get_options())
      if (o->get_type_name().rfind("FLOAT", 0) == 0) o->check(plantsim::app::finite_number());
  // An unknown command is named, with the known ones (CLI11 would say "A subcommand is required").
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (word == "--data") {
      ++i;
      continue;
    }
    if (word.rfind("--data=", 0) == 0 || word.rfind("-", 0) == 0) continue;
    std::string known;
    bool found = false;
    for (const CLI::App* sub : app.get_subcommands({})) {
      known += (known.empty() ? "" : ", ") + sub->get_name();
      found |= sub->get_name() == word;
    }
    if (!found) {
      std::cerr << "plantsim: unknown command '" << word << "' (commands: " << known
                << "; plantsim --help)\n";
      return plantsim::app::kExitBadInput;
    }
    break;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return plantsim::app::kExitBadInput;
  }
  try {
    if (!data_dir.empty()) plantsim::util::set_data_dir(data_dir);
    for (auto& [sub, action] : commands)
      if (sub->parsed()) return action();
  } catch (const plantsim::worlds::WorldError& e) {
    // Messages quote names and paths from the user's files: escape sequences in them are shown,
    // never acted on by the terminal.
    std::cerr << "plantsim: " << plantsim::util::printable(e.what(), true) << "\n";
    return plantsim::app::kExitBadInput;
  } catch (const std::invalid_argument& e) {
    std::cerr << "plantsim: " << plantsim::util::printable(e.what(), true) << "\n";
    return plantsim::app::kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "plantsim: error: " << plantsim::util::printable(e.what(), true) << "\n";
    return plantsim::app::kExitFailed;
  }
  return plantsim::app::kExitBadInput;
}
