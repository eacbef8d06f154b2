// Writing output files so that a reader never sees half of one: the bytes go to a temporary
// file beside the target, which is renamed over it only when complete.
#pragma once

#include <string>
#include <string_view>

namespace plantsim::util {

/// Throws std::runtime_error naming the path when the file cannot be written.
void write_file_atomically(const std::string& path, std::string_view bytes);

}  // namespace plantsim::util
