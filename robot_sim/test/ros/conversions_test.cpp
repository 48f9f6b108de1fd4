#include <gtest/gtest.h>

#include <cmath>

#include "robot_sim/range_sensors.h"
#include "robot_sim/ros/conversions.h"

namespace robot_sim {
namespace {

namespace conv = ros_conversions;

RangeRingSpec TwoSonars() {
  RangeRingSpec ring;
  ring.name = "sonar";
  ring.max_range = 6.5;
  ring.min_range = 0.43;
  ring.mounts = {{"sonar_1", 0.2, 0.0, 0.6, 0.0}, {"sonar_2", 0.0, 0.2, 0.6, M_PI / 2}};
  return ring;
}

TEST(ConversionsTest, RangeRingKeepsMountsFramesAndDropouts) {
  const auto msg = conv::ToRangeRing(TwoSonars(), {1.5, NAN}, "base_link", ros::Time(3.0));
  EXPECT_EQ(msg.header.frame_id, "base_link");
  EXPECT_EQ(msg.radiation_type, spott_msgs::RangeRing::ULTRASOUND);
  ASSERT_EQ(msg.ranges.size(), 2u);
  EXPECT_FLOAT_EQ(msg.ranges[0], 1.5f);
  EXPECT_TRUE(std::isnan(msg.ranges[1]));
  EXPECT_EQ(msg.frame_ids[1], "sonar_2");
  EXPECT_DOUBLE_EQ(msg.mounts[1].theta, M_PI / 2);
}

// The sensors ride on the Nomad's turret (PlaceMount): with the turret turned the mounts the
// stack reads in base_link turn with it, or every echo lands in the wrong place.
TEST(ConversionsTest, RangeRingMountsTurnWithTheTurret) {
  const auto msg =
      conv::ToRangeRing(TwoSonars(), {1.5, 2.0}, "base_link", ros::Time(3.0), M_PI / 2);
  ASSERT_EQ(msg.mounts.size(), 2u);
  const robot_sim::TransducerPose placed =
      robot_sim::PlaceMount(TwoSonars().mounts[1], {0.0, 0.0, 0.0}, M_PI / 2);
  EXPECT_NEAR(msg.mounts[1].x, placed.origin.x(), 1e-9);
  EXPECT_NEAR(msg.mounts[1].y, placed.origin.y(), 1e-9);
  EXPECT_NEAR(msg.mounts[1].theta, placed.yaw, 1e-9);
  EXPECT_NEAR(msg.mounts[0].x, 0.0, 1e-9);
  EXPECT_NEAR(msg.mounts[0].y, 0.2, 1e-9);
  EXPECT_NEAR(msg.mounts[0].theta, M_PI / 2, 1e-9);
}

TEST(ConversionsTest, RangeWithoutEchoIsInfinityPerRep117) {
  const auto ring = TwoSonars();
  EXPECT_TRUE(std::isinf(conv::ToRange(ring, 0, 6.5, ros::Time(1)).range));
  const auto r = conv::ToRange(ring, 1, 2.0, ros::Time(1));
  EXPECT_FLOAT_EQ(r.range, 2.0f);
  EXPECT_EQ(r.header.frame_id, "sonar_2");
}

TEST(ConversionsTest, BumperSegmentsAreCentredEvery18Degrees) {
  BumperSpec b;
  std::vector<bool> pressed(20, false);
  pressed[5] = true;
  const auto msg = conv::ToBumperRing(b, pressed, "base_link", ros::Time(1));
  ASSERT_EQ(msg.segment_angles.size(), 20u);
  EXPECT_NEAR(msg.segment_angles[5], M_PI / 2, 1e-6);
  EXPECT_NEAR(msg.segment_width, M_PI / 10, 1e-6);
  EXPECT_TRUE(msg.pressed[5]);
}

TEST(ConversionsTest, BatteryStateCarriesAFractionAndADischargeCurrent) {
  BatteryParameters p;
  p.capacity_wh = 100.0;
  p.initial_percent = 40.0;
  p.idle_power_w = 24.0;
  p.full_voltage_v = 26.0;
  p.empty_voltage_v = 22.0;
  const Battery b(p);  // drawing its idle 24 W
  const auto msg = conv::ToBatteryState(b, "base_link", ros::Time(2.0));
  EXPECT_NEAR(msg.percentage, 0.4, 1e-6);  // [0, 1], not percent
  EXPECT_NEAR(msg.voltage, 22.0 + 0.4 * 4.0, 1e-4);
  EXPECT_LT(msg.current, 0.0f);  // discharging
  EXPECT_NEAR(msg.current, -24.0 / msg.voltage, 1e-4);
  EXPECT_NEAR(msg.capacity, 100.0 / 24.0, 1e-5);
  EXPECT_EQ(msg.power_supply_status, sensor_msgs::BatteryState::POWER_SUPPLY_STATUS_DISCHARGING);
  EXPECT_TRUE(msg.present);
  EXPECT_EQ(msg.header.frame_id, "base_link");
}

TEST(ConversionsTest, OdometryCarriesPoseAndTwist) {
  const auto msg =
      conv::ToOdometry({1, 2, M_PI / 2}, {0.3, 0.1}, "odom", "base_link", ros::Time(1));
  EXPECT_DOUBLE_EQ(msg.pose.pose.position.y, 2);
  EXPECT_NEAR(msg.pose.pose.orientation.z, std::sqrt(0.5), 1e-12);
  EXPECT_DOUBLE_EQ(msg.twist.twist.linear.x, 0.3);
}

TEST(ConversionsTest, BadServiceRequestsAreRefused) {
  FaultEvent e;
  std::string error;
  spott_msgs::SetDoorState::Request door;
  door.door_id = "d1";
  door.state = 0;  // UNKNOWN: the simulated building always knows
  EXPECT_FALSE(conv::FromRequest(door, e, &error));
  door.state = 2;
  ASSERT_TRUE(conv::FromRequest(door, e, &error));
  EXPECT_TRUE(e.closed);
  spott_msgs::SensorFault::Request fault;
  fault.fault = 9;
  EXPECT_FALSE(conv::FromRequest(fault, e, &error));
  spott_msgs::AddObstacle::Request add;
  add.kind = "piano";
  EXPECT_FALSE(conv::FromRequest(add, e, &error));
  EXPECT_NE(error.find("piano"), std::string::npos);
}

TEST(ConversionsTest, VoxelMarkersGroupLeavesBySize) {
  const auto m = conv::ToVoxelMarkers({{Eigen::Vector3d(0, 0, 0.1), 0.05},
                                       {Eigen::Vector3d(1, 0, 0.1), 0.05},
                                       {Eigen::Vector3d(2, 0, 0.2), 0.1}},
                                      "map", ros::Time(1));
  ASSERT_EQ(m.markers.size(), 3u);  // DELETEALL + two sizes
  EXPECT_EQ(m.markers[1].points.size(), 2u);
  EXPECT_DOUBLE_EQ(m.markers[2].scale.x, 0.1);
}

TEST(ConversionsTest, BumperMarkersShowThePressedSegmentsOnTheShell) {
  BumperSpec b;  // 20 segments, 18 degrees apart
  std::vector<bool> pressed(20, false);
  pressed[5] = true;  // 90 degrees: the robot's left
  auto msg = conv::ToBumperMarkers(b, 0.2285, pressed, "base_link", ros::Time(1));
  ASSERT_EQ(msg.markers.size(), 1u);
  const auto& m = msg.markers[0];
  EXPECT_EQ(m.header.frame_id, "base_link");
  EXPECT_EQ(m.action, visualization_msgs::Marker::ADD);
  ASSERT_EQ(m.points.size(), 1u);
  EXPECT_NEAR(m.points[0].x, 0.0, 1e-9);
  EXPECT_NEAR(m.points[0].y, 0.2285, 1e-9);
  msg = conv::ToBumperMarkers(b, 0.2285, std::vector<bool>(20, false), "base_link", ros::Time(2));
  EXPECT_EQ(msg.markers[0].action, visualization_msgs::Marker::DELETEALL);  // none pressed
}

}  // namespace
}  // namespace robot_sim
