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
  std::string goal;         ///< Place name from the world file.
  spott_map::Pose2 target;  ///< (m, rad) in the map frame.
  std::string outcome;      ///< "reached", "unreachable: ...", "failed: ...", "timed out ..."
  bool reached = false;
  std::string global_path;     ///< Rooms and doors of the global plan, "hall_w -> d_lab_w -> lab".
  double sim_time_s = 0.0;     ///< Simulated time the leg took (s).
  double path_length_m = 0.0;  ///< Distance the robot really drove (ground truth, m).
  double final_error_m = 0.0;  ///< Ground-truth distance from the target at the end (m).
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
  bool ran = false;     ///< The navigation stack was up and took goals.
  std::string skipped;  ///< Why not, when !ran.
  std::vector<NavigationLeg> legs;
};

/// Sends the robot to each place of `goals` (names of places in `world`) through
/// harmonic_planner/navigate with the place as global_goal of the global planner; each leg may
/// take `leg_timeout_s` of simulated time. Needs /sim/ground_truth and /bumper from robot_sim.
NavigationReport RunNavigation(ros::NodeHandle& nh, const spott_map::World& world,
                               const std::vector<std::string>& goals, double leg_timeout_s,
                               double connect_timeout_s);

/// A Navigate goal to `target` (map frame) at NORMAL speed, without direction bias, with the
/// planner's default tolerances.
spott_msgs::NavigateGoal NavigateGoalTo(const spott_map::Pose2& target, bool ignore_heading);

/// The navigation section of the report ("" when no leg was asked for).
std::string FormatNavigation(const NavigationReport& report);

/// Closest distance from `p` to a wall or an object footprint of `world` (m).
double DistanceToNearestSolid(const spott_map::World& world, const spott_map::Vec2& p);

}  // namespace spott_launch
