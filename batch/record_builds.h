// Which builds made a batch's records: every record names the build that ran it ("build" in
// episodes.jsonl), and an output made from the records of more than one build says so, per
// build how many episodes and which commit. The verdict of such a mix is not green unless the
// user accepts it (--accept-mixed-builds). The stamp's parts are util/build_stamp.h's.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace plantsim::batch {

/// This binary's build as a record writes it: "0.15.0 1234567890ab", "+dirty" appended when
/// built from a tree with uncommitted changes.
std::string this_build();

/// What a record says of its build; records written before builds were recorded: "unrecorded".
std::string build_of(const nlohmann::json& record);

struct BuildCount {
  std::string build;
  std::int64_t episodes = 0;
};

/// The builds of `jsonl_lines`, most episodes first (ties by name). Unparsable lines are skipped
/// (the readers downstream report them).
std::vector<BuildCount> record_builds(const std::vector<std::string>& jsonl_lines);

/// "records of 2 builds: 0.15.0 1234567890ab (12 episodes), 0.15.0 abcdef012345 (4 episodes)".
std::string builds_text(const std::vector<BuildCount>& builds);

/// summary.json's "builds": [{"build": ..., "episodes": n}, ...].
nlohmann::json builds_json(const std::vector<BuildCount>& builds);

}  // namespace plantsim::batch
