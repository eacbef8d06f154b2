// Reading an input file whole, safely: only regular files (a FIFO would block forever, a
// device such as /dev/zero never ends), refused above a size limit before a byte is read.
// Every loader reads through here so that hostile paths are handled in one place.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace plantsim::util {

/// Input files larger than this are refused (docs/world_format.md says so): 256 MiB holds a
/// 16000 x 16000 PGM map, far beyond any plant plantsim plans over.
inline constexpr std::uint64_t kMaxInputFileBytes = 256ull << 20;

/// A file that cannot be read, is not a regular file, or is too large.
struct InputFileError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// The whole file. Throws InputFileError: "cannot be opened (No such file or directory)", "is
/// not a regular file (a FIFO)", "is 70000000 bytes, more than the 67108864 allowed".
std::string read_input_file(const std::string& path, std::uint64_t max_bytes = kMaxInputFileBytes);

}  // namespace plantsim::util
