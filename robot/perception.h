// What the controllers, planners and seed methods are allowed to know: a perception built
// only from sensor readings and the robot's map. In mode "sensors" (the default) the pose is
// the EKF's (encoders + gyro, corrected by scans matched to the map), moving and unmapped
// obstacles are the tracker's (scan returns the map does not explain), the potential field
// feels the scan's returns, and the charger detection is carried to the present through the
// odometry. Mode "oracle" keeps the old idealised sensing for comparison.
#pragma once

#include <array>
#include <deque>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "controller/collision_check.h"
#include "controller/potential_field.h"
#include "robot/beam_directions.h"
#include "robot/dock_detector.h"
#include "robot/ekf_localizer.h"
#include "robot/global_match.h"
#include "robot/local_obstacle_layer.h"
#include "robot/map_raycaster.h"
#include "robot/obstacle_tracker.h"
#include "robot/particle_localizer.h"
#include "robot/pose_estimator.h"
#include "robot/readings.h"
#include "robot/scan_matcher.h"
#include "util/param_spec.h"

namespace plantsim::robot {

enum class PerceptionMode { kSensors, kOracle };
std::string_view to_string(PerceptionMode m);

struct PerceptionParams {
  PerceptionMode mode = PerceptionMode::kSensors;
  double range_m = 4.0;        ///< oracle mode: moving obstacles closer than this are known exactly
  double field_range_m = 3.0;  ///< scan returns closer than this reach the potential field
  double field_cluster_gap_m = 0.3;  ///< returns closer than this form one obstacle for the field
  double target_exclusion_m = 0.6;   ///< returns this close to the beacon's target are the target
  /// The pose estimator by its registry name (estimator_registry.h) and a plugin's parameters
  /// (the built-ins read theirs, typed, below).
  std::string estimator = "ekf";
  util::NamedValues estimator_params;
  /// The dock detector by its registry name (dock_detector.h) and its parameters.
  std::string dock_detector = "camera";
  util::NamedValues dock_detector_params;
  EkfParams ekf;  ///< the EKF's, and the odometry's noise and health thresholds both use
  ParticleParams particles;
  TrackerParams tracker;
  ObstacleLayerParams layer;
  double moving_speed_mps = 0.3;  ///< tracks faster than this do not mark the layer (they move on)
  /// A return lies off the map when it is farther from every mapped surface than the tracker's
  /// margin or this many of the range noise the estimator uses (ekf.range_sigma_m, or more when
  /// it learnt more), whichever is more: a noisier lidar must not turn its own scatter into
  /// obstacles that move.
  double explained_sigmas = 3.0;
  /// The robot holds still this long at the start (sensors mode), so that the gyro's bias is
  /// measured at rest before it has to carry the heading across open ground.
  double gyro_calibration_s = 1.0;
  double displaced_jump_m =
      0.05;  ///< one scan moving the estimate this far means the wheels missed a motion
  double slip_jump_m = 0.02;      ///< ... this far, that the wheels slipped
  double slip_turn_radps = 0.15;  ///< encoders' turn rate this far from the gyro's, on average over
                                  ///< slip_window_s: the wheels slip (single readings are noise)
  double slip_window_s = 0.5;
  double relocalize_sigma_m =
      0.3;                   ///< a displacement widens the estimate by this, so scans can catch it
  GlobalMatchParams global;  ///< finding the robot again by a global scan match
};

struct Perception {
  double t_s = 0;
  double dt_s = 0;
  geom::Pose2 pose;             ///< estimated, map frame
  double position_sigma_m = 0;  ///< 1-sigma of the estimate (largest direction); 0 in oracle mode
  double yaw_sigma_rad = 0;
  LocalizationHealth health = LocalizationHealth::kOk;
  geom::Pose2 odom_pose;  ///< continuous odometry frame
  double speed_mps = 0;
  double yaw_rate_radps = 0;  ///< the gyro's reading
  bool charger_contact = false;
  bool charging = false;
  BumperReading bumper;
  bool displaced =
      false;  ///< moved without its wheels (the scan disagrees, a contact): stop and settle
  bool slipping =
      false;  ///< the wheels turned otherwise than the robot moved (encoders vs gyro and scan)
  std::optional<geom::Pose2> charger_in_robot;   ///< docked pose seen, carried to now (robot frame)
  std::vector<controller::MovingBox> obstacles;  ///< tracked (or, oracle, known) obstacles off the
                                                 ///< map, and the layer's cells (standing)
  std::vector<geom::Rect> layer;  ///< the local obstacle layer's occupied cells, merged
  std::vector<controller::FieldObstacle> field;  ///< what the potential field feels
  std::optional<geom::Vec2> target;              ///< a moving target's centre (map frame)
  geom::Vec2 target_velocity;
  std::optional<LidarScan>
      scan;  ///< the newest scan as read (sensor frame), for outside controllers
  std::array<double, 9> pose_covariance{};  ///< the estimate's (x, y, yaw) covariance, row-major;
                                            ///< zeros in oracle mode
  /// How far the footprint can drive straight ahead before it meets a lidar return (m): the
  /// newest scan's free range (free_range.h) less what odometry drove since it was taken;
  /// +inf with no scan yet (nothing seen to stop for). The traction governor's stopping bound.
  double free_ahead_m = std::numeric_limits<double>::infinity();
};

/// The last scan as perception interpreted it, for figures.
struct ScanView {
  geom::Pose2 pose;                                ///< estimated pose it was placed with
  std::vector<geom::Vec2> explained, unexplained;  ///< returns, map frame
};

class Perceiver {
 public:
  /// `map` is the plant as the robot knows it.
  Perceiver(const worlds::World& map, const PerceptionParams& params);
  const Perception& update(const SensorReadings& readings);
  const Perception& current() const { return now_; }
  const ScanView& last_scan() const { return scan_view_; }
  const ObstacleTracker& tracker() const { return tracker_; }
  /// Times the estimate was restarted (or reseeded) from a global scan match.
  int relocalizations() const { return estimator_->relocalizations(); }
  const PoseEstimator& estimator() const { return *estimator_; }

