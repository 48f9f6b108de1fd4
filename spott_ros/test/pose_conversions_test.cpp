#include "spott_ros/pose_conversions.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace spott_ros {
namespace {

TEST(PoseConversions, YawRoundTripsThroughTheQuaternion) {
  for (double yaw : {0.0, 0.3, -1.2, M_PI / 2, 3.0, -3.0}) {
    const auto back = YawOf(YawToQuaternion(yaw));
    ASSERT_TRUE(back);
    EXPECT_NEAR(*back, yaw, 1e-12);
  }
}

TEST(PoseConversions, YawOfAnUnnormalizedQuaternion) {
  geometry_msgs::Quaternion q = YawToQuaternion(0.7);
  q.z *= 3;
  q.w *= 3;
  EXPECT_NEAR(*YawOf(q), 0.7, 1e-12);
}

TEST(PoseConversions, ZeroOrNonFiniteQuaternionsHaveNoYaw) {
  geometry_msgs::Quaternion zero;
  zero.w = 0;
  EXPECT_FALSE(YawOf(zero));
  geometry_msgs::Quaternion nan = YawToQuaternion(0.1);
  nan.z = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(YawOf(nan));
}

TEST(PoseConversions, TransformPlacesTheChildAtThePose) {
  const auto t = ToTransform(MakePose2D(1, 2, 0.5), "map", "odom", ros::Time(3));
  EXPECT_EQ(t.header.frame_id, "map");
  EXPECT_EQ(t.child_frame_id, "odom");
  EXPECT_EQ(t.header.stamp, ros::Time(3));
  const auto p = ToPose2D(t.transform);
  ASSERT_TRUE(p);
  EXPECT_DOUBLE_EQ(p->x, 1);
  EXPECT_DOUBLE_EQ(p->y, 2);
  EXPECT_NEAR(p->theta, 0.5, 1e-12);
}

TEST(PoseConversions, ComposeWithTheInverseIsTheIdentity) {
  const auto a = MakePose2D(1.0, -2.0, 2.5);
  const auto id = Compose(a, Inverse(a));
  EXPECT_NEAR(id.x, 0, 1e-12);
  EXPECT_NEAR(id.y, 0, 1e-12);
  EXPECT_NEAR(id.theta, 0, 1e-12);
  // A quarter turn then one metre ahead ends one metre to the left.
  const auto b = Compose(MakePose2D(0, 0, M_PI / 2), MakePose2D(1, 0, 0));
  EXPECT_NEAR(b.x, 0, 1e-12);
  EXPECT_NEAR(b.y, 1, 1e-12);
}

TEST(PoseConversions, NonFinitePositionsAreRefused) {
  geometry_msgs::Pose p = ToPose(MakePose2D(1, 1, 0));
  p.position.x = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(ToPose2D(p));
}

}  // namespace
}  // namespace spott_ros
