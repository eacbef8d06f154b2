// A plugin's components guarded so that whatever they throw, at construction or at any call,
// reaches the episode as util::ComponentFailure naming the plugin's file and the component: the
// episode ends with `plugin_error` and the batch goes on. Built-ins are never guarded.
#pragma once

#include "controller/local_controller.h"
#include "planner/registry.h"
#include "robot/dock_detector.h"
#include "robot/estimator_registry.h"

namespace plantsim::plugins {

/// The entry with its factory and everything it makes guarded; `origin` is the plugin's file.
controller::LocalControllerEntry guarded(controller::LocalControllerEntry e,
                                         const std::string& origin);
robot::EstimatorEntry guarded(robot::EstimatorEntry e, const std::string& origin);
planner::PlannerEntry guarded(planner::PlannerEntry e, const std::string& origin);
robot::DockDetectorEntry guarded(robot::DockDetectorEntry e, const std::string& origin);

}  // namespace plantsim::plugins
