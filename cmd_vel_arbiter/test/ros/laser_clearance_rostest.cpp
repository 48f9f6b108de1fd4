// The laser in the clearance cap, node and simulator together (laser_clearance.test): driven at
// the wall with no ring to cap it, the robot stops before touching it on the ground truth. The
// glue under test: the scanner's pose from tf, the radius from the robot description.
#include <geometry_msgs/Twist.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <spott_msgs/BumperRing.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>

namespace {

constexpr double kWallFaceX = 0.075;  // hilare_room's west wall: 0.15 m thick about x = 0
constexpr double kRadius = 0.4;       // robot_sim/urdf/hilare.urdf's collision cylinder

struct Truth {
  std::mutex mutex;
  double x = 0.0, v = 0.0;
  bool seen = false;
  void On(const nav_msgs::Odometry& m) {
    std::lock_guard<std::mutex> lock(mutex);
    x = m.pose.pose.position.x;
    v = std::hypot(m.twist.twist.linear.x, m.twist.twist.linear.y);
    seen = true;
  }
};

bool AnyPressed(const spott_msgs::BumperRing& ring) {
  return std::any_of(ring.pressed.begin(), ring.pressed.end(), [](bool p) { return p; });
}

TEST(LaserClearance, TheLaserAloneStopsTheRobotBeforeTheWall) {
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(2);
  spinner.start();
  ASSERT_TRUE(ros::Time::waitForValid(ros::WallDuration(30.0)));
  Truth truth;
  std::atomic<int> bumps{0}, touches{0};
  ros::Subscriber truth_sub = nh.subscribe("/sim/ground_truth", 10, &Truth::On, &truth);
  ros::Subscriber bumper = nh.subscribe<spott_msgs::BumperRing>(
      "/bumper", 10, [&](const spott_msgs::BumperRing::ConstPtr& m) { bumps += AnyPressed(*m); });
  ros::Subscriber contact = nh.subscribe<spott_msgs::BumperRing>(
      "/sim/contact", 10,
      [&](const spott_msgs::BumperRing::ConstPtr& m) { touches += AnyPressed(*m); });
  ros::Publisher planner = nh.advertise<geometry_msgs::Twist>("cmd_vel/planner", 10);
  const ros::WallTime ready = ros::WallTime::now() + ros::WallDuration(30.0);
  while ((planner.getNumSubscribers() == 0 || !truth.seen) && ros::WallTime::now() < ready)
    ros::WallDuration(0.05).sleep();
  ASSERT_GT(planner.getNumSubscribers(), 0u);
  // Let the arbiter hear the laser (tf and the first scans) before driving.
  ros::Duration(1.0).sleep();
  double start_x = 0.0;
  {
    std::lock_guard<std::mutex> lock(truth.mutex);
    start_x = truth.x;
  }

  // 0.3 m/s for 10 s would cover 3 m; the wall is 1.5 m ahead of the centre.
  geometry_msgs::Twist ahead;
  ahead.linear.x = 0.3;
  const ros::Time end = ros::Time::now() + ros::Duration(10.0);
  while (ros::ok() && ros::Time::now() < end) {
    planner.publish(ahead);
    ros::Duration(0.1).sleep();
  }
  std::lock_guard<std::mutex> lock(truth.mutex);
  EXPECT_EQ(bumps.load(), 0) << "the bumper was pressed";
  EXPECT_EQ(touches.load(), 0) << "the body touched the wall (ground truth)";
  EXPECT_LT(truth.v, 0.03) << "still moving at x = " << truth.x;
  // It drove up to the wall and the cap, not a stall, stopped it: the body within 0.3 m of the
  // wall's face (stop_margin_m 0.05 and the braking's slack), most of the 1.1 m covered.
  const double gap = truth.x - kRadius - kWallFaceX;
  EXPECT_GT(gap, 0.0) << "x = " << truth.x;
  EXPECT_LT(gap, 0.3) << "x = " << truth.x;
  EXPECT_GT(start_x - truth.x, 0.8) << "from " << start_x << " to " << truth.x;
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "laser_clearance_rostest");
  return RUN_ALL_TESTS();
}
