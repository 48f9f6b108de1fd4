// fixed_pose: broadcasts a fixed robot pose as the static transform parent -> child, for running
// the global planner without localization or a simulator (demonstrations, screenshots). Debian's
// tf2_ros has no static_transform_publisher.
//   rosrun spott_global_planner fixed_pose _x_m:=1.1 _y_m:=1.1 _yaw_rad:=0
// Parameters: ~x_m, ~y_m, ~yaw_rad, ~parent_frame (map), ~child_frame (base_link).
#include <cmath>
#include <string>

#include <ros/ros.h>
#include <tf2_ros/static_transform_broadcaster.h>

#include "spott_ros/parameter_reader.h"
#include "spott_ros/pose_conversions.h"

namespace {

struct FixedPose {
  double x_m = 0.0, y_m = 0.0, yaw_rad = 0.0;
  std::string parent_frame = "map", child_frame = "base_link";
};

void Read(spott_ros::ParameterReader& r, FixedPose& p) {
  r.Get("x_m", p.x_m, "m");
  r.Get("y_m", p.y_m, "m");
  r.Get("yaw_rad", p.yaw_rad, "rad");
  r.Get("parent_frame", p.parent_frame);
  r.Get("child_frame", p.child_frame);
  r.Require(std::isfinite(p.x_m), "x_m", "finite", p.x_m);
  r.Require(std::isfinite(p.y_m), "y_m", "finite", p.y_m);
  r.Require(std::isfinite(p.yaw_rad), "yaw_rad", "finite", p.yaw_rad);
  if (p.parent_frame.empty()) r.Fail("parent_frame must not be empty");
  if (p.child_frame.empty()) r.Fail("child_frame must not be empty");
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "fixed_pose");
  ros::NodeHandle pnh("~");
  const auto p = spott_ros::ReadNodeParameters<FixedPose>(pnh, "fixed_pose", Read);
  if (!p) return 1;
  tf2_ros::StaticTransformBroadcaster broadcaster;
  broadcaster.sendTransform(
      spott_ros::ToTransform(spott_ros::MakePose2D(p->x_m, p->y_m, p->yaw_rad), p->parent_frame,
                             p->child_frame, ros::Time::now()));
  ROS_INFO("fixed_pose: %s -> %s at (%.2f, %.2f, %.2f rad)", p->parent_frame.c_str(),
           p->child_frame.c_str(), p->x_m, p->y_m, p->yaw_rad);
  ros::spin();
  return 0;
}
