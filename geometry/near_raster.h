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

  /// kDepends outside the raster's area (the caller tests exactly).
  Answer at(Vec2 p) const;
  double margin_m() const { return margin_; }

 private:
  double margin_;
  Rect area_;
  double cell_ = 1;
  long nx_ = 1, ny_ = 1;
  std::vector<Answer> cells_;
};

}  // namespace plantsim::geom
