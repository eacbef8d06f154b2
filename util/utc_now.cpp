// The time now, for stamps (util/build_stamp.h).
#include <ctime>

#include "util/build_stamp.h"

namespace plantsim::util {

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

}  // namespace plantsim::util
