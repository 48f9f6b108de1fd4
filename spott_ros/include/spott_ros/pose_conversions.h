// Planar poses between the forms ROS carries them in: yaw <-> quaternion, Pose2D <-> Pose,
// PoseStamped and TransformStamped. Every node uses these instead of writing sin(yaw / 2) by hand.
#pragma once

#include <optional>
#include <string>

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/Pose2D.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/Quaternion.h>
#include <geometry_msgs/Transform.h>
#include <geometry_msgs/TransformStamped.h>
#include <ros/time.h>

namespace spott_ros {

/// A rotation of `yaw` (rad) about +z.
geometry_msgs::Quaternion YawToQuaternion(double yaw);
/// The yaw (rad, in (-pi, pi]) of `q`, which need not be normalized; nullopt when `q` is not
/// finite or has (almost) zero norm. Roll and pitch are ignored (planar robots).
std::optional<double> YawOf(const geometry_msgs::Quaternion& q);

geometry_msgs::Pose ToPose(const geometry_msgs::Pose2D& p);
geometry_msgs::PoseStamped ToPoseStamped(const geometry_msgs::Pose2D& p,
                                         const std::string& frame_id, const ros::Time& stamp);
/// nullopt when a number is not finite or the orientation has no yaw (see YawOf).
std::optional<geometry_msgs::Pose2D> ToPose2D(const geometry_msgs::Pose& p);
std::optional<geometry_msgs::Pose2D> ToPose2D(const geometry_msgs::Transform& t);

/// `frame_id` -> `child_frame_id` placing the child at `p` in the parent.
geometry_msgs::TransformStamped ToTransform(const geometry_msgs::Pose2D& p,
                                            const std::string& frame_id,
                                            const std::string& child_frame_id,
                                            const ros::Time& stamp);

/// a * b of planar poses (b expressed in a's frame).
geometry_msgs::Pose2D Compose(const geometry_msgs::Pose2D& a, const geometry_msgs::Pose2D& b);
geometry_msgs::Pose2D Inverse(const geometry_msgs::Pose2D& p);

geometry_msgs::Pose2D MakePose2D(double x, double y, double theta);

}  // namespace spott_ros
