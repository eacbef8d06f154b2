// Reads VmHWM and VmRSS from /proc/self/status.
#include "bench/memory_probe.h"

#include <malloc.h>

#include <fstream>
#include <sstream>
#include <string>

namespace plantsim::bench {
namespace {

std::optional<double> status_field_mb(const std::string& field) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind(field + ":", 0) != 0) continue;
    std::istringstream in(line.substr(field.size() + 1));
    double kb = 0;
    if (in >> kb) return kb / 1024.0;
  }
  return std::nullopt;
}

}  // namespace

bool reset_peak_memory() {
  // Memory freed by an earlier phase but kept by the allocator would be reused without the
  // resident size growing: hand it back first, so that growth means new memory.
  malloc_trim(0);
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
  clear.flush();
  return static_cast<bool>(clear);
}

std::optional<double> peak_memory_mb() { return status_field_mb("VmHWM"); }
std::optional<double> current_memory_mb() { return status_field_mb("VmRSS"); }

}  // namespace plantsim::bench
