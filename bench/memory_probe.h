// Resident memory of this process, read from /proc/self (Linux): its current size and its peak
// since the last reset, so that one phase of a benchmark (building a planner, answering queries)
// can be measured on its own.
#pragma once

#include <optional>

namespace plantsim::bench {

/// Returns freed heap memory to the system (glibc's malloc_trim) and sets the peak back to the
/// current size (writes 5 to /proc/self/clear_refs). False where the kernel does not allow it:
/// the peak is then the process's since it started.
bool reset_peak_memory();
/// Peak resident size (VmHWM) in MB; nothing when /proc is not readable.
std::optional<double> peak_memory_mb();
/// Current resident size (VmRSS) in MB.
std::optional<double> current_memory_mb();

}  // namespace plantsim::bench
