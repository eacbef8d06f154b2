// The image of a ROS map_server map: PGM (P5 binary, P2 text) or PNG, told apart by their first
// bytes, decoded to its samples exactly as stored: no gamma or colour-space conversion (a 16-bit
// grey of 0xC000 is 0.75 of white, as map_server reads it), the alpha channel kept (a
// transparent pixel is not a free one: ros_map.h says how map_server's modes read it). The
// dimensions are checked from the header before any pixel buffer is allocated.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace plantsim::worlds {

struct MapImage {
  int width = 0, height = 0;
  int max_value = 255;  ///< of one sample: a PGM's maximum, 255 or 65535 for a PNG
  int colours = 1;      ///< colour samples per pixel summed into `values`: 1 (grey) or 3 (RGB)
  std::vector<std::uint32_t> values;  ///< per pixel, its colour samples summed; row 0 at the top
  std::vector<std::uint16_t> alpha;   ///< per pixel, 0 (transparent) to max_value; empty: opaque

  /// The pixel's mean colour from 0 (black) to 1 (white), as map_server averages colour pixels.
  double shade(std::size_t i) const {
    return values[i] / (static_cast<double>(colours) * max_value);
  }
  /// From 0 (transparent) to 1 (opaque).
  double opacity(std::size_t i) const {
    return alpha.empty() ? 1.0 : alpha[i] / static_cast<double>(max_value);
  }
};

/// Largest image accepted, in pixels.
inline constexpr double kMaxMapPixels = 64.0e6;

/// Throws WorldError naming the file and what is wrong (not an image, truncated, too large).
MapImage read_map_image(const std::string& path);

}  // namespace plantsim::worlds
