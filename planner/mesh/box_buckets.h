// Point location for a mesh: a uniform grid of buckets over the boxes' bounding box, each
// listing the boxes (cells, polygons' bounds) that overlap it, about one bucket per box.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/vec2.h"

namespace plantsim::planner {

class BoxBuckets {
 public:
  struct Box {
    double xlo, ylo, xhi, yhi;
  };
  BoxBuckets() = default;
  /// `eps`: how far past its edges a box still counts as overlapping a bucket.
  BoxBuckets(const std::vector<Box>& boxes, double eps);
  /// The boxes that may hold p (every one that does, and some that do not).
  struct Span {
    const std::int32_t* b;
    const std::int32_t* e;
    const std::int32_t* begin() const { return b; }
    const std::int32_t* end() const { return e; }
  };
  Span near(geom::Vec2 p) const;

 private:
  double x0_ = 0, y0_ = 0, size_ = 1;
  int nx_ = 1, ny_ = 1;
  std::vector<std::int32_t> index_, start_;
};

}  // namespace plantsim::planner
