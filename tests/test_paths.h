// Where tests find shared data and the project's own fixture worlds, and how large the
// statistical and search-heavy tests run in this tree.
#pragma once

#include <algorithm>
#include <cstdlib>
#include <string>

namespace plantsim::test {

// Built in place and returned by name (no temporary moved): GCC 12 misreads the move of a short
// string's inline buffer as an out-of-bounds copy when a concatenation's temporary is returned.
inline std::string joined(const char* folder, const std::string& rel) {
  std::string out;
  out.reserve(std::char_traits<char>::length(folder) + 1 + rel.size());
  out.append(folder).append(1, '/').append(rel);
  return out;
}
inline std::string shared_data(const std::string& rel) { return joined(PLANTSIM_SHARED_DATA, rel); }
inline std::string source_file(const std::string& rel) { return joined(PLANTSIM_SOURCE_DIR, rel); }

/// PLANTSIM_SUITE_SCALE in (0, 1) (scripts/test.sh sets 0.025 in the sanitizer tree, where each
/// episode costs several times more): the share of their size the suites and the long searches
/// run at. There they look for memory errors and undefined behaviour on every path; the
/// statistics and the large proofs are the Release tree's. 1 elsewhere.
inline double suite_scale() {
  const char* env = std::getenv("PLANTSIM_SUITE_SCALE");
  const double s = env ? std::atof(env) : 1.0;
  return s > 0 && s < 1 ? s : 1.0;
}
inline bool full_size() { return suite_scale() == 1.0; }
/// `count` at the suite scale, never below `at_least`.
inline int scaled(int count, int at_least) {
  return full_size() ? count : std::max(at_least, static_cast<int>(count * suite_scale()));
}

}  // namespace plantsim::test
