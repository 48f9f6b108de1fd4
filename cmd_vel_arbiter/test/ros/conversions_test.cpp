#include "cmd_vel_arbiter/ros/conversions.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace cmd_vel_arbiter::ros_conversions {
namespace {

TEST(Conversions, TwistKeepsThePlanarComponentsAndSaysWhatItDrops) {
  geometry_msgs::Twist t;
  t.linear.x = 0.3;
  t.angular.z = -0.2;
  bool ignored = true;
  const Velocity v = FromTwist(t, &ignored);
  EXPECT_FALSE(ignored);
  EXPECT_DOUBLE_EQ(v.linear_mps, 0.3);
  EXPECT_DOUBLE_EQ(v.angular_rps, -0.2);
  t.linear.y = 0.1;
  FromTwist(t, &ignored);
  EXPECT_TRUE(ignored);
  const geometry_msgs::Twist back = ToTwist(v);
  EXPECT_DOUBLE_EQ(back.linear.x, 0.3);
  EXPECT_DOUBLE_EQ(back.angular.z, -0.2);
}

TEST(Conversions, PressedAnglesOfABumperRing) {
  spott_msgs::BumperRing r;
  r.segment_angles = {0.0f, 1.0f, 2.0f};
  r.pressed = {false, true, true};
  std::string error;
  const auto a = PressedAngles(r, &error);
  ASSERT_TRUE(a) << error;
  ASSERT_EQ(a->size(), 2u);
  EXPECT_FLOAT_EQ((*a)[0], 1.0f);
  r.pressed.pop_back();
  EXPECT_FALSE(PressedAngles(r, &error));
  EXPECT_NE(error.find("2 pressed flags but 3"), std::string::npos);
  r.pressed = {true, false, false};
  r.segment_angles[0] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE(PressedAngles(r, &error));
}

TEST(Conversions, StatusStatesMatchTheMessageConstants) {
  EXPECT_EQ(static_cast<int>(SourceState::kIdle), spott_msgs::ArbiterSource::IDLE);
  EXPECT_EQ(static_cast<int>(SourceState::kDriving), spott_msgs::ArbiterSource::DRIVING);
  EXPECT_EQ(static_cast<int>(SourceState::kPreempted), spott_msgs::ArbiterSource::PREEMPTED);
  EXPECT_EQ(static_cast<int>(SourceState::kTimedOut), spott_msgs::ArbiterSource::TIMED_OUT);
  ArbiterParameters p;
  p.sources = {{"a", 1, 0.5}, {"b", 2, 0.5}};
  Arbiter arb(p);
  std::string why;
  arb.Command("a", Velocity{0.1, 0}, 0.0, &why);
  const auto s = ToStatus(arb, ros::Time(1));
  EXPECT_EQ(s.driver, "a");
  ASSERT_EQ(s.sources.size(), 2u);
  EXPECT_EQ(s.sources[0].name, "b");  // by priority, highest first
  EXPECT_EQ(s.sources[1].state, spott_msgs::ArbiterSource::DRIVING);
}

TEST(Conversions, ARangeRingGivesTheClearanceBoundsOrIsRefusedNamingTheField) {
  spott_msgs::RangeRing r;
  r.field_of_view = 0.436f;
  r.min_range = 0.15f;
  r.max_range = 5.0f;
  for (int i = 0; i < 4; ++i) {  // front, left, back, right on a 0.25 m body
    geometry_msgs::Pose2D m;
    m.theta = i * M_PI / 2;
    m.x = 0.25 * std::cos(m.theta);
    m.y = 0.25 * std::sin(m.theta);
    r.mounts.push_back(m);
  }
  r.ranges = {0.5f, 5.0f, std::numeric_limits<float>::quiet_NaN(), 5.0f};
  const ClearanceParameters p;
  std::string error;
  const auto b = RingBounds(r, p, &error);
  ASSERT_TRUE(b) << error;
  EXPECT_NEAR(b->forward_gap_m, 0.5, 1e-6);  // the front echo, from the body's front
  EXPECT_EQ(b->backward_gap_m, std::numeric_limits<double>::infinity());  // NaN: dropped out
  EXPECT_NEAR(b->forward_mps, StoppingSpeed(0.5, p), 1e-6);
  r.ranges.pop_back();
  EXPECT_FALSE(RingBounds(r, p, &error));
  EXPECT_NE(error.find("3 ranges but 4 mounts"), std::string::npos) << error;
  r.ranges.push_back(5.0f);
  r.mounts[1].theta = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(RingBounds(r, p, &error));
  EXPECT_NE(error.find("mounts[1]"), std::string::npos) << error;
  r.mounts[1].theta = M_PI / 2;
  r.field_of_view = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE(RingBounds(r, p, &error));
}

TEST(Conversions, ALaserScanGivesTheClearanceBoundsOrIsRefusedNamingTheField) {
  sensor_msgs::LaserScan scan;  // three rays at -10, 0, +10 degrees from a laser 0.1 m ahead
  scan.angle_min = -0.1745f;
  scan.angle_increment = 0.1745f;
  scan.range_min = 0.02f;
  scan.range_max = 25.0f;
  scan.ranges = {30.0f, 0.5f, std::numeric_limits<float>::quiet_NaN()};
  const Transducer mount{0.1, 0.0, 0.0};
  ClearanceParameters p;
  std::string error;
  const auto b = ScanBounds(scan, mount, 0.25, p, &error);
  ASSERT_TRUE(b) << error;
  EXPECT_NEAR(b->forward_gap_m, 0.1 + 0.5 - 0.25, 1e-6);  // only the ray at 0 degrees echoes
  const auto refused = [&](sensor_msgs::LaserScan s, const Transducer& m, double radius,
                           const std::string& field) {
    std::string why;
    EXPECT_FALSE(ScanBounds(s, m, radius, p, &why)) << field;
    EXPECT_NE(why.find(field), std::string::npos) << why;
  };
  sensor_msgs::LaserScan bad = scan;
  bad.angle_min = std::numeric_limits<float>::infinity();
  refused(bad, mount, 0.25, "angle_min");
  bad = scan;
  bad.angle_increment = 0.0f;
  refused(bad, mount, 0.25, "angle_increment is 0");
  bad = scan;
  bad.range_min = 30.0f;
  refused(bad, mount, 0.25, "range_min");
  refused(scan, Transducer{std::nan(""), 0.0, 0.0}, 0.25, "tf");
  refused(scan, mount, 0.0, "radius");
  p.footprint_radius_m = 0.3;  // the parameter stands for an unknown robot description
  EXPECT_TRUE(ScanBounds(scan, mount, 0.0, p, &error)) << error;
}

TEST(Conversions, TheDriverMarkerSaysWhoDrivesOverTheRobot) {
  spott_msgs::ArbiterStatus s;
  s.header.stamp = ros::Time(5.0);
  auto m = ToDriverMarker(s, "base_link");
  EXPECT_EQ(m.header.frame_id, "base_link");
  EXPECT_EQ(m.type, visualization_msgs::Marker::TEXT_VIEW_FACING);
  EXPECT_EQ(m.text, "wheels: nobody");
  s.driver = "reflex";
  s.exclusive_holder = "reflex";
  s.bumper_stop = true;
  s.limits_reason = "office: slow";
  m = ToDriverMarker(s, "b21/base_link");
  EXPECT_EQ(m.header.frame_id, "b21/base_link");
  EXPECT_EQ(m.text, "wheels: reflex (held by reflex); bumper stop; limits: office: slow");
  EXPECT_GT(m.color.r, m.color.g);  // red on a bumper stop
}

}  // namespace
}  // namespace cmd_vel_arbiter::ros_conversions
