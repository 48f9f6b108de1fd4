#include "spott_ros/robot_pose.h"

#include <tf2/exceptions.h>

#include "spott_ros/pose_conversions.h"

namespace spott_ros {
namespace {

geometry_msgs::Pose2D Planar(const geometry_msgs::TransformStamped& t) {
  const auto p = ToPose2D(t.transform);
  if (!p)
    throw tf2::TransformException(t.header.frame_id + " -> " + t.child_frame_id +
                                  " is not a planar pose");
  return *p;
}

RobotPose Direct(const tf2::BufferCore& tf, const RobotFrames& f) {
  const auto t = tf.lookupTransform(f.map, f.base, ros::Time(0));
  return RobotPose{Planar(t), t.header.stamp, 0.0, std::nullopt};
}

}  // namespace

RobotPose LookupRobotPose(const tf2::BufferCore& tf, const RobotFrames& f) {
  if (f.odom.empty() || f.odom == f.map || f.odom == f.base) return Direct(tf, f);
  geometry_msgs::TransformStamped map_odom, odom_base;
  try {
    map_odom = tf.lookupTransform(f.map, f.odom, ros::Time(0));
    odom_base = tf.lookupTransform(f.odom, f.base, ros::Time(0));
  } catch (const tf2::TransformException&) {
    return Direct(tf, f);  // odom is not between them; or nothing is there: Direct says which
  }
  RobotPose r;
  r.odom = Planar(odom_base);
  r.pose = Compose(Planar(map_odom), *r.odom);
  r.stamp = odom_base.header.stamp;
  r.map_to_odom_age_s = (odom_base.header.stamp - map_odom.header.stamp).toSec();
  return r;
}

}  // namespace spott_ros
