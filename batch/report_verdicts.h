// The batch report's verdict first: a banner (PASS or FAIL; which configurations fail, by how
// much, against which threshold and statistic, with their 95 % intervals), then the table with
// each configuration's gate early and failing rows first, in red; the detail columns in a second
// table below, so that the first fits a 1,400-pixel screen. Everything stays in summary.csv.
#pragma once

#include <string>
#include <vector>

#include "batch/batch_gate.h"
#include "render/report.h"

namespace plantsim::batch {

/// The banner's HTML (trusted: every name in it escaped).
std::string verdict_banner_html(const std::vector<ConfigurationVerdict>& verdicts,
                                const Gate& gate);

/// The report's table from summary.csv: the main columns, the gate's verdict per row, failing
/// rows first (row class "fail"); returns the detail table's HTML for the report's body.
std::string fill_verdict_table(render::Report& report, const std::string& csv,
                               const std::vector<ConfigurationVerdict>& verdicts,
                               GateStatistic statistic);

}  // namespace plantsim::batch
