// Where the particle filter's recovery draws fresh particles (in AMCL, a uniform pose
// generator; here the places a global scan match finds, on a 100 m plant uniform particles
// would never land near the truth): owns the search's parameters, its scan matcher (built the
// first time it is needed) and its schedule (a search that finds nothing is repeated less and
// less often). Searches a square of tiles about the estimate and keeps the places the beams
// confirm.
#pragma once

#include <optional>
#include <vector>

#include "geometry/vec2.h"
#include "robot/global_match.h"
#include "robot/likelihood_field.h"
#include "robot/map_raycaster.h"
#include "robot/particle_set.h"
#include "robot/readings.h"
#include "robot/scan_matcher.h"
#include "worlds/world.h"

namespace plantsim::robot {

struct ParticlePlaceSearchParams {
  double reseed_tile_m = 3.5;  ///< half-size of one global match's window (all headings)
  int reseed_rings = 2;  ///< tiles searched: this many rings of them about the estimate (2: the
                         ///< square 10.5 m about it, with tiles of 3.5 m)
  /// Places a reseed keeps (the best-scoring of those the beams confirm): among racks in rows
  /// the true place may score below several look-alikes in the view the kidnap left.
  int max_places = 16;
};

class ParticlePlaceSearch {
 public:
  ParticlePlaceSearch(const worlds::World& map, const MapRaycaster& raycaster,
                      const GlobalMatchParams& global, const ParticlePlaceSearchParams& params)
      : map_(map), raycaster_(raycaster), global_(global), p_(params) {}

  /// The places found for the scan about `estimate` that the beams confirm, or that the best
  /// place near the estimate is the estimate itself. `trusted`: the estimate may end the search
  /// (else a failed confirmation doubts it); `agrees`: the scan agreed with the map at it.
  struct Result {
    std::vector<ParticlePlace> candidates;
    bool estimate_fits = false;  ///< or nothing fits anywhere: no evidence against it
  };
  Result search(const LidarScan& scan, const geom::Pose2& estimate, bool trusted, bool agrees,
                const LikelihoodField& field);

  /// Whether a search is due at `t_s`, and the next one scheduled after a search at `t_s`
  /// (`found_nothing`: backs off up to 8 periods).
  bool due(double t_s) const { return t_s + 1e-9 >= next_s_; }
  void searched(double t_s, bool found_nothing);

  /// The matcher's cells (the spread of a place that has none).
  double resolution_m();

 private:
  ScanMatcher& matcher();
  /// The place matched again in a narrow window at full resolution (see the .cpp).
  ParticlePlace polish(const LidarScan& scan, ParticlePlace place);

  const worlds::World& map_;
  const MapRaycaster& raycaster_;
  GlobalMatchParams global_;
  ParticlePlaceSearchParams p_;
  std::optional<ScanMatcher> matcher_;
  double next_s_ = 0;
  int backoff_ = 1;  // periods between searches
};

}  // namespace plantsim::robot
