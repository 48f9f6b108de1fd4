// Conversions between the planner's core types and ROS messages (the only ROS-facing code
// besides the node).
#pragma once

#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Path.h>
#include <ros/time.h>
#include <spott_msgs/NavigateGoal.h>
#include <spott_msgs/PotentialFieldStatus.h>
#include <spott_msgs/SteeringStatus.h>
#include <visualization_msgs/Marker.h>

#include <string>

#include "spott_harmonic_planner/local_planner.h"
#include "spott_harmonic_planner/navigate_session.h"

namespace spott_harmonic_planner::ros_conversions {

/// Decades of p shown by the potential image and the contours: u = 1 - 10^-k, k = 1..12.
constexpr int kDecades = 12;

/// The potential as an image for rviz: obstacles (and cells cut off from the goal) 100, the goal
/// 0, free cells 1..99 growing with -log10(p) (p = 1 - u) over kDecades decades, so long
/// corridors stay visible where u itself is 1 to double precision.
nav_msgs::OccupancyGrid ToPotentialImage(const PotentialField& field, const std::string& frame_id,
                                         const ros::Time& stamp);

/// Equipotential contours u = 1 - 10^-k (k = 1..kDecades) by marching squares over the cell
/// centres, as one LINE_LIST (like the paper's figures).
visualization_msgs::Marker ToContours(const PotentialField& field, const std::string& frame_id,
                                      const ros::Time& stamp);

nav_msgs::Path ToPath(const PotentialField::Path& path, const std::string& frame_id,
                      const ros::Time& stamp);

spott_msgs::PotentialFieldStatus ToStatus(const LocalPlanner& planner, double solve_time_s,
                                          const std::string& frame_id, const ros::Time& stamp);

/// The widest position tolerance a Navigate goal may ask for (m).
constexpr double kMaxPositionToleranceM = 10.0;

/// A Navigate goal as a request, with the node's defaults for zero tolerances; nullopt with
/// `error` (naming the field) for a target that is not finite or not in `frame_id`, an unknown
/// speed mode, an orientation without a yaw while the heading counts, or a tolerance that is
/// not finite and >= 0 or wider than kMaxPositionToleranceM (heading: pi).
std::optional<NavigateRequest> FromGoal(const spott_msgs::NavigateGoal& goal,
                                        const std::string& frame_id, double default_tolerance_m,
                                        double default_heading_tolerance_rad, std::string* error);

spott_msgs::SteeringStatus ToSteering(const SteeringCommand& cmd, SpeedMode mode,
                                      double distance_to_goal_m, const std::string& frame_id,
                                      const ros::Time& stamp);

}  // namespace spott_harmonic_planner::ros_conversions
