// The one verdict (see the header): failed when any run did not succeed or any linked report
// failed; "mixed builds" (not green) when a batch's records come from several builds unaccepted;
// passed when something was judged and nothing failed.
#include "render/overall_verdict.h"

namespace plantsim::render {
namespace {

/// "2 of 3 batches below their gates: a, b" for the links of one kind that failed.
std::string failed_links(const std::vector<DashboardLink>& links, const std::string& kind,
                         const std::string& plural, const std::string& failing, int& judged,
                         int& passed) {
  int of_kind = 0, failed = 0;
  std::string names;
  for (const DashboardLink& l : links) {
    if (l.kind != kind) continue;
    ++of_kind;
    if (l.verdict == "passed") ++passed, ++judged;
    if (l.verdict == "failed") {
      ++judged, ++failed;
      names += (names.empty() ? "" : ", ") + l.title;
    }
  }
  if (failed == 0) return "";
  return std::to_string(failed) + " of " + std::to_string(of_kind) + " " + plural + " " + failing +
         ": " + names;
}

}  // namespace

OverallVerdict overall_verdict(const std::vector<DashboardRun>& runs,
                               const std::vector<DashboardLink>& links) {
  int judged = 0, passed = 0;
  std::vector<std::string> failures;
  for (const auto& [kind, plural, failing] :
       {std::tuple<std::string, std::string, std::string>{"batch", "batches", "below their gates"},
        {"tune", "tunings", "failed their held-out check"},
        {"comparison", "comparisons", "failed"}})
    if (std::string f = failed_links(links, kind, plural, failing, judged, passed); !f.empty())
      failures.push_back(std::move(f));
  // A batch of records of several builds that nobody accepted: no build's pass, so no PASS.
  std::string mixed;
  for (const DashboardLink& l : links)
    if (l.verdict == "mixed") mixed += (mixed.empty() ? "" : ", ") + l.title;
  int runs_failed = 0;
  std::string run_names;
  for (const DashboardRun& r : runs) {
    ++judged;
    if (r.succeeded) continue;
    ++runs_failed;
    run_names += (run_names.empty() ? "" : ", ") + r.world + " (" + r.status + ")";
  }
  if (runs_failed > 0)
    failures.push_back(std::to_string(runs_failed) + " of " + std::to_string(runs.size()) +
                       " single runs did not succeed: " + run_names);
  OverallVerdict v;
  if (!failures.empty()) {
    v.kind = OverallVerdict::Kind::kFail, v.word = "FAIL";
    for (std::size_t i = 0; i < failures.size(); ++i) v.why += (i ? "; " : "") + failures[i];
  } else if (!mixed.empty()) {
    v.word = "MIXED BUILDS";
    v.why =
        "batches whose records several builds ran, not accepted (--accept-mixed-builds): " + mixed;
  } else if (judged > 0) {
    v.kind = OverallVerdict::Kind::kPass, v.word = "PASS";
    v.why = "every single run succeeded (" + std::to_string(runs.size()) +
            ") and every report with a verdict passed (" + std::to_string(passed) + ")";
  } else {
    v.word = "NO VERDICT";
    v.why = "no run and no gated batch or tuning to judge";
  }
  return v;
}

}  // namespace plantsim::render
