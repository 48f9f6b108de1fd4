// The robot's pose in the map as a planner or controller must read it from tf: the latest
// map -> odom composed with the latest odom -> base.
//
// Why not one lookup of map -> base at time 0: tf2 answers it at the chain's latest COMMON time.
// When the localization falls silent (killed and respawning, rebuilding its models, starved of
// CPU) its last map -> odom stays in the buffer and that common time freezes at its stamp: the
// lookup keeps returning where the robot was then while it drives on (node_kill.test touched
// the hallway's end wall that way). map -> odom changes slowly (REP-105); the odometry does not.
#pragma once

#include <optional>
#include <string>

#include <geometry_msgs/Pose2D.h>
#include <ros/time.h>
#include <tf2/buffer_core.h>

namespace spott_ros {

/// A map -> odom older than this (s) means the localization is silent: say so (it publishes at
/// the sensors' rate, 5-10 Hz here).
constexpr double kSilentLocalizationS = 1.0;

struct RobotFrames {
  std::string map;   ///< e.g. "map"
  std::string odom;  ///< e.g. "odom"; empty: map -> base looked up directly
  std::string base;  ///< e.g. "base_link"
};

struct RobotPose {
  geometry_msgs::Pose2D pose;  ///< base in the map frame
  ros::Time stamp;             ///< of the odometry part (odom -> base)
  /// How far map -> odom's stamp lags the odometry's (s); <= 0 while the localization publishes
  /// (its transform is future-dated), growing while it is silent: the pose is dead-reckoned.
  double map_to_odom_age_s = 0.0;
  /// The odometry part (odom -> base) the pose was composed with; empty when map -> base was
  /// looked up directly. Whoever compares the pose with odometry uses this one: an odometry
  /// message from a callback queue can be half a second older than tf's.
  std::optional<geometry_msgs::Pose2D> odom;
};

/// Throws tf2::TransformException when a part is missing, and when a transform is not planar
/// (no yaw, non-finite numbers). Falls back to map -> base directly when `odom` is empty or not
/// between them (a localization that publishes map -> base itself).
RobotPose LookupRobotPose(const tf2::BufferCore& tf, const RobotFrames& frames);

}  // namespace spott_ros
