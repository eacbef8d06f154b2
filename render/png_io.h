// PNG encoding and decoding through libpng. Encoding takes a speed/size setting
// (zlib level and row filters); files are written atomically.
#pragma once

#include <string>

#include "render/image.h"

namespace plantsim::render {

struct PngSettings {
  int compression_level = 6;     ///< zlib level 0..9; 1 is fast, 9 smallest
  bool adaptive_filters = true;  ///< libpng's per-row filter choice; off = no filtering (fast)
  bool run_length = false;       ///< zlib RLE strategy (measured slower than level 1 here)
  static PngSettings fast() { return {1, false, false}; }
};

std::string encode_png(const Image& image, const PngSettings& settings = {});
void write_png(const Image& image, const std::string& path, const PngSettings& settings = {});
/// Throws std::runtime_error when the file is missing or not a valid PNG.
Image read_png(const std::string& path);

}  // namespace plantsim::render
