// Sizes beyond which a world is refused as "huge" instead of exhausting memory or time.
#pragma once

#include <cstddef>

namespace plantsim::worlds {

inline constexpr double kMaxFloorSide_m = 10000.0;
inline constexpr std::size_t kMaxObstacles = 200000;
/// A world JSON file: 200,000 rectangles written out with indentation take about 16 MiB, so a
/// larger file is refused before it is parsed (a 200 MB file once took 3 GB and 10 s to refuse).
inline constexpr std::size_t kMaxWorldFileBytes = 32u * 1024u * 1024u;
/// Metres per pixel of a ROS map.
inline constexpr double kMinResolution_m = 0.001;
inline constexpr double kMaxResolution_m = 10.0;
/// Coordinates in world files lie within +-this (metres): beyond it a plant is not a plant and
/// coordinate differences lose the millimetres docking is judged by.
inline constexpr double kMaxCoordinate_m = 1e7;
/// A pose's yaw lies within +-this (radians): a yaw of 1e39 is no heading (its wrap to [-pi, pi]
/// keeps no digit of the intended angle). World files and the Python module refuse beyond it.
inline constexpr double kMaxYaw_rad = 100.0;

}  // namespace plantsim::worlds
