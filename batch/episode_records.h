// episodes.jsonl, the batch's record of its episodes: read as a stream (memory bounded by the
// records kept, never by the file's size; a line longer than any record is counted as bad
// without being held), and the output folder a batch or a merge may write into.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace plantsim::batch {

/// No record is longer: a record's driven path is thinned to about 400 points (3 kB).
inline constexpr std::size_t kMaxRecordBytes = 1u << 20;

struct JsonlScan {
  std::int64_t bad_lines = 0;  ///< malformed, too long, or not a record of a batch
  std::string first_problem;   ///< the first bad line's number and problem, for the warning
  bool torn_tail = false;      ///< a last line without its newline (a killed run)
};

/// Calls `each` with every usable record of the file (batch/record_schema.h: every field of its
/// type, each key once, an id that is the record's own); a missing file has none. The file must be
/// a regular file (never a link, a FIFO or a device): else std::invalid_argument naming it.
JsonlScan scan_jsonl(const std::string& path, const std::function<void(std::string&& line)>& each);

/// Every usable record of the file, in order.
std::vector<std::string> read_records(const std::string& path);

/// The entries a batch or a merge writes into its output folder, and what a kill mid-write
/// leaves of them ("summary.csv.tmp.PID.N").
bool is_batch_output_name(const std::string& name);

/// Removes the temporaries a killed run left in the folder and its failures/ (call it holding
/// the folder's lock: no other plantsim is writing them).
void remove_batch_temporaries(const std::string& dir);

/// Removes every batch output of the folder but its lock (--fresh: nothing of an earlier run
/// stays beside the new one). Only names is_batch_output_name knows; a user's file is never
/// there, for check_batch_output_folder refused the folder before. A merge keeps the records
/// (it replaces them atomically afterwards; they may be one of its inputs).
void remove_batch_outputs(const std::string& dir, bool keep_records = false);

/// Refuses (std::invalid_argument, before any work) an output folder that holds a symbolic
/// link, anything a batch does not write, or batch outputs without their episodes.jsonl (a
/// user's own report.html): a batch resumes its own folder, never replaces someone's files.
/// `own` names further files of this run that may stand there (a --junit report written into
/// the folder).
void check_batch_output_folder(const std::string& dir, const std::vector<std::string>& own = {});

}  // namespace plantsim::batch
