// `plantsim diff BASELINE CANDIDATE [--out DIR] [--level L] [--junit FILE]`: two batch folders
// compared episode by episode (batch/batch_diff.h); diff.json, diff.md, diff.html in DIR and a
// JUnit report; exit 1 when the candidate is worse, 2 on bad input with nothing written.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>

#include "app/commands.h"
#include "app/output_kinds.h"
#include "batch/batch_diff.h"
#include "batch/diff_outputs.h"
#include "util/atomic_file.h"
#include "util/made_by.h"
#include "worlds/known_keys.h"

namespace plantsim::app {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kDiffFiles = {"diff.json", "diff.md", "diff.html"};

std::string folder_name(const std::string& dir) {
  fs::path p = fs::path(dir).lexically_normal();
  if (p.filename().empty()) p = p.parent_path();
  const std::string name = p.filename().string();
  return worlds::file_name_component(name.empty() || name == "." || name == ".." ? "batch" : name);
}

/// True when `file` would stand directly in `dir`.
bool inside(const std::string& file, const std::string& dir) {
  std::error_code ec;
  const fs::path parent = fs::absolute(fs::path(file), ec).lexically_normal().parent_path();
  return parent == fs::absolute(fs::path(dir), ec).lexically_normal();
}

/// True when `path` is `folder` or lies under it.
bool within(const std::string& path, const std::string& folder) {
  std::error_code ec;
  const fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
  const fs::path f = fs::weakly_canonical(fs::absolute(folder, ec), ec);
  return std::mismatch(f.begin(), f.end(), p.begin(), p.end()).first == f.end();
}

/// Checks, before anything is written, that the outputs may be written: `out` not in a batch
/// folder, a --junit file missing or a JUnit report. Returns the names `out` may hold (an earlier
/// diff's files, a JUnit report in it).
std::vector<std::string> check_outputs(const std::string& out, const std::string& junit,
                                       bool junit_inside, const std::vector<std::string>& inputs) {
  std::vector<std::string> replaceable = kDiffFiles;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(out, ec))  // an earlier diff's --junit report
    if (e.path().extension() == ".xml" && junit_report_kind().is_own(e.path().string()))
      replaceable.push_back(e.path().filename().string());
  if (junit_inside) {
    const std::string name = fs::path(junit).filename().string();
    if (std::find(kDiffFiles.begin(), kDiffFiles.end(), name) != kDiffFiles.end() || name.empty())
      throw std::invalid_argument("--junit: '" + junit + "' is " + name +
                                  " of the diff's folder; name the report otherwise");
    if (fs::exists(fs::symlink_status(junit)))
      util::check_output_file(junit, "--junit", junit_report_kind());
    replaceable.push_back(name);
  } else if (!junit.empty()) {
    util::check_output_file(junit, "--junit", junit_report_kind());
  }
  for (const std::string& input : inputs)
    if (within(out, input))
      throw std::invalid_argument("--out: '" + out + "' is in the batch folder '" + input +
                                  "' (a batch resumes only a folder of its own files); write "
                                  "the diff elsewhere");
  return replaceable;
}

}  // namespace

std::function<int()> add_diff_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "diff",
      "Compare two batch folders episode by episode: gained and lost episodes, paired tests per "
      "configuration, a verdict (exit 1 when the candidate is worse)");
  struct Options {
    std::string baseline, candidate, out, junit;
    double level = 0.05;
  };
  auto opt = std::make_shared<Options>();
  cmd->add_option("baseline", opt->baseline, "The baseline's batch folder")->required();
  cmd->add_option("candidate", opt->candidate, "The candidate's batch folder")->required();
  cmd->add_option("--out", opt->out,
                  "Output folder (default results/diff_<baseline>_vs_<candidate>); new, empty, "
                  "or an earlier diff's");
  cmd->add_option("--level", opt->level,
                  "Significance level of every test (default 0.05); intervals are 1 - level")
      ->check(CLI::Range(0.0001, 0.5));
  cmd->add_option("--junit", opt->junit,
                  "Also write a JUnit XML report, one test case per configuration, a failure "
                  "when it is worse");
  return [opt, cmd]() {
    const auto began = std::chrono::steady_clock::now();
    // Everything is read and checked before anything is written.
    const batch::BatchDiff d = batch::diff_batches(opt->baseline, opt->candidate, opt->level);
    const std::string out = opt->out.empty() ? "results/diff_" + folder_name(opt->baseline) +
                                                   "_vs_" + folder_name(opt->candidate)
                                             : opt->out;
    const bool junit_inside = !opt->junit.empty() && inside(opt->junit, out);
    const std::vector<std::string> replaceable =
        check_outputs(out, opt->junit, junit_inside, {opt->baseline, opt->candidate});
    util::StagedFolder staged(out, replaceable);  // refuses a folder holding anything else
    util::MadeBy made_by;
    made_by.input = "records";
    made_by.input_hash = d.input_hash;
    made_by.duration_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    const std::string command = command_line(cmd);
    const std::string at = staged.path() + "/";
    util::write_file_atomically(at + "diff.json",
                                batch::diff_json(d, made_by, command).dump(2) + "\n");
    util::write_file_atomically(at + "diff.md", batch::diff_markdown(d, made_by, command));
    util::write_file_atomically(at + "diff.html",
                                batch::diff_html(d, made_by, command, staged.destination()));
    const std::string junit = batch::diff_junit(d, made_by);
    if (junit_inside)
      util::write_file_atomically(at + fs::path(opt->junit).filename().string(), junit);
    staged.commit();
    if (!opt->junit.empty() && !junit_inside) util::write_file_atomically(opt->junit, junit);
    for (const batch::ConfigurationDiff& c : d.configurations)
      for (const std::string& w : c.why)
        (c.verdict == batch::DiffVerdict::kWorse ? std::cerr : std::cout)
            << (c.verdict == batch::DiffVerdict::kWorse ? "WORSE " : "better ") << c.name() << ": "
            << w << "\n";
    int worse = 0;
    for (const batch::ConfigurationDiff& c : d.configurations)
      worse += c.verdict == batch::DiffVerdict::kWorse;
    std::cout << "diff: " << batch::diff_verdict_name(d.verdict) << ": " << d.paired
              << " episodes in both, " << d.lost << " lost, " << d.gained << " gained; " << worse
              << " of " << d.configurations.size() << " configurations worse -> "
              << staged.destination() << "\n";
    return d.verdict == batch::DiffVerdict::kWorse ? kExitFailed : kExitOk;
  };
}

}  // namespace plantsim::app
