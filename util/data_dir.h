// Where input paths point: the shared data folder (`--data DIR`, $PLANTSIM_DATA, or the
// checkout's ../shared/data found from the executable's own location, so that plantsim works
// from any current folder) and paths written inside a file (relative to that file).
#pragma once

#include <string>

namespace plantsim::util {

/// Sets the shared data folder (from `--data`); throws std::invalid_argument when it is no folder.
void set_data_dir(const std::string& dir);

/// The folder set by set_data_dir, or empty.
const std::string& chosen_data_dir();

/// The shared data folder: as set, else $PLANTSIM_DATA, else <checkout>/../shared/data beside
/// the build folder holding this executable, else ../shared/data.
std::string data_dir();

/// The checkout this executable was built in (the nearest ancestor of its folder holding
/// data/worlds/plants), for its own example worlds; empty when there is none.
std::string checkout_dir();

/// A path as written in a file in folder `base`: "$data/..." is under data_dir(), an absolute
/// path stays, anything else is relative to `base`.
std::string resolve_input_path(const std::string& written, const std::string& base);

}  // namespace plantsim::util
