// The particle filter's confirmation of a reseeded estimate: owns the reseed's places
// (place_hypotheses.h), carried along by the odometry and judged scan by scan, the turn and
// travel since the estimate was last doubted, the strikes against it, and the redraw it asks
// for (fresh particles about the estimate's own place, or the set handed over to the rival
// places left). While it is under way the filter reports itself lost.
#pragma once

#include <optional>
#include <vector>

#include "robot/global_match.h"
#include "robot/map_raycaster.h"
#include "robot/particle_field_model.h"
#include "robot/particle_motion_model.h"
#include "robot/particle_set.h"
#include "robot/place_hypotheses.h"
#include "robot/readings.h"

namespace plantsim::robot {

/// After a reseed the filter reports itself lost until its estimate is confirmed by views the
/// reseed did not use: the set one tight hypothesis and every scan agreeing with the map at
/// it (global_match.h's verify_agreement) while the robot turns this far or moves this far.
/// A scan that disagrees starts the confirmation again; `confirm_strikes` of them reseed,
/// searching wide even if the estimate fits best nearby (a look-alike seen from one side).
/// The reseed's other places are carried along meanwhile (place_hypotheses.h): the estimate
/// is not confirmed while one of them still agrees with the scans (`confirm_strikes`
/// contradictions or trailing the best place's summed log-likelihood by `rival_margin` rule a
/// place out), and an estimate whose place is ruled out, or is contradicted, hands over to them.
struct ParticleConfirmationParams {
  double confirm_turn_rad = 4.7;
  double confirm_move_m = 3.0;
  int confirm_strikes = 3;
  double rival_margin = 30;
  /// The estimate is not confirmed while its own place (refined onto each scan) lies farther
  /// than this from it; after `confirm_strikes` such scans fresh particles are drawn about it.
  double place_offset_m = 0.25;
};

/// What contradicts a place: a scan agreeing with the map less than `contradicted_agreement`
/// there, or one of `min_returns` returns or more explained less than `min_explained`.
struct ParticleContradiction {
  double contradicted_agreement = 0.7;
  double min_explained = 0.3;
  int min_returns = 20;
};

class ParticleConfirmation {
 public:
  ParticleConfirmation(const ParticleConfirmationParams& params,
                       const ParticleContradiction& contradiction, const GlobalMatchParams& global)
      : p_(params), contradiction_(contradiction), global_(global) {}

  bool active() const { return active_; }
  /// A failed confirmation doubts the estimate: the next search does not stop at it.
  bool doubted() const { return doubted_; }
  void clear_doubt() { doubted_ = false; }
  /// The rivals to hand the set over to (taken), and the place to draw fresh particles about.
  bool handing_over() const { return !handover_.empty(); }
  std::vector<ParticlePlace> take_handover();
  const std::optional<ParticlePlace>& nudge() const { return nudge_; }
  void clear_nudge() { nudge_.reset(); }

  /// A reseed drew the set about these places: the confirmation starts.
  void start(const std::vector<ParticlePlace>& places);
  /// The particles moved by `m`: the places carried along, the turn and travel counted.
  void moved(const OdometryDelta& m);
  /// One scan's part in confirming `estimate` (`agree`: the scan's agreement with the map at it,
  /// none when too few beams judge; `sigma_m`: the set's spread, over `lost_sigma_m` not yet one
  /// hypothesis) and in ruling out its rivals. Returns whether the estimate must be reseeded.
  bool check(const LidarScan& scan, const std::optional<double>& agree, const geom::Pose2& estimate,
             double sigma_m, double lost_sigma_m, ParticleFieldModel& field,
             const MapRaycaster& raycaster);

 private:
  /// The scan's verdict on a place (refined onto the scan first, written back).
  PlaceHypotheses::Verdict judge_place(const LidarScan& scan, geom::Pose2& place,
                                       ParticleFieldModel& field, const MapRaycaster& raycaster);

  ParticleConfirmationParams p_;
  ParticleContradiction contradiction_;
  GlobalMatchParams global_;
  bool active_ = false;
  double turned_rad_ = 0, moved_m_ = 0;
  int strikes_ = 0;
  int offset_scans_ = 0;                 // scans in a row the estimate's own place lay off it
  PlaceHypotheses places_;               // the last reseed's places, until the scans rule them out
  std::optional<ParticlePlace> nudge_;   // fresh particles to draw about the estimate's own place
  std::vector<ParticlePlace> handover_;  // rivals still agreeing when the estimate was contradicted
  bool doubted_ = false;
};

}  // namespace plantsim::robot
