#include "spott_ros/robot_pose.h"

#include <cmath>

#include <gtest/gtest.h>
#include <tf2/exceptions.h>

#include "spott_ros/pose_conversions.h"

namespace spott_ros {
namespace {

void Put(tf2::BufferCore& tf, const char* parent, const char* child, double x, double y, double yaw,
         double t) {
  ASSERT_TRUE(
      tf.setTransform(ToTransform(MakePose2D(x, y, yaw), parent, child, ros::Time(t)), "test"));
}

const RobotFrames kFrames{"map", "odom", "base_link"};

// The localization published map -> odom last at 1.2 s (future-dated by 0.2 s) and fell silent;
// the odometry went on to 5 s, 2 m further along odom's x.
class SilentLocalization : public ::testing::Test {
 protected:
  void SetUp() override {
    Put(tf_, "map", "odom", 1.0, 2.0, M_PI / 2, 1.2);
    for (int i = 0; i <= 8; ++i) Put(tf_, "odom", "base_link", 0.25 * i, 0.0, 0.0, 1.0 + 0.5 * i);
  }
  tf2::BufferCore tf_;
};

TEST_F(SilentLocalization, OneLookupAtTimeZeroFreezesWhereTheRobotWas) {
  // What every node did before: the chain's latest common time is map -> odom's stamp.
  const auto t = tf_.lookupTransform("map", "base_link", ros::Time(0));
  EXPECT_NEAR(t.header.stamp.toSec(), 1.2, 1e-9);
  EXPECT_NEAR(t.transform.translation.y, 2.0 + 0.1, 1e-6);
}

TEST_F(SilentLocalization, TheRobotPoseFollowsTheOdometryOnTheLastMapToOdom) {
  const RobotPose r = LookupRobotPose(tf_, kFrames);
  // odom's x is map's y (odom turned 90 deg): 2 m along it from (1, 2).
  EXPECT_NEAR(r.pose.x, 1.0, 1e-6);
  EXPECT_NEAR(r.pose.y, 4.0, 1e-6);
  EXPECT_NEAR(r.pose.theta, M_PI / 2, 1e-6);
  EXPECT_NEAR(r.stamp.toSec(), 5.0, 1e-9);
  EXPECT_NEAR(r.map_to_odom_age_s, 3.8, 1e-6);
  ASSERT_TRUE(r.odom);  // the odometry the pose was composed with
  EXPECT_NEAR(r.odom->x, 2.0, 1e-6);
  EXPECT_NEAR(r.odom->y, 0.0, 1e-6);
}

TEST(RobotPose, AFutureDatedMapToOdomHasNoAge) {
  tf2::BufferCore tf;
  Put(tf, "odom", "base_link", 0.5, 0.0, 0.0, 3.0);
  Put(tf, "map", "odom", 0.0, 0.0, 0.0, 3.2);
  const RobotPose r = LookupRobotPose(tf, kFrames);
  EXPECT_NEAR(r.pose.x, 0.5, 1e-9);
  EXPECT_LE(r.map_to_odom_age_s, 0.0);
}

TEST(RobotPose, WithoutAnOdomFrameTheMapToBaseIsReadDirectly) {
  tf2::BufferCore tf;
  Put(tf, "map", "base_link", 3.0, -1.0, 0.2, 2.0);
  for (const RobotFrames& f : {kFrames, RobotFrames{"map", "", "base_link"}}) {
    const RobotPose r = LookupRobotPose(tf, f);
    EXPECT_NEAR(r.pose.x, 3.0, 1e-9);
    EXPECT_NEAR(r.pose.theta, 0.2, 1e-9);
    EXPECT_EQ(r.map_to_odom_age_s, 0.0);
    EXPECT_FALSE(r.odom);
  }
}

TEST(RobotPose, NoLocalizationYetThrows) {
  tf2::BufferCore tf;
  Put(tf, "odom", "base_link", 0.5, 0.0, 0.0, 3.0);
  EXPECT_THROW(LookupRobotPose(tf, kFrames), tf2::TransformException);
}

}  // namespace
}  // namespace spott_ros
