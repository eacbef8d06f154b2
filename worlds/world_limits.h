// Sizes beyond which a world is refused as "huge" instead of exhausting memory or time.
#pragma once

#include <cstddef>

namespace plantsim::worlds {

inline constexpr double kMaxFloorSide_m = 10000.0;
inline constexpr std::size_t kMaxObstacles = 200000;
inline constexpr std::size_t kMaxWorldFileBytes = 256u * 1024u * 1024u;

}  // namespace plantsim::worlds
