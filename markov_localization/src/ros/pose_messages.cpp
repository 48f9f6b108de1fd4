#include "markov_localization/ros/pose_messages.h"

#include "spott_ros/pose_conversions.h"

namespace markov_localization::ros_conversions {

using spott_map::Pose2;

std::optional<Pose2> PoseOf(const geometry_msgs::Pose& pose) {
  const auto p = spott_ros::ToPose2D(pose);
  if (!p) return std::nullopt;
  return Pose2{p->x, p->y, p->theta};
}

std::optional<Pose2> InitialPoseOf(const geometry_msgs::PoseWithCovarianceStamped& msg,
                                   const std::string& map_frame, std::string* field,
                                   std::string* why) {
  const auto pose = PoseOf(msg.pose.pose);
  if (!pose) {
    *field = "pose.pose";
    *why = "not finite or no yaw in the quaternion";
    return std::nullopt;
  }
  if (!msg.header.frame_id.empty() && msg.header.frame_id != map_frame) {
    *field = "header.frame_id";
    *why = "'" + msg.header.frame_id + "' is not '" + map_frame + "'";
    return std::nullopt;
  }
  return pose;
}

}  // namespace markov_localization::ros_conversions
