// The global_planner node's parameters (config/global_planner.yaml), read through spott_ros's
// reader: wrong types, values out of range and unknown keys are refused, each named. The
// robot's radius is not a parameter: the node takes it from the robot description.
#pragma once

#include <string>
#include <vector>

#include "spott_global_planner/planning_session.h"
#include "spott_ros/parameter_reader.h"

namespace spott_global_planner::ros_parameters {

struct NodeParameters {
  std::string frame_id = "map";  ///< frame of the graph, goals and outputs
  std::string odom_frame =
      "odom";  ///< Empty: frame_id -> robot_frame directly (spott_ros/robot_pose.h).
  std::string robot_frame = "base_link";  ///< pose = tf frame_id -> robot_frame; its URDF link
  std::string robot_description = "robot_description";  ///< parameter holding the URDF
  double update_rate_hz = 5.0;                          ///< [0.01, 100]
  bool follow_local_window = true;                      ///< use the window received on local_window
  /// Passage padding = robot radius (robot description) + this (m), >= 0.
  double max_localization_error_m = 0.075;
  GlobalPlannerParameters core;  ///< core.passage.padding_m is set by the node
};

/// Fills `p` (missing keys keep their defaults) and records every violation in `r`, each named
/// ("~window/window_size_m must be > 0 (got -1)").
void ReadParameters(spott_ros::ParameterReader& r, NodeParameters& p);

/// The core's checks once the padding is known.
void ValidateCore(spott_ros::ParameterReader& r, const NodeParameters& p);

}  // namespace spott_global_planner::ros_parameters
