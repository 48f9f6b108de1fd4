// The node's parameters (config/harmonic_planner.yaml), read through spott_ros's reader: wrong
// types, values out of range and unknown keys stop the node, each named. The robot's radius is
// not a parameter: it comes from the robot description (spott_ros::FootprintRadiusFromParameter).
#pragma once

#include <string>
#include <vector>

#include "spott_harmonic_planner/local_planner.h"
#include "spott_harmonic_planner/navigate_session.h"
#include "spott_ros/parameter_reader.h"

namespace spott_harmonic_planner {

struct NodeParameters {
  PlannerParameters planner;  ///< window.robot_radius_m is set from the robot description.
  NavigateSessionParameters navigate;
  std::string frame_id = "map";
  /// The pose is map -> odom composed with odom -> base (spott_ros/robot_pose.h); empty: map
  /// -> base directly.
  std::string odom_frame = "odom";
  std::string base_frame = "base_link";  ///< Also the URDF link whose footprint pads obstacles.
  std::string robot_description = "robot_description";  ///< Parameter holding the URDF.
  /// The localization's estimates, one per update (geometry_msgs/PoseWithCovarianceStamped,
  /// AMCL's amcl_pose); "": none (arrivals are not judged again, navigate/settle_timeout_s).
  std::string localization_topic = "amcl_pose";
  /// Its status (spott_msgs/LocalizationStatus): no arrival while it says lost
  /// (navigate/lost_timeout_s); "": none (AMCL has no such topic).
  std::string localization_status_topic = "localization_status";
  double cycle_rate_hz = 20.0;         ///< [0.01, 1000]
  int visualization_every = 5;         ///< Cycles between potential/contour/path messages, >= 1.
  double heading_tolerance_rad = 0.1;  ///< Default final heading tolerance (rad), (0, pi].
  double contact_memory_s = 60.0;      ///< Bumper contacts kept as obstacles (s), > 0.
  double contact_size_m = 0.1;         ///< Their diameter (m), > 0.
  /// Back off a bumper contact itself while navigating. stack.launch sets it false when the TR+
  /// controller runs: its reflex (BUMPER_CHECK, SPOTT Fig. 7) takes the wheels and moves the robot
  /// away, and two back-offs of one contact would fight. Contacts are remembered either way.
  bool bumper_backoff = true;
};

/// Reads every key of config/harmonic_planner.yaml (defaults where unset) and records every
/// violation in `r` by its key.
void ReadParameters(spott_ros::ParameterReader& r, NodeParameters& p);

}  // namespace spott_harmonic_planner
