// A pan-tilt range sensor's profile (spott_msgs/RangeProfile, QUADRIS) placed in a frame whose z
// is up (the base's, or odometry's): one place for every node that maps or localizes with it.
#pragma once

#include <optional>
#include <vector>

#include <geometry_msgs/Transform.h>
#include <spott_msgs/RangeProfile.h>
#include <Eigen/Geometry>

namespace spott_ros {

/// The head's pose as a rigid transform (the quaternion normalized); nullopt when a translation
/// or a quaternion's component is not finite or the quaternion is zero.
std::optional<Eigen::Isometry3d> HeadPose(const geometry_msgs::Transform& head);

/// The profile's echoes placed by `head` (the head's pose in the target frame), in scan order:
/// samples below max_range with a finite point whose height lies in [min_height_m,
/// max_height_m] (a head tilted down sees the floor, which is no obstacle), as (x, y); the
/// head's origin in `*origin`. nullopt when the head's pose is not finite or a zero quaternion.
std::optional<std::vector<Eigen::Vector2d>> ProfileEchoes(const spott_msgs::RangeProfile& msg,
                                                          const geometry_msgs::Transform& head,
                                                          double min_height_m, double max_height_m,
                                                          Eigen::Vector3d* origin);

}  // namespace spott_ros
