// Unknown keys in input files are errors, not silence: a typo such as "obstacels" would drop
// every obstacle it meant to add. The message suggests the nearest known name.
#pragma once

#include <string>
#include <vector>

namespace plantsim::worlds {

/// The known name closest to `key` by edit distance, when it is close enough to be a typo
/// (at most a third of the key's length, and 3, edits); empty otherwise.
std::string nearest_known_name(const std::string& key, const std::vector<std::string>& known);

/// "unknown key" with ", did you mean 'obstacles'?" when one is near.
std::string unknown_key_problem(const std::string& key, const std::vector<std::string>& known);

/// True when `text` is valid UTF-8 (JSON records and reports need it).
bool valid_utf8(const std::string& text);

/// A name safe as one folder or file name component: path separators, control characters and
/// characters that break CSV or ids become '_', leading dots are dropped, at most 100 bytes.
std::string file_name_component(const std::string& name);

}  // namespace plantsim::worlds
