#include "spott_ros/pose_conversions.h"

#include <cmath>

namespace spott_ros {

geometry_msgs::Quaternion YawToQuaternion(double yaw) {
  geometry_msgs::Quaternion q;
  q.z = std::sin(yaw / 2.0);
  q.w = std::cos(yaw / 2.0);
  return q;
}

std::optional<double> YawOf(const geometry_msgs::Quaternion& q) {
  const double n = q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w;
  if (!std::isfinite(n) || n < 1e-12) return std::nullopt;
  // atan2 of the rotated x axis: correct for unnormalized quaternions too (both terms scale).
  return std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 * n - 2.0 * (q.y * q.y + q.z * q.z));
}

geometry_msgs::Pose ToPose(const geometry_msgs::Pose2D& p) {
  geometry_msgs::Pose pose;
  pose.position.x = p.x;
  pose.position.y = p.y;
  pose.orientation = YawToQuaternion(p.theta);
  return pose;
}

geometry_msgs::PoseStamped ToPoseStamped(const geometry_msgs::Pose2D& p,
                                         const std::string& frame_id, const ros::Time& stamp) {
  geometry_msgs::PoseStamped s;
  s.header.frame_id = frame_id;
  s.header.stamp = stamp;
  s.pose = ToPose(p);
  return s;
}

std::optional<geometry_msgs::Pose2D> ToPose2D(const geometry_msgs::Pose& p) {
  const std::optional<double> yaw = YawOf(p.orientation);
  if (!yaw || !std::isfinite(p.position.x) || !std::isfinite(p.position.y)) return std::nullopt;
  return MakePose2D(p.position.x, p.position.y, *yaw);
}

std::optional<geometry_msgs::Pose2D> ToPose2D(const geometry_msgs::Transform& t) {
  const std::optional<double> yaw = YawOf(t.rotation);
  if (!yaw || !std::isfinite(t.translation.x) || !std::isfinite(t.translation.y))
    return std::nullopt;
  return MakePose2D(t.translation.x, t.translation.y, *yaw);
}

geometry_msgs::TransformStamped ToTransform(const geometry_msgs::Pose2D& p,
                                            const std::string& frame_id,
                                            const std::string& child_frame_id,
                                            const ros::Time& stamp) {
  geometry_msgs::TransformStamped t;
  t.header.frame_id = frame_id;
  t.header.stamp = stamp;
  t.child_frame_id = child_frame_id;
  t.transform.translation.x = p.x;
  t.transform.translation.y = p.y;
  t.transform.rotation = YawToQuaternion(p.theta);
  return t;
}

geometry_msgs::Pose2D Compose(const geometry_msgs::Pose2D& a, const geometry_msgs::Pose2D& b) {
  const double c = std::cos(a.theta), s = std::sin(a.theta);
  return MakePose2D(a.x + c * b.x - s * b.y, a.y + s * b.x + c * b.y,
                    std::remainder(a.theta + b.theta, 2.0 * M_PI));
}

geometry_msgs::Pose2D Inverse(const geometry_msgs::Pose2D& p) {
  const double c = std::cos(p.theta), s = std::sin(p.theta);
  return MakePose2D(-(c * p.x + s * p.y), s * p.x - c * p.y, std::remainder(-p.theta, 2.0 * M_PI));
}

geometry_msgs::Pose2D MakePose2D(double x, double y, double theta) {
  geometry_msgs::Pose2D p;
  p.x = x;
  p.y = y;
  p.theta = theta;
  return p;
}

}  // namespace spott_ros
