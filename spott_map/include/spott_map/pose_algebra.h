// REP-105's correction map -> odom: where the odometry's frame lies in the map, such that
// (map -> odom) * odom = the robot's pose in the map. One definition for the localization (what
// it publishes), the simulator (its ground-truth map -> odom) and the TR+ controller (whether the
// estimate jumped).
#pragma once

#include "spott_map/world.h"

namespace spott_map {

/// map -> odom such that Compose(MapToOdom(map_pose, odom_pose), odom_pose) = map_pose; its yaw
/// in [-pi, pi].
Pose2 MapToOdom(const Pose2& map_pose, const Pose2& odom_pose);
/// a * b: the pose b, given in a's frame, in a's parent frame (e.g. (map -> odom) * odom = the
/// robot in the map); yaw in [-pi, pi].
Pose2 Compose(const Pose2& a, const Pose2& b);

}  // namespace spott_map
