// The one rule for names, wherever they come from: a world's "name" or its file's name, a
// scenario's, its faults', controllers', sweeps' and planners' names. Names label figures and
// reports, make episode ids and folder names, and are printed: each must be readable as it is.
#pragma once

#include <string>

namespace plantsim::worlds {

/// Empty when `name` is a valid name; otherwise what is wrong with it, in words that do not
/// repeat the name (it may not be printable). Valid: 1 to 100 bytes of UTF-8, no control,
/// invisible or direction-changing character (util::invisible_or_control), no '|' (it separates
/// an episode id's parts), no space at either end, and not only dots.
std::string name_problem(const std::string& name);

/// A world's name from its file's name (the stem), checked by the same rule: a WorldError
/// naming the file when the stem cannot be a name, with `remedy` (what the user can do).
std::string name_from_file(const std::string& path, const std::string& remedy);

}  // namespace plantsim::worlds
