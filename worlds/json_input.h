// Parsing a JSON input (a world, an episode config, coverage parameters) as untrusted text: one
// place that turns syntax errors and keys given twice into WorldError naming the file and the
// field, so that every JSON loader refuses the same things in the same words.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace plantsim::worlds {

/// The parsed document. Throws WorldError naming `source`: "malformed JSON: ..." for a syntax
/// error or a number no double holds, and, naming the field, "given twice in one object" for a
/// key repeated in an object (nlohmann-json, like most parsers, would keep the last copy
/// silently, and yaml-cpp the first: a file holding both `"seeds": 1` and `"seeds": 2` has no
/// single meaning).
nlohmann::json parse_json_input(const std::string& text, const std::string& source);

}  // namespace plantsim::worlds
