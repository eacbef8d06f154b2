// One verdict over everything a dashboard or summary.md covers: its single runs and the
// verdicts of the reports it links (batches by their gates, tunings by their held-out check).
// The dashboard's banner, summary.md's first line and `summarize`'s exit code all come from it,
// so a page never says PASS over a run that failed.
#pragma once

#include <string>
#include <vector>

#include "render/dashboard.h"

namespace plantsim::render {

struct OverallVerdict {
  enum class Kind { kPass, kFail, kNone };
  Kind kind = Kind::kNone;
  std::string word;  ///< "PASS", "FAIL", "MIXED BUILDS", "NO VERDICT"
  std::string why;   ///< plain text: what failed, or what passed
  bool failed() const { return kind == Kind::kFail; }
};

OverallVerdict overall_verdict(const std::vector<DashboardRun>& runs,
                               const std::vector<DashboardLink>& links);

}  // namespace plantsim::render
