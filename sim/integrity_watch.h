// The referee's view of localisation integrity: how far off the estimate the robot drove, and
// whether it drove on a bad estimate without knowing. Measured from the truth every control
// period; nothing here feeds back into the robot. The rule (docs/failures.md): an estimate more
// than 0.25 m from the truth (Nav2's localisation system test holds AMCL to 0.25 m) that the
// estimator does not report `lost` within 2 s, while the robot moves on it, breaks integrity:
// the episode is not a success even if it docked, and fails as localization_lost at the first
// excess of that stretch. Saying `lost` is no licence to drive on: more than 1 m driven in all on
// an estimate 0.25 m off breaks integrity whatever the estimator said (issue 89).
#pragma once

#include <optional>

#include "geometry/vec2.h"
#include "robot/pose_estimator.h"

namespace plantsim::sim {

struct IntegrityParams {
  double off_m = 0.25;       ///< an estimate this far from the truth is off
  double ok_off_m = 0.10;    ///< reported `ok` while this far off is counted apart
  double grace_s = 2.0;      ///< time an estimator has to notice it is off (report lost)
  double moving_mps = 0.02;  ///< true speed above which the robot drives on its estimate
  /// Driven this far in all (true path length) on an estimate off_m off breaks integrity even
  /// when the estimator reported `lost`: a robot that knows it is lost should stop, not drive.
  double max_driven_off_m = 1.0;
};

/// Which side of the rule a breach broke.
enum class BreachKind {
  kUnnoticed,  ///< off for more than grace_s, moving, without reporting `lost`
  kDrivenOff,  ///< more than max_driven_off_m driven in all on an off estimate, whatever reported
};

/// The first breach of the rule. kUnnoticed: when and where (true pose) the estimate first went
/// off in the stretch, the error then and the worst in the stretch, and its length. kDrivenOff:
/// when and where the distance driven off passed max_driven_off_m, the worst moving error of the
/// episode and the distance driven off in all.
struct IntegrityBreach {
  double time_s = 0;
  geom::Pose2 pose;
  double worst_error_m = 0;
  double unnoticed_s = 0;  ///< kUnnoticed: how long it stayed off without `lost` (> grace_s)
  BreachKind kind = BreachKind::kUnnoticed;
  double driven_off_m = 0;  ///< kDrivenOff: true distance driven on an off estimate, in all
};

/// What an episode's record keeps of integrity.
struct IntegrityRecord {
  double worst_moving_error_m = 0;  ///< true position error, worst while the robot moved
  double driven_off_s = 0;          ///< time moving on an estimate more than off_m off
  double driven_off_m = 0;          ///< true distance driven on an estimate more than off_m off
  double ok_while_off_s = 0;        ///< time reported `ok` while more than ok_off_m off
  double not_ok_s = 0;              ///< time the estimator reported anything but `ok`
  std::optional<IntegrityBreach> breach;
};

class IntegrityWatch {
 public:
  explicit IntegrityWatch(IntegrityParams params = {}) : p_(params) {}

  /// Every control period: the true pose and speed, the estimate and its reported health.
  void observe(double t_s, const geom::Pose2& truth, double true_speed_mps,
               const geom::Pose2& estimate, robot::LocalizationHealth health);

  const IntegrityRecord& record() const { return record_; }

 private:
  /// The distance side of the rule: past max_driven_off_m the breach is there, lost or not.
  void judge_distance(double t_s, const geom::Pose2& truth);

  IntegrityParams p_;
  IntegrityRecord record_;
  bool started_ = false;
  double last_s_ = 0;
  // The current stretch off the truth without `lost`, if any.
  bool in_stretch_ = false;
  bool drove_in_stretch_ = false;
  IntegrityBreach stretch_;
};

}  // namespace plantsim::sim
