// An RGBA8 image in memory, row 0 at the top, as PNG stores it.
#pragma once

#include <cstdint>
#include <vector>

namespace plantsim::render {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(Rgb, Rgb) = default;
};

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  ///< width * height * 4 bytes

  Rgb at(int col, int row) const {
    const std::size_t i = (static_cast<std::size_t>(row) * width + col) * 4;
    return {rgba[i], rgba[i + 1], rgba[i + 2]};
  }
};

}  // namespace plantsim::render
