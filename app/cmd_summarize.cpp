// `plantsim summarize DIR...`: gathers the summary.json of several runs into one Markdown
// table, for a reader who wants every result on one page.
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "app/commands.h"
#include "util/input_file.h"
#include "render/report.h"
#include "util/atomic_file.h"

namespace plantsim::app {

std::function<int()> add_summarize_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("summarize", "Gather run folders' summary.json into a Markdown table");
  struct Options {
    std::vector<std::string> dirs;
    std::string out;
    std::string html;
    std::vector<std::string> links;
  };
  auto opt = std::make_shared<Options>();
  cmd->add_option("dirs", opt->dirs, "Run output folders")->required()->check(CLI::ExistingDirectory);
  cmd->add_option("--out", opt->out, "Write here instead of stdout");
  cmd->add_option("--html", opt->html, "Also write an HTML index with the metrics and every run's figure");
  cmd->add_option("--link", opt->links, "Further reports to link from the index");
  return [opt]() {
    std::string md =
        "# plantsim results\n\n| world | planner | travel | status | position error (cm) | heading error (deg) | "
        "collisions | retries | time (s) | planned (m) | driven (m) | figure |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    bool all_docked = true;
    render::Report index;
    index.title = "plantsim results";
    index.headers = {"world", "planner", "travel", "status", "position error (cm)", "heading error (deg)", "collisions",
                     "retries", "time (s)", "planned (m)", "driven (m)"};
    const std::string html_base = opt->html.empty() ? "." : std::filesystem::path(opt->html).parent_path().string();
    for (const auto& d : opt->dirs) {
      nlohmann::json j;
      try {
        j = nlohmann::json::parse(util::read_input_file(d + "/summary.json", 64u << 20));
      } catch (const util::InputFileError& e) {
        throw std::invalid_argument(d + "/summary.json: " + e.what());
      } catch (const nlohmann::json::exception& e) {
        throw std::invalid_argument(d + "/summary.json: malformed JSON: " + e.what());
      }
      // Links relative to where the table is written, so they work when it is opened.
      const std::string base = opt->out.empty() ? "." : std::filesystem::path(opt->out).parent_path().string();
      const std::string link = std::filesystem::relative(d, base.empty() ? "." : base).string();
      char row[512];
      std::snprintf(row, sizeof row, "| %s | %s | %s | %s | %.2f | %.2f | %d | %d | %.1f | %.2f | %.2f | [run.png](%s/run.png) |\n",
                    j.value("world", "?").c_str(), j.value("planner", "?").c_str(), j.value("travel", "path").c_str(),
                    j.value("status", "?").c_str(), 100.0 * j.value("position_error_m", 0.0),
                    j.value("heading_error_deg", 0.0), j.value("collisions", 0), j.value("retries", 0),
                    j.value("time_s", 0.0), j.value("path_length_m", 0.0), j.value("driven_length_m", 0.0),
                    link.c_str());
      md += row;
      auto fmt = [](double v, int d) {
        char b[64];
        std::snprintf(b, sizeof b, "%.*f", d, v);
        return std::string(b);
      };
      index.rows.push_back({j.value("world", "?"), j.value("planner", "?"), j.value("travel", "path"), j.value("status", "?"),
                            fmt(100.0 * j.value("position_error_m", 0.0), 2), fmt(j.value("heading_error_deg", 0.0), 2),
                            std::to_string(j.value("collisions", 0)), std::to_string(j.value("retries", 0)),
                            fmt(j.value("time_s", 0.0), 1), fmt(j.value("path_length_m", 0.0), 2),
                            fmt(j.value("driven_length_m", 0.0), 2)});
      const std::string rel = std::filesystem::relative(d, html_base.empty() ? "." : html_base).string();
      index.figures.push_back({rel + "/run.png", j.value("world", "?") + ": " + j.value("status", "?")});
      index.files.push_back(rel + "/report.html");
      all_docked = all_docked && (j.value("docked", false) || j.value("caught", false));
    }
    if (!opt->html.empty()) {
      for (const auto& l : opt->links)
        index.files.push_back(std::filesystem::relative(l, html_base.empty() ? "." : html_base).string());
      render::write_report(index, opt->html);
    }
    if (opt->out.empty()) {
      std::cout << md;
    } else {
      util::write_file_atomically(opt->out, md);
    }
    return all_docked ? kExitOk : kExitFailed;
  };
}

}  // namespace plantsim::app

