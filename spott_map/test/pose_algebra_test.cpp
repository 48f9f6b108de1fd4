#include "spott_map/pose_algebra.h"

#include <gtest/gtest.h>

#include <cmath>

namespace spott_map {
namespace {

TEST(PoseAlgebra, MapToOdomPutsTheOdometryOnTheMapPose) {
  const Pose2 map_pose{3.0, -2.0, 2.5}, odom_pose{1.0, 4.0, -2.0};
  const Pose2 m = MapToOdom(map_pose, odom_pose);
  // map->odom composed with odom->base must give map->base, worked out by hand.
  const double c = std::cos(m.yaw), s = std::sin(m.yaw);
  EXPECT_NEAR(m.x + c * odom_pose.x - s * odom_pose.y, map_pose.x, 1e-12);
  EXPECT_NEAR(m.y + s * odom_pose.x + c * odom_pose.y, map_pose.y, 1e-12);
  EXPECT_NEAR(std::remainder(m.yaw + odom_pose.yaw - map_pose.yaw, 2 * M_PI), 0.0, 1e-12);
  EXPECT_LE(std::abs(m.yaw), M_PI);  // 4.5 rad wrapped
  const Pose2 back = Compose(m, odom_pose);
  EXPECT_NEAR(back.x, map_pose.x, 1e-12);
  EXPECT_NEAR(back.y, map_pose.y, 1e-12);
  EXPECT_NEAR(back.yaw, map_pose.yaw, 1e-12);
}

TEST(PoseAlgebra, ComposeTurnsAndShiftsByTheFirstPose) {
  const Pose2 p = Compose(Pose2{1.0, 2.0, M_PI / 2}, Pose2{1.0, 0.0, 3.0});
  EXPECT_NEAR(p.x, 1.0, 1e-12);  // 1 m along the first pose's heading (+y)
  EXPECT_NEAR(p.y, 3.0, 1e-12);
  EXPECT_NEAR(p.yaw, M_PI / 2 + 3.0 - 2 * M_PI, 1e-12);  // wrapped into [-pi, pi]
}

}  // namespace
}  // namespace spott_map
