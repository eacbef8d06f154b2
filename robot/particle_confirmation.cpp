// The confirmation of a reseeded estimate: its places judged scan by scan, its progress, the
// redraw it asks for.
#include "robot/particle_confirmation.h"

#include "robot/place_refinement.h"

namespace plantsim::robot {

std::vector<ParticlePlace> ParticleConfirmation::take_handover() {
  std::vector<ParticlePlace> out;
  out.swap(handover_);
  return out;
}

void ParticleConfirmation::start(const std::vector<ParticlePlace>& places) {
  active_ = true;
  turned_rad_ = moved_m_ = 0;
  strikes_ = offset_scans_ = 0;
  std::vector<geom::Pose2> poses;
  for (const ParticlePlace& c : places) poses.push_back(c.pose);
  places_.reset(poses);
}

void ParticleConfirmation::moved(const OdometryDelta& m) {
  turned_rad_ += m.turned_rad;
  moved_m_ += m.moved_m;
  places_.move(m.delta);
}

PlaceHypotheses::Verdict ParticleConfirmation::judge_place(const LidarScan& scan,
                                                           geom::Pose2& place,
                                                           ParticleFieldModel& field,
                                                           const MapRaycaster& raycaster) {
  if (field.points().empty()) return {};
  // Refined within a few centimetres only: the odometry drifts that little between scans, and a
  // wider reach would let a look-alike slide along a corridor to keep fitting.
  place = refine_on_field(field.field(), field.points(), place, 0.05, 0.01);
  const std::optional<double> agree =
      scan_agreement(raycaster, scan, place, global_.verify_tolerance_m);
  const bool contradicted = (agree && *agree < contradiction_.contradicted_agreement) ||
                            (valid_returns(scan) >= contradiction_.min_returns &&
                             field.explained_share(place) < contradiction_.min_explained);
  return {contradicted, field.log_likelihood(place)};
}

bool ParticleConfirmation::check(const LidarScan& scan, const std::optional<double>& agree,
                                 const geom::Pose2& estimate, double sigma_m, double lost_sigma_m,
                                 ParticleFieldModel& field, const MapRaycaster& raycaster) {
  const double apart_m = global_.matcher.apart_m, apart_rad = global_.matcher.apart_rad;
  places_.check([&](geom::Pose2& place) { return judge_place(scan, place, field, raycaster); },
                p_.confirm_strikes, p_.rival_margin);
  const std::vector<geom::Pose2> rivals = places_.rivals(estimate, apart_m, apart_rad);
  // Progress counts only while the set is one hypothesis: two live ones are not yet a place.
  if (sigma_m > lost_sigma_m) {
    turned_rad_ = moved_m_ = 0;
    return false;
  }
  // The estimate's own place ruled out while others live: the set chose a look-alike.
  if (!rivals.empty() && !places_.holds(estimate, apart_m, apart_rad)) {
    turned_rad_ = moved_m_ = 0;
    strikes_ = 0;
    for (const geom::Pose2& r : rivals) handover_.push_back({r, 0, Eigen::Matrix3d::Zero()});
    return false;
  }
  // The estimate's own place, refined scan by scan, has moved off it: the set lost the spread
  // that held the truth (along a wall the scans leave open, until a corner comes into view).
  // Fresh particles are drawn about the place and the scans choose.
  const std::optional<geom::Pose2> own = places_.nearest(estimate, apart_m, apart_rad);
  const bool own_off =
      own && geom::distance(own->position(), estimate.position()) > p_.place_offset_m;
  // ... unless the estimate fits the scan clearly better than its place does (by kClearlyBetter
  // nats: along a lone wall both fit alike, and there the place is the guard): then the place is
  // what drifted (refined a few centimetres a scan, it cannot climb out once the wall's end comes
  // into view), and it moves onto the estimate. Drawing particles about it would pull the set off
  // the better fit, scan after scan (training yard_s2, seed 4: the place 0.42 m off and 19 nats
  // worse, the estimate 1 cm off, the confirmation started again every third scan until the
  // robot gave up).
  constexpr double kClearlyBetter = 5.0;
  if (own_off && field.log_likelihood(estimate) >= field.log_likelihood(*own) + kClearlyBetter) {
    places_.move_nearest(estimate, apart_m, apart_rad, estimate);
    offset_scans_ = 0;
  } else if (own_off) {
    if (++offset_scans_ >= p_.confirm_strikes) {
      turned_rad_ = moved_m_ = 0;
      offset_scans_ = 0;
      nudge_ = ParticlePlace{*own, 0, Eigen::Matrix3d::Zero()};
    }
    return false;
  }
  offset_scans_ = 0;
  if (agree && *agree < contradiction_.contradicted_agreement) {
    turned_rad_ = moved_m_ = 0;
    if (++strikes_ >= p_.confirm_strikes) {
      strikes_ = 0;
      if (rivals.empty()) {
        doubted_ = true;
        return true;  // reseed
      }
      for (const geom::Pose2& r : rivals) handover_.push_back({r, 0, Eigen::Matrix3d::Zero()});
    }
    return false;
  }
  // A rival place still agreeing with every view so far: the estimate is one of two look-alikes.
  if (!rivals.empty()) return false;
  if (turned_rad_ >= p_.confirm_turn_rad || moved_m_ >= p_.confirm_move_m) {
    active_ = false;
    turned_rad_ = moved_m_ = 0;
    strikes_ = offset_scans_ = 0;
    places_.clear();
  }
  return false;
}

}  // namespace plantsim::robot
