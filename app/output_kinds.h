// The kinds of output file the commands write to a path the user names (--junit, --out,
// --html), each able to tell an earlier output of its own from anything else at that path:
// an output replaces only its own kind (util::check_output_file).
#pragma once

#include "util/atomic_file.h"

namespace plantsim::app {

const util::OutputKind& junit_report_kind();      ///< batch and merge --junit
const util::OutputKind& summary_markdown_kind();  ///< summarize --out
const util::OutputKind& dashboard_kind();         ///< summarize --html
const util::OutputKind& config_file_kind();       ///< nav2-import --out
const util::OutputKind& world_file_kind();        ///< generate and vary --out

}  // namespace plantsim::app
