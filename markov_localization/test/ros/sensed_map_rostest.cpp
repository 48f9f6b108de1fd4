// sensed_map_localization_node on the simulator (see sensed_map.test): kidnaps across and along
// cim_office's west hallway, and of the heading, judged on the ground truth.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <mutex>

#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <spott_msgs/Kidnap.h>
#include <spott_msgs/LocalizationStatus.h>
#include <spott_msgs/MapFeatureArray.h>

namespace {

struct Listener {
  // The estimate and the ground truth, from now on.
  explicit Listener(ros::NodeHandle& nh)
      : status_sub(nh.subscribe("localization_status", 5, &Listener::OnStatus, this)),
        truth_sub(nh.subscribe("sim/ground_truth", 5, &Listener::OnTruth, this)) {}
  std::mutex mutex;
  spott_msgs::LocalizationStatus status;
  nav_msgs::Odometry truth;
  bool have_status = false, have_truth = false;
  ros::Subscriber status_sub, truth_sub;  // last: their callbacks use the members above
  void OnStatus(const spott_msgs::LocalizationStatus& s) {
    std::lock_guard<std::mutex> lock(mutex);
    status = s;
    have_status = true;
  }
  void OnTruth(const nav_msgs::Odometry& t) {
    std::lock_guard<std::mutex> lock(mutex);
    truth = t;
    have_truth = true;
  }
  // The estimate's heading error (rad); false before both came.
  bool HeadingError(double* error) {
    std::lock_guard<std::mutex> lock(mutex);
    if (!have_status || !have_truth) return false;
    const auto& q = truth.pose.pose.orientation;
    const double yaw =
        std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
    *error = std::remainder(status.estimate.theta - yaw, 2.0 * M_PI);
    return true;
  }
  // The estimate's error along (x) and across (y) the hallway; false before both came.
  bool Error(double* along, double* across) {
    std::lock_guard<std::mutex> lock(mutex);
    if (!have_status || !have_truth) return false;
    *along = status.estimate.x - truth.pose.pose.position.x;
    *across = status.estimate.y - truth.pose.pose.position.y;
    return true;
  }
};

spott_msgs::MapFeature Wall(const std::string& id, double y) {
  spott_msgs::MapFeature f;
  f.id = id;
  f.type = spott_msgs::MapFeature::LINE_SEGMENT;
  f.source = spott_msgs::MapFeature::SOURCE_SENSED;
  f.points.resize(2);
  f.points[0].x = 4.45;  // between the doors at x = 4 and 9
  f.points[1].x = 8.55;
  f.points[0].y = f.points[1].y = y;
  spott_msgs::Attribute a;
  a.key = "sensor";
  a.value = "sonar";
  f.attributes.push_back(a);
  return f;
}

// Waits until the error across the hallway is within `tolerance`; the last errors.
bool WaitAcross(Listener& l, double tolerance, double seconds, double* along, double* across) {
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
  while (ros::ok() && ros::WallTime::now() < end) {
    if (l.Error(along, across) && std::abs(*across) < tolerance) return true;
    ros::WallDuration(0.1).sleep();
  }
  return false;
}

bool Kidnap(double ahead, double left, double turn = 0.0) {
  spott_msgs::Kidnap k;
  k.request.relative = true;
  k.request.pose.x = ahead;
  k.request.pose.y = left;
  k.request.pose.theta = turn;
  return ros::service::waitForService("sim/kidnap", ros::Duration(10)) &&
         ros::service::call("sim/kidnap", k) && k.response.success;
}

TEST(SensedMapLocalizationNode, FindsAKidnapAcrossTheHallwayNotOneAlongIt) {
  ros::NodeHandle nh;
  Listener l(nh);
  // The hallway's wall faces (walls 0.15 m thick on y = 7 and 9.5), as the sonar mapped them.
  auto pub = nh.advertise<spott_msgs::MapFeatureArray>("map_features", 1, true);
  spott_msgs::MapFeatureArray features;
  features.features = {Wall("sonar_1", 7.075), Wall("sonar_2", 9.425)};
  pub.publish(features);
  ros::AsyncSpinner spinner(1);
  spinner.start();

  double along = 0.0, across = 0.0;
  ASSERT_TRUE(WaitAcross(l, 0.03, 30.0, &along, &across)) << "across " << across;
  EXPECT_LT(std::abs(along), 0.03);

  // 0.15 m to the left (north) without the odometry seeing it: the next fixes find it.
  ASSERT_TRUE(Kidnap(0.0, 0.15));
  ros::WallDuration(0.5).sleep();
  ASSERT_TRUE(l.Error(&along, &across));
  EXPECT_NEAR(across, -0.15, 0.03);  // the estimate stayed where the odometry says
  const ros::WallTime kidnapped = ros::WallTime::now();
  ASSERT_TRUE(WaitAcross(l, 0.03, 10.0, &along, &across)) << "not found across: " << across;
  EXPECT_LT(std::abs(along), 0.03) << "moved along the hallway without cause";
  std::printf("kidnap 0.15 m across the hallway found after %.1f s (wall)\n",
              (ros::WallTime::now() - kidnapped).toSec());

  // 0.4 m ahead: the side walls cannot tell; the estimate keeps odometry's place along the
  // hallway (no jump to a wrong wall) and stays right across it.
  ASSERT_TRUE(Kidnap(0.4, 0.0));
  ros::WallDuration(6.0).sleep();  // three fixes
  ASSERT_TRUE(l.Error(&along, &across));
  EXPECT_NEAR(along, -0.4, 0.03);
  EXPECT_LT(std::abs(across), 0.03);
}

TEST(SensedMapLocalizationNode, TurnsBackAKidnapOfItsHeadingOnTheHallwaysWalls) {
  ros::NodeHandle nh;
  Listener l(nh);
  // The QUADRIS heads pointed left and right, level: each profile lies along a hallway wall.
  auto heads = nh.advertise<sensor_msgs::JointState>("range_profile/point_head", 1, true);
  sensor_msgs::JointState point;
  point.name = {"quadris_1_pan_joint", "quadris_1_tilt_joint", "quadris_2_pan_joint",
                "quadris_2_tilt_joint"};
  point.position = {M_PI / 2, 0.0, -M_PI / 2, 0.0};
  heads.publish(point);
  ros::AsyncSpinner spinner(1);
  spinner.start();
  ros::WallDuration(3.0).sleep();

  double error = 1.0;
  ASSERT_TRUE(l.HeadingError(&error));
  EXPECT_LT(std::abs(error), 0.3 * M_PI / 180.0);
  // Turned 3 degrees without the odometry seeing it: the estimate keeps the old heading, then
  // the walls' lines turn it back.
  ASSERT_TRUE(Kidnap(0.0, 0.0, 3.0 * M_PI / 180.0));
  ros::WallDuration(0.5).sleep();
  ASSERT_TRUE(l.HeadingError(&error));
  EXPECT_NEAR(error, -3.0 * M_PI / 180.0, 0.3 * M_PI / 180.0);
  const ros::WallTime kidnapped = ros::WallTime::now();
  const ros::WallTime end = kidnapped + ros::WallDuration(12.0);
  while (ros::ok() && ros::WallTime::now() < end &&
         !(l.HeadingError(&error) && std::abs(error) < 0.3 * M_PI / 180.0)) {
    ros::WallDuration(0.1).sleep();
  }
  EXPECT_LT(std::abs(error), 0.3 * M_PI / 180.0)
      << "heading error " << error * 180.0 / M_PI << " deg";
  std::printf("heading kidnap of 3 deg turned back after %.1f s (wall lattice)\n",
              (ros::WallTime::now() - kidnapped).toSec());
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "sensed_map_rostest");
  return RUN_ALL_TESTS();
}
