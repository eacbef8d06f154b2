// A map image's PNG decoding (worlds/map_image.h reads PGM itself and hands PNG here): libpng's
// low-level reader, row by row, so that samples stay as stored (16 bits, alpha) and no buffer
// of the whole image is made besides the samples kept.
#pragma once

#include <string>

#include "worlds/map_image.h"

namespace plantsim::worlds {

/// `bytes` a whole PNG file; throws WorldError naming `path` (not a readable PNG, truncated,
/// over kMaxMapPixels: refused from the header, before the pixels are allocated).
MapImage decode_png_map(const std::string& bytes, const std::string& path);

}  // namespace plantsim::worlds
