// What a tuning leaves in its folder besides evaluations.jsonl: best.json (the tuned values as a
// configuration that `run --config` reads, and that a batch scenario's controller names),
// summary.json, validation.csv, the two charts and report.html.
#pragma once

#include <string>

#include "tune/run_tune.h"
#include "util/made_by.h"

namespace plantsim::tune {

void write_tune_outputs(const TuneSpec& spec, const TuneOutcome& outcome,
                        const TuneOptions& options, const util::MadeBy& made_by);

}  // namespace plantsim::tune
