// The simulator's parameters as configuration rows (section, key, bounds; util/param_table.h):
// the physics step, the drive, every sensor model and the charger's pads. Defaults live in each
// struct; the episode's configuration takes these rows over as they are.
#pragma once

#include "sim/charger_detector.h"
#include "sim/charger_pads.h"
#include "sim/imu.h"
#include "sim/lidar.h"
#include "sim/localization.h"
#include "sim/odometry.h"
#include "sim/physics_world.h"
#include "sim/sensor_suite.h"
#include "sim/wheel_drive.h"
#include "util/param_table.h"

namespace plantsim::sim {

using util::kMaxParameter;

const util::ParamRows<StepSettings>& step_param_rows();                ///< "step"
const util::ParamRows<DriveParams>& drive_param_rows();                ///< "drive"
const util::ParamRows<OdometryNoise>& odometry_param_rows();           ///< "odometry"
const util::ParamRows<LocalizationParams>& localization_param_rows();  ///< "localization"
const util::ParamRows<DetectionParams>& detection_param_rows();        ///< "detection"
const util::ParamRows<LidarParams>& lidar_param_rows();                ///< "lidar"
const util::ParamRows<ImuParams>& imu_param_rows();                    ///< "imu"
const util::ParamRows<BeaconParams>& beacon_param_rows();              ///< "beacon"
/// "tolerance": what the pads accept as docked (their travel and width come from the plant).
const util::ParamRows<ChargerPadParams>& tolerance_param_rows();

}  // namespace plantsim::sim
