// What made an output: plantsim's version, the commit it was built from and whether the source
// tree differed from that commit when it was built (cmake/build_stamp.cmake writes them at every
// build), and the date, so that every report, summary, JUnit file and figure says which build
// and when.
#pragma once

#include <string>

namespace plantsim::util {

struct BuildStamp {
  std::string version;
  std::string commit;  ///< 12 hex digits, or "unknown" outside a git checkout
  bool dirty = false;  ///< built from a tree with changes not committed
  /// "plantsim 0.15.0 (commit 1234567890ab)", ", with uncommitted changes" when dirty.
  std::string text() const {
    return "plantsim " + version + " (commit " + commit +
           (dirty ? ", with uncommitted changes)" : ")");
  }
};

const BuildStamp& build_stamp();

/// The time now as ISO 8601 in UTC, to the second ("2026-12-03T15:02:11Z").
std::string utc_now();

}  // namespace plantsim::util
