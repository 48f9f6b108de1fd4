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

}  // namespace
}  // namespace cmd_vel_arbiter::ros_conversions
