// What a record of episodes.jsonl must hold before anything reads it: the type of every field
// the batch writes (batch/episode_record.cpp, episode/episode_json.cpp), each key once, and an
// id that agrees with the record's own world, planner, controller, fault and seed. A record that
// fails is malformed: left out (and rerun, or refused as missing by a merge), never half-read.
#pragma once

#include <string>

namespace plantsim::batch {

/// Empty when `line` is a usable record; else the first problem, naming the field
/// ("field 'time_s': expected a number").
std::string record_problem(const std::string& line);

}  // namespace plantsim::batch
