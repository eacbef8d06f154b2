// The places a reseed found for a kidnapped robot, carried along by its odometry and checked
// against each later scan until the scans rule all but one out. A particle set drawn about
// several look-alikes (a row of racks, a corridor's bays) settles on one of them within a scan
// or two, and a full turn on the spot cannot tell them apart: before the filter calls its
// estimate confirmed, every rival place must have been ruled out, and an estimate whose own
// place is ruled out hands over to the rivals left. A place is ruled out by contradictions (the
// scan disagreeing with the map there) or by falling behind the best place's summed
// log-likelihood by a margin (a sequential test: look-alikes differ only in the few beams that
// see where they differ, scan after scan).
// Robot side: the map, the scans and the odometry only.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include "geometry/vec2.h"

namespace plantsim::robot {

class PlaceHypotheses {
 public:
  /// A scan's verdict on a place: whether it contradicts it and its log-likelihood there.
  struct Verdict {
    bool contradicted = false;
    double log_likelihood = 0;
  };
  /// Judges a place; the pose refined onto the scan (small corrections for the odometry's drift)
  /// is written back.
  using Judge = std::function<Verdict(geom::Pose2& place)>;

  /// Starts over with these places (the reseed's candidates, the chosen one among them).
  void reset(const std::vector<geom::Pose2>& places);
  void clear() { places_.clear(); }
  /// Each place moved by the odometry's motion, given in the frame of the place it starts from.
  void move(const geom::Pose2& delta);
  /// One scan's verdict on each place: a place contradicted `strikes` times, or whose summed
  /// log-likelihood trails the best place's by more than `margin`, is dropped.
  void check(const Judge& judge, int strikes, double margin);
  /// Whether a live place lies within apart_m and apart_rad of `estimate`.
  bool holds(const geom::Pose2& estimate, double apart_m, double apart_rad) const;
  /// The live place nearest `estimate` among those within apart_m and apart_rad of it.
  std::optional<geom::Pose2> nearest(const geom::Pose2& estimate, double apart_m,
                                     double apart_rad) const;
  /// The live place nearest `estimate` (as `nearest`) moved onto `pose`.
  void move_nearest(const geom::Pose2& estimate, double apart_m, double apart_rad,
                    const geom::Pose2& pose);
  /// The live places farther than apart_m or apart_rad from `estimate`.
  std::vector<geom::Pose2> rivals(const geom::Pose2& estimate, double apart_m,
                                  double apart_rad) const;

 private:
  struct Place {
    geom::Pose2 pose;
    int strikes = 0;
    double log_likelihood = 0;  // summed over the scans since the reset
  };
  std::optional<std::size_t> nearest_index(const geom::Pose2& estimate, double apart_m,
                                           double apart_rad) const;
  std::vector<Place> places_;
};

}  // namespace plantsim::robot
