// The scenario file as a record names it: relative to the folder that holds the records, never
// absolute, so that a results tree copied or a checkout moved elsewhere still finds its
// scenario and no record carries the machine's directory layout. Readers resolve it against
// the records' folder; a merge re-bases it onto its own.
#pragma once

#include <string>

namespace plantsim::batch {

/// `scenario` (any path) as the records in `records_dir` name it: relative to that folder.
std::string scenario_path_for_records(const std::string& scenario, const std::string& records_dir);

/// What a record's `scenario_file` means, read from `records_dir`: a relative path resolved
/// against that folder; an absolute one (records before issue 89) or "" as it is.
std::string scenario_path_from_record(const std::string& value, const std::string& records_dir);

/// A record line whose scenario_file is re-based from `from_dir` to `to_dir` (a merge's), the
/// rest of the line unchanged; `to_dir` "": made absolute (while a merge holds records of several
/// folders). A line without one as it is.
std::string rebased_record(const std::string& line, const std::string& from_dir,
                           const std::string& to_dir);

}  // namespace plantsim::batch
