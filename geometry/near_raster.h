// "Does some box come within a margin of this point?" answered from a raster built once: each
// cell records whether the answer is yes everywhere in it, no everywhere, or depends on where
// (only then is the caller's exact test needed). A lidar's returns mostly fall in cells of the
// first two kinds, so the per-return question costs one array read.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/vec2.h"

namespace plantsim::geom {

class NearRaster {
 public:
  enum class Answer : std::uint8_t { kNo = 0, kDepends = 1, kYes = 2 };

  /// The answer for "within `margin_m` per axis of one of `boxes`" over `area`, in cells of
  /// `cell_m`, made coarser when the area would need more than `max_cells`.
  NearRaster(const std::vector<Rect>& boxes, double margin_m, Rect area, double cell_m,
             long max_cells = 8'000'000);

  /// kDepends outside the raster's area (the caller tests exactly). A point rounded into the
  /// next cell gets that cell's answer, which is still right: a "yes" cell lies inside a grown
  /// box with rounding to spare, and a ring of "depends" cells separates every box from the
  /// "no" cells.
  Answer at(Vec2 p) const {
    const double fx = (p.x - area_.xmin) * inverse_cell_, fy = (p.y - area_.ymin) * inverse_cell_;
    if (!(fx >= 0 && fy >= 0 && fx < static_cast<double>(nx_) && fy < static_cast<double>(ny_)))
      return Answer::kDepends;
    const long i = static_cast<long>(fx), j = static_cast<long>(fy);
    return get(static_cast<std::size_t>(j * nx_ + i));
  }
  double margin_m() const { return margin_; }

 private:
  double margin_;
  Rect area_;
  double cell_ = 1, inverse_cell_ = 1;
  long nx_ = 1, ny_ = 1;
  // Four answers a byte: a 100 x 60 m plant's raster at 7.5 cm is 0.3 MB rather than 1.1 MB
  // (no speed-up measured on world_N200's episodes; the memory is what it saves).
  std::vector<std::uint8_t> cells_;
  Answer get(std::size_t c) const {
    return static_cast<Answer>((cells_[c >> 2] >> ((c & 3) * 2)) & 3);
  }
  void set(std::size_t c, Answer a) {
    const unsigned shift = static_cast<unsigned>(c & 3) * 2;
    cells_[c >> 2] = static_cast<std::uint8_t>((cells_[c >> 2] & ~(3u << shift)) |
                                               (static_cast<unsigned>(a) << shift));
  }
};

}  // namespace plantsim::geom
