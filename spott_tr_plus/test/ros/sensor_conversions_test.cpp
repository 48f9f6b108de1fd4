// The TR+ controller's sensor messages at its edge (spott_tr_plus/ros/sensor_conversions.h).
#include "spott_tr_plus/ros/sensor_conversions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace spott_tr_plus {
namespace {

namespace conv = ros_conversions;

spott_msgs::RangeRing TwoSonars() {
  spott_msgs::RangeRing r;
  r.min_range = 0.15f;
  r.max_range = 6.5f;
  r.field_of_view = 0.52f;
  r.mounts.resize(2);
  r.mounts[0].x = 0.2;
  r.mounts[1].theta = M_PI / 2;
  r.ranges = {1.5f, 7.0f};
  return r;
}

TEST(SensorConversions, ARingKeepsItsReadingsAndDropsTheImpossibleOnes) {
  std::string problem;
  int discarded = 0;
  const auto ring = conv::RingFromMsg(TwoSonars(), &problem, &discarded);
  ASSERT_TRUE(ring) << problem;
  EXPECT_EQ(discarded, 1);  // 7 m beyond a 6.5 m sonar
  EXPECT_DOUBLE_EQ(ring->ranges[0], 1.5);
  EXPECT_TRUE(std::isnan(ring->ranges[1]));
  EXPECT_DOUBLE_EQ(ring->mounts[0].x, 0.2);
  EXPECT_NEAR(ring->mounts[1].yaw, M_PI / 2, 1e-12);
  EXPECT_FLOAT_EQ(static_cast<float>(ring->max_range_m), 6.5f);
  spott_msgs::RangeRing blind = TwoSonars();
  blind.max_range = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE(conv::RingFromMsg(blind, &problem, &discarded));
  EXPECT_EQ(problem.rfind("max_range: ", 0), 0u) << problem;
}

TEST(SensorConversions, OnlyPressedSegmentsWithAnAngleCount) {
  spott_msgs::BumperRing b;
  b.pressed = {true, false, true, true};
  b.segment_angles = {0.5f, 1.0f, std::numeric_limits<float>::infinity()};  // one short
  EXPECT_EQ(conv::PressedAngles(b), (std::vector<double>{0.5}));
}

TEST(SensorConversions, AProfileKeepsTheEchoesInItsHeightBand) {
  spott_msgs::RangeProfile p;
  p.max_range = 4.0f;
  p.points.resize(4);
  p.ranges = {1.0f, 4.0f, 1.0f, 1.0f};
  p.points[0].x = 1.0;                                       // an echo ahead
  p.points[1].x = 4.0;                                       // no echo (max range)
  p.points[2].x = 1.0, p.points[2].z = -0.98;                // the floor
  p.points[3].x = std::numeric_limits<double>::quiet_NaN();  // not finite
  geometry_msgs::Transform head;
  head.translation.x = 0.1;
  head.translation.z = 1.0;
  head.rotation.z = std::sin(M_PI / 4);  // turned 90 degrees left
  head.rotation.w = std::cos(M_PI / 4);
  controller::Vec2 origin;
  const auto points = conv::ProfilePoints(p, head, 0.05, 2.0, &origin);
  ASSERT_TRUE(points);
  ASSERT_EQ(points->size(), 1u);
  EXPECT_NEAR((*points)[0].x(), 0.1, 1e-12);
  EXPECT_NEAR((*points)[0].y(), 1.0, 1e-12);
  EXPECT_NEAR(origin.x(), 0.1, 1e-12);
  head.rotation.w = head.rotation.z = 0.0;  // no rotation at all
  EXPECT_FALSE(conv::ProfilePoints(p, head, 0.05, 2.0, &origin));
  head.rotation.w = 1.0;
  head.translation.y = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(conv::ProfilePoints(p, head, 0.05, 2.0, &origin));
}

// For recognition every sample stays, in its order: echoes by their range, a sample without a
// finite point as "no echo" at NaN, in 3-D in the base frame.
TEST(SensorConversions, AProfileForRecognitionKeepsEverySampleInOrder) {
  spott_msgs::RangeProfile p;
  p.max_range = 4.0f;
  p.orientation = spott_msgs::RangeProfile::VERTICAL;
  p.points.resize(4);
  p.ranges = {1.0f, 4.0f, 1.0f};                             // one range short
  p.points[0].x = 1.0, p.points[0].z = 0.2;                  // an echo ahead, above
  p.points[1].x = 4.0;                                       // no echo (max range)
  p.points[2].x = std::numeric_limits<double>::quiet_NaN();  // not finite
  p.points[3].x = 2.0;                                       // no range: no echo
  geometry_msgs::Transform head;
  head.translation.x = 0.1;
  head.translation.z = 0.85;
  head.rotation.z = std::sin(M_PI / 4);  // turned 90 degrees left
  head.rotation.w = std::cos(M_PI / 4);
  controller::Vec3 origin;
  const auto samples = conv::ProfileSamples(p, head, &origin);
  ASSERT_TRUE(samples);
  ASSERT_EQ(samples->size(), 4u);
  EXPECT_TRUE((*samples)[0].echo);
  EXPECT_NEAR((*samples)[0].point.x(), 0.1, 1e-12);
  EXPECT_NEAR((*samples)[0].point.y(), 1.0, 1e-12);
  EXPECT_NEAR((*samples)[0].point.z(), 1.05, 1e-6);  // Point32: float
  EXPECT_FALSE((*samples)[1].echo);
  EXPECT_FALSE((*samples)[2].echo);
  EXPECT_FALSE((*samples)[2].point.allFinite());
  EXPECT_FALSE((*samples)[3].echo);
  EXPECT_NEAR(origin.z(), 0.85, 1e-12);
  head.rotation.w = head.rotation.z = 0.0;  // no rotation at all
  EXPECT_FALSE(conv::ProfileSamples(p, head, &origin));
}

}  // namespace
}  // namespace spott_tr_plus