 private:
  /// The stages of update, in order.
  void take_readings(const SensorReadings& r);
  /// The free range ahead (free_range.h) of the newest scan, carried to now.
  void see_free_range(const SensorReadings& r);
  const Perception& update_oracle(const SensorReadings& r);
  /// The estimator's prediction and correction, and what they say: displaced, slipping.
  void localize(const SensorReadings& r);
  /// The encoders' turn against the gyro's over the slip window (odometry noise averaged out).
  bool turn_slipped(const SensorReadings& r);
  void publish_estimate();
  /// The beacon's fixes, smoothed; the velocity from their change (alpha-beta, as the tracker).
  void follow_target(const SensorReadings& r);
  void publish_obstacles(const SensorReadings& r);
  void interpret_scan(const LidarScan& scan);
  std::optional<geom::Pose2> carry_to_now(const ChargerDetection& d) const;
  /// The dock detector's sighting this period, if any.
  std::optional<ChargerDetection> sight_dock(const SensorReadings& r);
  const worlds::World& map_;
  PerceptionParams p_;
  MapRaycaster raycaster_;
  std::unique_ptr<PoseEstimator> estimator_;
  std::unique_ptr<DockDetector> dock_detector_;
  ObstacleTracker tracker_;
  LocalObstacleLayer layer_;
  Perception now_;
  ScanView scan_view_;
  std::vector<controller::FieldObstacle> static_field_;  // from the last scan
  std::vector<geom::Rect> layer_rects_;                  // the layer after the last scan
  BeamDirections directions_;                            // scratch for interpret_scan
  // interpret_scan's lists, emptied and refilled each scan (not allocated afresh: the scan's
  // lists grew from nothing ten times a scan).
  std::vector<geom::Vec2> unexplained_, near_static_, marks_;
  std::deque<std::pair<double, geom::Pose2>> odom_history_;  // for detections that arrive late
  std::optional<geom::Vec2> last_target_;
  bool touched_before_ = false;  // the bumper at the last reading
  double odom_yaw_before_ = 0;   // for the encoders' turn rate
  double free_at_scan_m_ = std::numeric_limits<double>::infinity();  // the newest scan's
  std::deque<std::pair<double, double>>
      turn_gap_;  // (dt, encoders' turn minus the gyro's) over the slip window
  double turn_gap_sum_ = 0, turn_gap_time_ = 0;
};

}  // namespace plantsim::robot
