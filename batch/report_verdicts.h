// The batch report's verdict first: a banner (PASS or FAIL; which configurations fail, by how
// much, against which threshold and statistic, with their 95 % intervals), then the table with
// each configuration's gate early and failing rows first, in red; the detail columns in a second
// table below, so that the first fits a 1,400-pixel screen. Everything stays in summary.csv.
#pragma once

#include <string>
#include <vector>

#include "batch/batch_gate.h"
#include "batch/record_builds.h"
#include "render/report.h"

namespace plantsim::batch {

/// The banner's HTML (trusted: every name in it escaped). `unaccepted_mix`: the records are of
/// more than one build and nobody accepted it: a pass is not shown green.
std::string verdict_banner_html(const std::vector<ConfigurationVerdict>& verdicts, const Gate& gate,
                                bool unaccepted_mix = false);

/// Above the verdict when the records are of more than one build: per build, how many
/// episodes; empty for one build.
std::string mixed_builds_banner_html(const std::vector<BuildCount>& builds, bool accepted);

/// The report's table from summary.csv: the main columns, the gate's verdict per row, failing
/// rows first (row class "fail"); returns the detail table's HTML for the report's body.
std::string fill_verdict_table(render::Report& report, const std::string& csv,
                               const std::vector<ConfigurationVerdict>& verdicts,
                               GateStatistic statistic);

}  // namespace plantsim::batch
