// What both estimators share to find the robot again on its map: when and how widely a scan is
// matched globally (scan_matcher.h), and the beam-by-beam check that confirms or contradicts a
// pose (ray casts through the map: what returns pass through, not only where they fall).
#pragma once

#include <optional>
#include <vector>

#include "geometry/vec2.h"
#include "robot/map_raycaster.h"
#include "robot/readings.h"
#include "robot/scan_matcher.h"

namespace plantsim::robot {

struct GlobalMatchParams {
  /// Beyond this 1-sigma a local scan update could lock onto the nearest look-alike: the scan is
  /// matched globally (scan_matcher.h) within three sigmas instead, at most every
  /// global_match_period_s, and the filter restarts from an unambiguous match.
  double global_match_sigma_m = 0.15;
  double global_match_period_s = 0.5;
  double global_match_max_window_m = 10.0;
  /// Up to this 1-sigma the local update still runs when no unambiguous global match is found
  /// (a corridor matches all along itself, yet pins the estimate across it); beyond it only a
  /// global match may move the estimate, and each informative scan that finds none widens the
  /// window by half (a growing search, up to global_match_max_window_m).
  double local_update_max_sigma_m = 0.3;
  /// A global match must also be confirmed beam by beam: ray cast through the map from it, at
  /// least this share of the beams that meet a mapped surface in range must read it (within
  /// verify_tolerance_m); a return short of it, or where the map has none, is something the map
  /// lacks and judges nothing, as does no return where the map has nothing in range. The
  /// matcher scores only where returns fall; this adds what they pass through.
  double verify_agreement = 0.8;
  double verify_tolerance_m = 0.2;
  int global_match_min_returns = 30;  ///< fewer returns: too little to place the robot anywhere
  ScanMatcherParams matcher;
};

/// Share of the beams meeting a mapped surface that read it from `pose` (within `tolerance_m`);
/// none when fewer than 10 beams meet one (too few to judge the pose either way). With
/// `residuals`, the agreeing beams' range errors (read minus mapped) are appended to it.
std::optional<double> scan_agreement(const MapRaycaster& map, const LidarScan& scan,
                                     const geom::Pose2& pose, double tolerance_m,
                                     std::vector<double>* residuals = nullptr);

/// The scan's valid returns.
int valid_returns(const LidarScan& scan);

}  // namespace plantsim::robot
