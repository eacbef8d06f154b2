// The figure colours, named once so that drawings and pixel tests agree. The hues that must be
// told apart at a glance (plan, charger, start, moving obstacles, target, events) are Okabe and
// Ito's colour-blind-safe set; speed is on cividis (colormap.h), which none of them lies on.
#pragma once

#include "render/image.h"

namespace plantsim::render::palette {

// Okabe-Ito (Okabe & Ito 2008, "Color Universal Design").
inline constexpr Rgb kOkabeBlack{0, 0, 0};
inline constexpr Rgb kOkabeOrange{230, 159, 0};
inline constexpr Rgb kOkabeSkyBlue{86, 180, 233};
inline constexpr Rgb kOkabeBluishGreen{0, 158, 115};
inline constexpr Rgb kOkabeYellow{240, 228, 66};
inline constexpr Rgb kOkabeBlue{0, 114, 178};
inline constexpr Rgb kOkabeVermillion{213, 94, 0};
inline constexpr Rgb kOkabeReddishPurple{204, 121, 167};

inline constexpr Rgb kBackground{255, 255, 255};
inline constexpr Rgb kFloor{248, 247, 242};
inline constexpr Rgb kGrid{222, 222, 218};
inline constexpr Rgb kInflation{236, 222, 200};
inline constexpr Rgb kObstacle{64, 64, 64};
inline constexpr Rgb kGraph{170, 170, 190};
inline constexpr Rgb kPlan = kOkabeVermillion;  ///< the plan at the end, drawn over the driven path
inline constexpr Rgb kFirstPlan{0, 0, 0};       ///< the plan set off on, dashed, when replanned
inline constexpr Rgb kTrajectory =
    kOkabeBlue;  ///< a driven path in one colour (plots, batch overlays)
inline constexpr Rgb kFailure = kOkabeVermillion;  ///< failed episodes in batch overlays
inline constexpr Rgb kCharger = kOkabeBluishGreen;
// Black, not orange: under deuteranopia orange starts and vermillion failed paths were one colour
// (render/colour_vision.h; tests/test_render.cpp checks the pairs a reader must tell apart).
inline constexpr Rgb kStart = kOkabeBlack;
/// A success bar that meets its gate while its 95 % lower bound is below it (between the failing
/// vermillion and the passing green, told apart from both under deuteranopia and protanopia).
inline constexpr Rgb kUnsureBar = kOkabeSkyBlue;
inline constexpr Rgb kRobot{20, 20, 20};
inline constexpr Rgb kMoving =
    kOkabeSkyBlue;  ///< moving obstacles, their swept tracks and time ticks
inline constexpr Rgb kAxis{40, 40, 48};
inline constexpr Rgb kFootprint{120, 120, 130};
inline constexpr Rgb kTarget = kOkabeReddishPurple;  ///< a moving target and its track
inline constexpr Rgb kExplored{180, 222,
                               180};  ///< a walk before the answer (003's exploration, 002's raw
                                      ///< walk): a pale green band, off the speed scale
inline constexpr Rgb kExploredText{40, 105,
                                   40};    ///< letters recorded on it (darker, to read on the band)
inline constexpr Rgb kTried{0, 110, 110};  ///< the ring search's walks (dashed), seed 003
/// A sampling controller's trajectories in the replay: a few of its samples (thin) and its choice.
inline constexpr Rgb kSampledTrajectory = kOkabeSkyBlue;
inline constexpr Rgb kChosenTrajectory = kOkabeReddishPurple;
inline constexpr Rgb kWallFollow{
    215, 185,
    240};  ///< potential-field travel while following a wall (band; not the speed scale's yellow)
inline constexpr Rgb kScan{20, 50, 140};  ///< lidar returns the map explains (dots): navy, apart
                                          ///< from the greys of the estimate and the footprints
/// Lidar returns the map does not explain (tracked obstacles): dark plum ({150, 0, 90} was 9
/// Delta E from the obstacles' grey under deuteranopia).
inline constexpr Rgb kScanOffMap{75, 0, 75};
inline constexpr Rgb kTracked{0, 0, 0};         ///< boxes of the tracked obstacles (outlines)
inline constexpr Rgb kEstimate{185, 185, 185};  ///< the path as the robot estimated it (band)
inline constexpr Rgb kUnmapped{150, 30,
                               30};  ///< obstacles in the plant but not on the map (hatched)
/// The local obstacle layer's occupied cells: a light green. Its violet {120, 90, 200}, the
/// failure's purple and the replan rings' blue were one blue under deuteranopia (issue 89; checked
/// by tests/test_figure_layout.cpp under deuteranopia, protanopia and tritanopia).
inline constexpr Rgb kLayer{150, 255, 105};
inline constexpr Rgb kStopMark{0, 0, 0};        ///< where the robot stopped for something (ring)
inline constexpr Rgb kReplanMark = kOkabeBlue;  ///< where it replanned (ring)
inline constexpr Rgb kRecoveryMark =
    kOkabeOrange;  ///< where it recovered after a displacement (ring)
/// Where a collision began (cross): magenta. Pure red {220, 0, 0} was 8 Delta E from the
/// vermillion plan under deuteranopia, and every red within 12 of the obstacles' dark grey under
/// protanopia, where collisions are drawn.
inline constexpr Rgb kCollisionMark{225, 60, 255};
/// Where the docking backed off to retry (ring): khaki; the reddish purple was 12 Delta E from the
/// footprints' grey rings under deuteranopia.
inline constexpr Rgb kRetryMark{195, 165, 90};
/// Where the episode failed (filled diamond): a blue violet, apart from the replan rings' blue
/// under deuteranopia ({150, 0, 200} was 18 Delta E from it, 10 from the old layer).
inline constexpr Rgb kFailureMark{120, 0, 255};
/// A kidnap's carry (dashed, lifted ring to set-down square): orange, the colour of the recovery
/// that follows it, on no other line of the run figure.
inline constexpr Rgb kCarry = kOkabeOrange;
inline constexpr Rgb kTolerance = kOkabeBluishGreen;  ///< the docking tolerance box (inset)
inline constexpr Rgb kPhaseTravel{235, 240, 250};     ///< time-plot shading by phase
inline constexpr Rgb kPhaseDocking{232, 246, 238};
inline constexpr Rgb kPhaseBackOff{252, 238, 226};

}  // namespace plantsim::render::palette
