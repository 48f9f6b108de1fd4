// The navigation part of the main demo: the robot is sent through the running stack
// (global_planner -> harmonic_planner -> robot_sim) to named places of the world, one leg after
// the other, and each leg is measured against the simulator's ground truth.
#pragma once

#include <string>
#include <vector>

#include <ros/ros.h>
#include <spott_msgs/NavigateGoal.h>

#include "spott_launch/leg_metrics.h"
#include "spott_map/world.h"

namespace spott_launch {

/// Sends the robot to each place of `goals` (names of places in `world`) through the stack's
/// one entry, harmonic_planner/navigate (which hands the target to the global planner and waits
/// for the robot's pose itself); each leg may take `leg_timeout_s` of simulated time and is
/// judged on /sim/ground_truth and /bumper from robot_sim with `goal_tolerance_m`.
NavigationReport RunNavigation(ros::NodeHandle& nh, const spott_map::World& world,
                               const std::vector<std::string>& goals, double leg_timeout_s,
                               double connect_timeout_s, double goal_tolerance_m,
                               bool estimate_from_tf = false);

/// Gives the TR+ controller each command of `tasks` on /task (spott_msgs/Task), one after the
/// other, each within `leg_timeout_s` of simulated time, and judges each leg on
/// /sim/ground_truth and /bumper: "reached" only when the controller reports reached, the robot
/// really is in the command's goal region (interpreted on the world's CAD map from where the
/// robot really started) or within `goal_tolerance_m` of the goal point the controller sent to
/// Navigate, and no bumper was pressed. Recoveries and the global path come from Navigate's
/// feedback.
NavigationReport RunTasks(ros::NodeHandle& nh, const spott_map::World& world,
                          const std::vector<std::string>& tasks, double leg_timeout_s,
                          double connect_timeout_s, double goal_tolerance_m,
                          bool estimate_from_tf = false);

/// Gives rpl_executive each of `missions` on /mission (spott_msgs/Mission: a shipped RPL plan or
/// Noreils-Chatila mission), one after the other, each within `leg_timeout_s` of simulated time.
/// A leg is "reached" when the executive's outcome, the monitors that fired and its message are
/// what the scenario says, the robot really ended at the mission's goal (when it gives one)
/// within `goal_tolerance_m`, and no bumper was pressed and the body touched nothing.
NavigationReport RunMissions(ros::NodeHandle& nh, const spott_map::World& world,
                             const std::vector<MissionSpec>& missions, double leg_timeout_s,
                             double connect_timeout_s, double goal_tolerance_m,
                             bool estimate_from_tf = false);

/// `estimate_from_tf` (each of the three): the stack publishes no localization_status (truth or
/// dead reckoning); the legs' localization error is tf's map -> base_link, sampled at 5 Hz.

/// "SPOTT[2], INTERPRET_TASK[1], MAP_OBJECTS_WITH_SONAR[1] x3, ...": the trace's rules by
/// program and index, repeats in a row counted.
std::string CompactTrace(const std::vector<std::string>& trace);

/// A Navigate goal to `target` (map frame) at NORMAL speed, without direction bias, with
/// `tolerance_m` (0 = the planner's default) and the planner's default heading tolerance.
spott_msgs::NavigateGoal NavigateGoalTo(const spott_map::Pose2& target, bool ignore_heading,
                                        double tolerance_m = 0.0);

/// The navigation section of the report ("" when no leg was asked for).
std::string FormatNavigation(const NavigationReport& report);

}  // namespace spott_launch
