// The parameters of the package's two nodes, read through spott_ros's reader: wrong types,
// values out of range and unknown keys stop the node, each named. tr_plus_node:
// config/tr_plus_node.yaml; tr_plus_controller: config/tr_plus_controller.yaml.
#pragma once

#include <string>
#include <vector>

#include "spott_ros/parameter_reader.h"
#include "spott_tr_plus/controller/navigation_controller.h"
#include "spott_tr_plus/controller/ptu_control.h"
#include "spott_tr_plus/task_command.h"

namespace spott_tr_plus {

/// tr_plus_node's parameters.
struct NodeParameters {
  std::string program_file;           ///< Required: the .tr file to run at start-up.
  std::string main;                   ///< The program to run; empty: the file's `main`.
  int max_call_depth = 32;            ///< >= 1
  TaskInterpretationParameters task;  ///< ~task/... (task_command.h)
};

/// Fills `p` (missing keys keep their defaults) and records every violation in `r` by its key.
void ReadParameters(spott_ros::ParameterReader& r, NodeParameters& p);

}  // namespace spott_tr_plus

namespace spott_tr_plus::controller {

/// tr_plus_controller's parameters. controller.robot_radius_m comes from the robot description.
struct NodeParameters {
  std::string program_file;  ///< Required: programs/spott_navigation.tr.
  std::string main;          ///< Empty: the file's main program.
  std::string frame_id = "map";
  std::string odom_frame = "odom";  ///< Empty: map -> base directly (spott_ros/robot_pose.h).
  std::string base_frame = "base_link";
  std::string robot_description = "robot_description";
  std::string navigate_action = "harmonic_planner/navigate";
  /// markov_localization's ActiveLocalize, started on Navigate's "not localized"; "" = none.
  std::string active_localize_action = "active_localize";
  std::string arbiter = "cmd_vel_arbiter";
  double tick_rate_hz = 20.0;  ///< Motions, waits, feedback (Hz), [0.01, 200].
  /// No localization status (localization:=truth): the pose is taken as certain.
  bool assume_localized = false;
  std::vector<std::string> pan_joints{"quadris_1_pan_joint", "quadris_2_pan_joint"};
  std::vector<std::string> tilt_joints{"quadris_1_tilt_joint", "quadris_2_tilt_joint"};
  PtuParameters ptu;               ///< CONTROL_THE_PTU's patterns (ptu_control.h).
  double ptu_min_height_m = 0.05;  ///< QUADRIS points lower than this are the floor (m).
  double ptu_max_height_m = 2.0;   ///< ... higher than this, above the robot (m).
  double marker_height_m = 1.4;    ///< The firing rule's text over the robot (m).
  ControllerParameters controller;
};

/// Fills `p` (missing keys keep their defaults) and records every violation in `r` by its key;
/// the node adds the core's ValidateParameters once the robot's radius is known.
void ReadParameters(spott_ros::ParameterReader& r, NodeParameters& p);

}  // namespace spott_tr_plus::controller
