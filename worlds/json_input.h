// Parsing a JSON input (a world, an episode config, coverage parameters, a record of
// episodes.jsonl, a summary.json or a tuning's evaluations read back) as untrusted text: the one
// function every JSON input goes through, bounded while it reads (nesting depth), turning syntax
// errors and keys given twice into WorldError naming the file and the field, so that every JSON
// loader refuses the same things in the same words. Sizes are bounded by the readers
// (util::read_input_file's limit, episodes.jsonl's longest record).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace plantsim::worlds {

/// Arrays and objects nested deeper than this are refused while the text is read: plantsim's
/// deepest input (a tunnel maze's corridors) nests 5 levels. Unbounded nesting cost memory
/// quadratic in the depth (a 120 KB file of brackets exhausted the memory).
inline constexpr int kMaxJsonDepth = 64;

/// The parsed document. Throws WorldError naming `source`: "malformed JSON: ..." for a syntax
/// error or a number no double holds, and, naming the field, "given twice in one object" for a
/// key repeated in an object (nlohmann-json, like most parsers, would keep the last copy
/// silently, and yaml-cpp the first: a file holding both `"seeds": 1` and `"seeds": 2` has no
/// single meaning) and "nests deeper than 64 levels" past kMaxJsonDepth.
nlohmann::json parse_json_input(const std::string& text, const std::string& source);

/// The same, keeping the objects' keys in the file's order (for a file rewritten for the user).
nlohmann::ordered_json parse_ordered_json_input(const std::string& text, const std::string& source);

}  // namespace plantsim::worlds
