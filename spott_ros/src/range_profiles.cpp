#include "spott_ros/range_profiles.h"

namespace spott_ros {

std::optional<Eigen::Isometry3d> HeadPose(const geometry_msgs::Transform& head) {
  const auto& q = head.rotation;
  const Eigen::Quaterniond rotation(q.w, q.x, q.y, q.z);
  const Eigen::Vector3d from(head.translation.x, head.translation.y, head.translation.z);
  if (!from.allFinite() || !rotation.coeffs().allFinite() || rotation.norm() < 1e-6)
    return std::nullopt;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = rotation.normalized().toRotationMatrix();
  pose.translation() = from;
  return pose;
}

std::optional<std::vector<Eigen::Vector2d>> ProfileEchoes(const spott_msgs::RangeProfile& msg,
                                                          const geometry_msgs::Transform& head,
                                                          double min_height_m, double max_height_m,
                                                          Eigen::Vector3d* origin) {
  const auto pose = HeadPose(head);
  if (!pose) return std::nullopt;
  *origin = pose->translation();
  std::vector<Eigen::Vector2d> points;
  points.reserve(msg.points.size());
  for (std::size_t i = 0; i < msg.points.size(); ++i) {
    if (!(i < msg.ranges.size() && msg.ranges[i] < msg.max_range - 1e-3)) continue;  // no echo
    const Eigen::Vector3d p =
        *pose * Eigen::Vector3d(msg.points[i].x, msg.points[i].y, msg.points[i].z);
    if (p.allFinite() && p.z() >= min_height_m && p.z() <= max_height_m)
      points.emplace_back(p.x(), p.y());
  }
  return points;
}

}  // namespace spott_ros
