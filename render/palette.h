// The figure colours, named once so that drawings and pixel tests agree.
#pragma once

#include "render/image.h"

namespace plantsim::render::palette {

inline constexpr Rgb kBackground{255, 255, 255};
inline constexpr Rgb kFloor{248, 247, 242};
inline constexpr Rgb kGrid{222, 222, 218};
inline constexpr Rgb kInflation{250, 210, 170};
inline constexpr Rgb kObstacle{70, 76, 92};
inline constexpr Rgb kGraph{190, 200, 225};
inline constexpr Rgb kPlan{30, 110, 230};
inline constexpr Rgb kTrajectory{215, 25, 35};
inline constexpr Rgb kCharger{20, 150, 60};
inline constexpr Rgb kStart{245, 160, 0};
inline constexpr Rgb kRobot{20, 20, 20};
inline constexpr Rgb kMoving{150, 60, 170};
inline constexpr Rgb kAxis{40, 40, 48};
inline constexpr Rgb kFootprint{120, 120, 130};
inline constexpr Rgb kTarget{225, 50, 150};      ///< a moving target and its track
inline constexpr Rgb kExplored{140, 170, 200};   ///< a hand-rule exploration walk
inline constexpr Rgb kWallFollow{255, 200, 60};  ///< potential-field travel while following a wall
inline constexpr Rgb kScan{86, 180, 233};         ///< lidar returns the map explains
inline constexpr Rgb kScanOffMap{213, 94, 0};     ///< lidar returns it does not (tracked obstacles)
inline constexpr Rgb kTracked{0, 0, 0};           ///< boxes of the tracked obstacles (outlines)
inline constexpr Rgb kEstimate{120, 60, 0};       ///< the path as the robot estimated it
inline constexpr Rgb kUnmapped{150, 30, 30};      ///< obstacles in the plant but not on the map (hatched)
inline constexpr Rgb kLayer{204, 121, 167};       ///< the local obstacle layer's occupied cells
inline constexpr Rgb kStopMark{0, 158, 115};      ///< where the robot stopped for something (ring)
inline constexpr Rgb kReplanMark{0, 114, 178};    ///< where it replanned (ring)
inline constexpr Rgb kRecoveryMark{213, 0, 0};    ///< where it recovered after a displacement (ring)

}  // namespace plantsim::render::palette
