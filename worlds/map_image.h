// The image of a ROS map_server map: PGM (P5 binary, P2 text) or PNG, as map_server reads
// them, told apart by their first bytes. Colour pixels are the mean of their red, green and
// blue values (map_server's rule); alpha is ignored.
#pragma once

#include <string>
#include <vector>

namespace plantsim::worlds {

struct MapImage {
  int width = 0, height = 0, max_value = 255;
  std::vector<int> values;  ///< row-major, row 0 at the top
};

/// Largest image accepted, in pixels.
inline constexpr double kMaxMapPixels = 64.0e6;

/// Throws WorldError naming the file and what is wrong (not an image, truncated, too large).
MapImage read_map_image(const std::string& path);

}  // namespace plantsim::worlds
