// What plantsim diff writes from a BatchDiff (batch/batch_diff.h): diff.json (everything, as
// data), diff.md (its first line the verdict), diff.html (the verdict, each configuration's
// tests, the changed episodes with the command that re-runs each on both sides and their replays
// side by side) and a JUnit report (one test case per configuration, a failure when worse).
// Each is stamped with the build that made it (util/made_by.h).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "batch/batch_diff.h"
#include "util/made_by.h"

namespace plantsim::batch {

/// Changed episodes listed at most in diff.json, diff.html and diff.md (the counts are whole).
inline constexpr std::size_t kDiffJsonChanged = 10000;
inline constexpr std::size_t kDiffHtmlChanged = 2000;
inline constexpr std::size_t kDiffMarkdownChanged = 50;

/// The command that re-runs `id` alone into `folder`/episodes/ (batch/batch_gate.h), from the
/// scenario file the record names ("SCENARIO" when it names none).
std::string diff_rerun_command(const DiffSide& side, const std::string& folder,
                               const std::string& id);

/// Where `folder` holds a replay of episode `id` (its episodes/<id>/report.html, else its
/// failure gallery's page), as a path under `folder`; empty when it holds none.
std::string diff_replay(const std::string& folder, const std::string& id);

nlohmann::ordered_json diff_json(const BatchDiff& d, const util::MadeBy& made_by,
                                 const std::string& command);
/// First line "# plantsim diff: WORSE" (BETTER, NO DETECTABLE CHANGE).
std::string diff_markdown(const BatchDiff& d, const util::MadeBy& made_by,
                          const std::string& command);
/// `out_dir`: where diff.html will stand, for the relative links to the replays.
std::string diff_html(const BatchDiff& d, const util::MadeBy& made_by, const std::string& command,
                      const std::string& out_dir);
std::string diff_junit(const BatchDiff& d, const util::MadeBy& made_by);

}  // namespace plantsim::batch
