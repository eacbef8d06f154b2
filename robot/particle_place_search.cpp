// The places a global match finds for a scan about the estimate, polished and confirmed.
#include "robot/particle_place_search.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "robot/place_refinement.h"
#include "robot/scan_points.h"

namespace plantsim::robot {
namespace {

// The global matches for reseeding search all headings in tiles: each may score more candidates
// than a local relocalisation does.
ScanMatcherParams reseed_matcher(ScanMatcherParams m) {
  m.max_candidates = std::max(m.max_candidates, 120'000L);
  // Its coarse rotation steps move a return 20 m away by up to 17 cm, so the true place may
  // score well below what it scores exactly: places are taken at a lower score, then polished
  // (matched again in a narrow window at full resolution) and judged by min_score.
  m.min_score *= 0.6;
  return m;
}

}  // namespace

ScanMatcher& ParticlePlaceSearch::matcher() {
  if (!matcher_) matcher_.emplace(map_, reseed_matcher(global_.matcher));
  return *matcher_;
}

double ParticlePlaceSearch::resolution_m() { return matcher().resolution_m(); }

void ParticlePlaceSearch::searched(double t_s, bool found_nothing) {
  // It costs, and while the view does not change it will find nothing again.
  backoff_ = found_nothing ? std::min(8, 2 * backoff_) : 1;
  next_s_ = t_s + backoff_ * global_.global_match_period_s;
}

ParticlePlace ParticlePlaceSearch::polish(const LidarScan& scan, ParticlePlace place) {
  // A wide window is searched in coarse rotation steps (a return 20 m away moves up to 17 cm
  // between them): each place it finds is matched again in a narrow window at full resolution,
  // climbing while that improves it, so that places are ranked by how well the scan fits them,
  // not by how near the coarse grid passed to each. The narrow match's spread says along what
  // the scan leaves the place open (a lone wall).
  const MatchWindow narrow{0.5 * global_.matcher.apart_m, 0.5 * global_.matcher.apart_rad};
  for (int climb = 0; climb < 4; ++climb) {
    const std::optional<ScanMatch> fine = matcher().match(scan, place.pose, narrow);
    if (!fine || fine->score <= place.score) break;
    place = {fine->pose, fine->score, fine->spread};
  }
  return place;
}

ParticlePlaceSearch::Result ParticlePlaceSearch::search(const LidarScan& scan,
                                                        const geom::Pose2& estimate, bool trusted,
                                                        bool agrees, const LikelihoodField& field) {
  Result out;
  ScanMatcher& m = matcher();
  const MatchWindow window{p_.reseed_tile_m, M_PI};
  auto apart = [&](const geom::Pose2& l, const geom::Pose2& r) {
    return geom::distance(l.position(), r.position()) > global_.matcher.apart_m ||
           std::fabs(geom::wrap_angle(l.yaw - r.yaw)) > global_.matcher.apart_rad;
  };
  auto by_score = [](const ParticlePlace& l, const ParticlePlace& r) { return l.score > r.score; };
  std::vector<ParticlePlace> found;
  const int rings = std::max(0, p_.reseed_rings - 1);
  for (int ring = 0; ring <= rings; ++ring) {
    for (int a = -ring; a <= ring; ++a)
      for (int b = -ring; b <= ring; ++b) {
        if (std::max(std::abs(a), std::abs(b)) != ring) continue;
        const geom::Pose2 centre{estimate.x + 2.0 * p_.reseed_tile_m * a,
                                 estimate.y + 2.0 * p_.reseed_tile_m * b, estimate.yaw};
        const std::optional<ScanMatch> wide = m.match(scan, centre, window);
        if (!wide) continue;
        for (const auto& [pose, score] : wide->alternatives) {
          const ParticlePlace place = polish(scan, {pose, score, wide->spread});
          if (place.score >= global_.matcher.min_score) found.push_back(place);
        }
      }
    // The best place for the scan about the estimate is the estimate itself: what the map did not
    // explain are things it lacks (boxes, people), not a kidnap. Nothing wider is searched.
    if (ring == 0 && trusted && agrees && !found.empty() &&
        !apart(std::min_element(found.begin(), found.end(), by_score)->pose, estimate)) {
      out.estimate_fits = true;
      return out;
    }
  }
  // No place fits the scan well anywhere: what it sees is mostly things the map lacks (a box in
  // an open yard). No evidence against the estimate either.
  out.estimate_fits = found.empty();
  std::stable_sort(found.begin(), found.end(), by_score);
  const std::vector<geom::Vec2> points = scan_points(scan, 90);
  for (ParticlePlace f : found) {
    if (static_cast<int>(out.candidates.size()) >= p_.max_places) break;
    if (!std::all_of(out.candidates.begin(), out.candidates.end(),
                     [&](const ParticlePlace& k) { return apart(k.pose, f.pose); }))
      continue;
    f.pose = refine_on_field(field, points, f.pose, 0.2, 0.05);
    const std::optional<double> agree =
        scan_agreement(raycaster_, scan, f.pose, global_.verify_tolerance_m);
    if (agree && *agree >= global_.verify_agreement) out.candidates.push_back(f);
  }
  // The best confirmed place is the estimate itself (a scan that agreed less than it should:
  // noise, things the map lacks): nothing to reseed, unless a failed confirmation doubts it.
  if (trusted && !out.candidates.empty() && !apart(out.candidates.front().pose, estimate)) {
    out.candidates.clear();
    out.estimate_fits = true;
  }
  return out;
}

}  // namespace plantsim::robot
