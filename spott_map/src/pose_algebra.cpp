#include "spott_map/pose_algebra.h"

#include <cmath>

namespace spott_map {

Pose2 MapToOdom(const Pose2& m, const Pose2& o) {
  const double yaw = std::remainder(m.yaw - o.yaw, 2.0 * M_PI);
  const double c = std::cos(yaw), s = std::sin(yaw);
  return Pose2{m.x - (c * o.x - s * o.y), m.y - (s * o.x + c * o.y), yaw};
}

Pose2 Compose(const Pose2& a, const Pose2& b) {
  const double c = std::cos(a.yaw), s = std::sin(a.yaw);
  return Pose2{a.x + c * b.x - s * b.y, a.y + s * b.x + c * b.y,
               std::remainder(a.yaw + b.yaw, 2.0 * M_PI)};
}

}  // namespace spott_map
