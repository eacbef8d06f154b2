// Where tests find shared data and the project's own fixture worlds.
#pragma once

#include <string>

namespace plantsim::test {

inline std::string shared_data(const std::string& rel) { return std::string(PLANTSIM_SHARED_DATA) + "/" + rel; }
inline std::string source_file(const std::string& rel) { return std::string(PLANTSIM_SOURCE_DIR) + "/" + rel; }

}  // namespace plantsim::test
