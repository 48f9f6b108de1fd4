#include "spott_ros/range_profiles.h"

#include <Eigen/Geometry>

namespace spott_ros {

std::optional<std::vector<Eigen::Vector2d>> ProfileEchoes(const spott_msgs::RangeProfile& msg,
                                                          const geometry_msgs::Transform& head,
                                                          double min_height_m, double max_height_m,
                                                          Eigen::Vector3d* origin) {
  const auto& q = head.rotation;
  const Eigen::Quaterniond rotation(q.w, q.x, q.y, q.z);
  const Eigen::Vector3d from(head.translation.x, head.translation.y, head.translation.z);
  if (!from.allFinite() || !rotation.coeffs().allFinite() || rotation.norm() < 1e-6)
    return std::nullopt;
  *origin = from;
  const Eigen::Matrix3d r = rotation.normalized().toRotationMatrix();
  std::vector<Eigen::Vector2d> points;
  points.reserve(msg.points.size());
  for (std::size_t i = 0; i < msg.points.size(); ++i) {
    if (!(i < msg.ranges.size() && msg.ranges[i] < msg.max_range - 1e-3)) continue;  // no echo
    const Eigen::Vector3d p =
        from + r * Eigen::Vector3d(msg.points[i].x, msg.points[i].y, msg.points[i].z);
    if (p.allFinite() && p.z() >= min_height_m && p.z() <= max_height_m)
      points.emplace_back(p.x(), p.y());
  }
  return points;
}

}  // namespace spott_ros
