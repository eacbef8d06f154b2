// Global relocalisation: a correlative scan matcher (Olson 2009, "Real-time correlative scan
// matching"; the idea of Cartographer's real-time correlative matcher) over the robot's map.
// Once per map it builds a likelihood grid (each cell scored by its distance to the nearest
// mapped surface: the rectangles' outlines, not their insides) and a coarser grid of maxima over
// blocks of cells; a match scores every pose of a window (translations on the grid, rotations in
// steps that move the farthest return by about a cell) by the likelihood of the scan's returns,
// bounding whole blocks of translations by the coarse grid first (branch and bound), so that most
// are never scored exactly. Only poses where the robot could stand are answers. It says how sure
// it is: the best pose's score, and the best score of any pose clearly apart from it (a plant of
// repeated racks matches in many places). Robot side: the map only, no truth.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/vec2.h"
#include "robot/readings.h"
#include "worlds/world.h"

namespace plantsim::robot {

struct ScanMatcherParams {
  double resolution_m = 0.1;   ///< likelihood grid cell (coarser on maps past max_cells)
  long max_cells = 4'000'000;  ///< the grid's size limit (memory: 8 bytes a cell, two grids)
  double hit_sigma_m = 0.1;    ///< a return this far from a surface scores exp(-1/2)
  int block = 4;               ///< coarse grid: maxima over block x block cells
  int max_points = 80;         ///< returns used, spread evenly over the scan
  double min_score = 0.55;     ///< mean likelihood of the returns a match must reach
  double max_ambiguity =
      0.9;               ///< the best pose apart from the match must score below this share of it
  double apart_m = 1.0;  ///< poses this far apart (or apart_rad) are different answers
  double apart_rad = 0.3;
  long max_candidates =
      40'000;  ///< rotations x translation blocks bounded per match: wide windows are
               ///< searched in coarser rotation steps (at most max_yaw_step_rad), then narrower
  double max_yaw_step_rad = 0.03;
  int max_alternatives = 8;  ///< distinct near-best poses a match lists (ScanMatch::alternatives)
};

/// The search window around a prior pose: translations within +-xy_m, rotations within +-yaw_rad.
struct MatchWindow {
  double xy_m = 1.0;
  double yaw_rad = 0.3;
};

struct ScanMatch {
  geom::Pose2 pose;
  double score = 0;       ///< mean likelihood of the returns at `pose` (0 to 1)
  double runner_up = 0;   ///< best score of a pose apart from it
  bool accepted = false;  ///< good enough and unambiguous
  long scored = 0;        ///< poses scored exactly (the rest were bounded away)
  /// Covariance (x, y, yaw) of the poses that score within max_ambiguity of the best, about the
  /// best, plus the search grid's step: small along what the scan pins down, large along what it
  /// leaves open (along a lone wall), as Olson 2009 derives a match's covariance.
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
  /// Poses apart from one another (apart_m, apart_rad) that score within max_ambiguity of the
  /// best, the best first, each with its score: the places the scan fits about as well (a plant
  /// of repeated racks), for a particle filter to weigh by the scans that follow.
  std::vector<std::pair<geom::Pose2, double>> alternatives;
};

class ScanMatcher {
 public:
  /// `map` is the plant as the robot knows it: its obstacles, floor walls and mapped charger.
  ScanMatcher(const worlds::World& map, ScanMatcherParams params = {});
  /// The best pose for `scan` within `window` of `prior`; none when the scan has too few returns.
  std::optional<ScanMatch> match(const LidarScan& scan, const geom::Pose2& prior,
                                 const MatchWindow& window) const;
  double resolution_m() const { return res_; }
  /// The likelihood of a return at `p` (0 off the grid).
  double likelihood(geom::Vec2 p) const;

 private:
  /// The search's grid: translation blocks of b cells, n_xy cells and n_yaw rotation steps of
  /// dyaw each way, bounded in work (coarser rotation for wide windows, then a narrower window).
  struct SearchSteps {
    long b, n_xy, n_yaw;
    double dyaw;
  };
  SearchSteps search_steps(const MatchWindow& window, double reach) const;
  /// A pose scored exactly: its score, rotation step and translation in cells from the prior.
  struct Scored {
    double score;
    long s, i, j;
  };
  /// ScanMatch::spread from the scored poses near the best.
  Eigen::Matrix3d near_best_spread(const std::vector<Scored>& good, const ScanMatch& best,
                                   const geom::Pose2& prior, double dyaw) const;
  /// The best score of a pose apart from the best (runner_up) and the distinct near-best poses
  /// (alternatives), from the exact scores.
  void rank_apart(const std::vector<Scored>& good, const geom::Pose2& prior, double dyaw,
                  ScanMatch& best) const;
  void mark_standable(const worlds::World& map);
  /// Whether the robot's centre could be at p on the map (standable_).
  bool standable(const geom::Vec2& p) const;
  double fine(long i, long j) const {
    return inside(i, j) ? fine_[static_cast<std::size_t>(j * nx_ + i)] : 0.0;
  }
  double coarse(long i, long j) const {
    return inside(i, j) ? coarse_[static_cast<std::size_t>(j * nx_ + i)] : 0.0;
  }
  bool inside(long i, long j) const { return i >= 0 && j >= 0 && i < nx_ && j < ny_; }

  ScanMatcherParams p_;
  double res_ = 0.1;
  geom::Vec2 origin_;  // lower left corner of cell (0, 0)
  long nx_ = 0, ny_ = 0;
  std::vector<double> fine_;             // likelihood per cell
  std::vector<double> coarse_;           // max of fine_ over [i, i + block) x [j, j + block)
  std::vector<std::uint8_t> standable_;  // 1 where the robot's centre could be (mark_standable)
};

}  // namespace plantsim::robot
