// fixed_pose: broadcasts a fixed robot pose as the static transform parent -> child, for running
// the global planner without localization or a simulator (demonstrations, screenshots). Debian's
// tf2_ros has no static_transform_publisher.
//   rosrun spott_global_planner fixed_pose _x:=1.1 _y:=1.1 _yaw:=0
// Parameters: ~x, ~y (m), ~yaw (rad), ~parent_frame (map), ~child_frame (base_link).
#include <cmath>

#include <ros/ros.h>
#include <tf2_ros/static_transform_broadcaster.h>

int main(int argc, char** argv) {
  ros::init(argc, argv, "fixed_pose");
  ros::NodeHandle pnh("~");
  double x = 0.0, y = 0.0, yaw = 0.0;
  std::string parent = "map", child = "base_link";
  pnh.param("x", x, x);
  pnh.param("y", y, y);
  pnh.param("yaw", yaw, yaw);
  pnh.param("parent_frame", parent, parent);
  pnh.param("child_frame", child, child);
  if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(yaw) || parent.empty() ||
      child.empty()) {
    ROS_FATAL("fixed_pose: ~x, ~y, ~yaw must be finite and the frames non-empty");
    return 1;
  }
  tf2_ros::StaticTransformBroadcaster broadcaster;
  geometry_msgs::TransformStamped t;
  t.header.stamp = ros::Time::now();
  t.header.frame_id = parent;
  t.child_frame_id = child;
  t.transform.translation.x = x;
  t.transform.translation.y = y;
  t.transform.rotation.z = std::sin(0.5 * yaw);
  t.transform.rotation.w = std::cos(0.5 * yaw);
  broadcaster.sendTransform(t);
  ROS_INFO("fixed_pose: %s -> %s at (%.2f, %.2f, %.2f rad)", parent.c_str(), child.c_str(), x, y,
           yaw);
  ros::spin();
  return 0;
}
