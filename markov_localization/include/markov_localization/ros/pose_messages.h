// The localization nodes' pose messages (odometry, /initialpose) to the core's planar pose,
// refused by field when they cannot be one.
#pragma once

#include <optional>
#include <string>

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>

#include "spott_map/world.h"

namespace markov_localization::ros_conversions {

/// A message's planar pose; nullopt when a number is not finite or the quaternion has no yaw.
std::optional<spott_map::Pose2> PoseOf(const geometry_msgs::Pose& pose);

/// An /initialpose message's pose in `map_frame` (an empty frame_id is taken as it); nullopt
/// with the refusal's field and reason otherwise.
std::optional<spott_map::Pose2> InitialPoseOf(const geometry_msgs::PoseWithCovarianceStamped& msg,
                                              const std::string& map_frame, std::string* field,
                                              std::string* why);

}  // namespace markov_localization::ros_conversions
