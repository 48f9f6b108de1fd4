// The navigation part of the main demo: the robot is sent through the running stack
// (global_planner -> harmonic_planner -> robot_sim) to named places of the world, one leg after
// the other, and each leg is measured against the simulator's ground truth.
#pragma once

#include <string>
#include <vector>

#include <ros/ros.h>
#include <spott_msgs/NavigateGoal.h>

#include "spott_map/world.h"

namespace spott_launch {

struct NavigationLeg {
  std::string goal;  ///< Place name from the world file (RunNavigation).
  /// RunTasks: the task command sent to /task, what the TR+ controller made of it, the TR+
  /// rules that fired in order, its outcome and the features it had added to the map.
  std::string task;
  std::string interpretation;
  std::vector<std::string> trace;
  std::string task_outcome;  ///< "reached", "failed: ...", "rejected: ...", "timed out ..."
  std::vector<std::string> features_added;  ///< During this leg.
  bool has_target = true;                   ///< RunTasks: the task had a goal point (`target`).
  spott_map::Pose2 target;                  ///< (m, rad) in the map frame.
  /// "reached" only when Navigate succeeded, the robot really is within the goal tolerance of
  /// the target (ground truth) and no bumper was pressed; else "not reached: <why>".
  std::string outcome;
  std::string navigate_outcome;  ///< What Navigate said: "succeeded", "unreachable: ..." ...
  bool reached = false;
  std::string global_path;  ///< Rooms and doors of the global plan, "hall_w -> d_lab_w -> lab".
  std::vector<std::string> recoveries;  ///< RECOVERING episodes, each with its note.
  double start_sim_s = 0.0;             ///< Simulated time the leg began (s since the clock's 0).
  double sim_time_s = 0.0;              ///< Simulated time the leg took (s).
  double wall_time_s = 0.0;             ///< Wall time the leg took (s).
  double path_length_m = 0.0;           ///< Distance the robot really drove (ground truth, m).
  double final_error_m = 0.0;           ///< Ground-truth distance from the target at the end (m).
  spott_map::Vec2 final_position{0.0, 0.0};  ///< Ground truth at the end (m, map).
  double min_wall_distance_m = 0.0;  ///< Closest approach of the robot's centre to a wall or
                                     ///< object of the simulated world (m).
  int bumper_hits = 0;               ///< Bumper messages with a pressed segment.
  /// Localization (markov_localization's status against the ground truth); 0 estimates when
  /// the stack runs on the simulator's map->odom.
  int estimates = 0;
  double mean_position_error_m = 0.0;
  double max_position_error_m = 0.0;
  double mean_heading_error_rad = 0.0;
  double max_heading_error_rad = 0.0;
  int lost_reports = 0;  ///< Statuses that said lost.
};

struct NavigationReport {
  bool by_task = false;                     ///< RunTasks (else RunNavigation).
  bool ran = false;                         ///< The navigation stack was up and took goals.
  std::string skipped;                      ///< Why not, when !ran.
  double requested_real_time_factor = 0.0;  ///< The simulator's ~real_time_factor (0 = unknown).
  std::vector<NavigationLeg> legs;
};

/// Sends the robot to each place of `goals` (names of places in `world`) through the stack's
/// one entry, harmonic_planner/navigate (which hands the target to the global planner and waits
/// for the robot's pose itself); each leg may take `leg_timeout_s` of simulated time and is
/// judged on /sim/ground_truth and /bumper from robot_sim with `goal_tolerance_m`.
NavigationReport RunNavigation(ros::NodeHandle& nh, const spott_map::World& world,
                               const std::vector<std::string>& goals, double leg_timeout_s,
                               double connect_timeout_s, double goal_tolerance_m);

/// Gives the TR+ controller each command of `tasks` on /task (spott_msgs/Task), one after the
/// other, each within `leg_timeout_s` of simulated time, and judges each leg on
/// /sim/ground_truth and /bumper: "reached" only when the controller reports reached, the robot
/// really is in the command's goal region (interpreted on the world's CAD map from where the
/// robot really started) or within `goal_tolerance_m` of the goal point the controller sent to
/// Navigate, and no bumper was pressed. Recoveries and the global path come from Navigate's
/// feedback.
NavigationReport RunTasks(ros::NodeHandle& nh, const spott_map::World& world,
                          const std::vector<std::string>& tasks, double leg_timeout_s,
                          double connect_timeout_s, double goal_tolerance_m);

/// "SPOTT[2], INTERPRET_TASK[1], MAP_OBJECTS_WITH_SONAR[1] x3, ...": the trace's rules by
/// program and index, repeats in a row counted.
std::string CompactTrace(const std::vector<std::string>& trace);

/// A Navigate goal to `target` (map frame) at NORMAL speed, without direction bias, with
/// `tolerance_m` (0 = the planner's default) and the planner's default heading tolerance.
spott_msgs::NavigateGoal NavigateGoalTo(const spott_map::Pose2& target, bool ignore_heading,
                                        double tolerance_m = 0.0);

/// The navigation section of the report ("" when no leg was asked for).
std::string FormatNavigation(const NavigationReport& report);

/// Closest distance from `p` to a wall or an object footprint of `world` (m).
double DistanceToNearestSolid(const spott_map::World& world, const spott_map::Vec2& p);

}  // namespace spott_launch
