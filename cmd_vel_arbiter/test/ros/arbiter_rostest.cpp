// The real cmd_vel_arbiter node driving the real simulator: who drives is judged on the
// robot's ground-truth motion, not on the arbiter's own status.
#include <geometry_msgs/Twist.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <spott_msgs/ArbiterStatus.h>
#include <spott_msgs/ReleaseWheels.h>
#include <spott_msgs/TakeWheels.h>

#include <cmath>
#include <limits>
#include <mutex>

#include "spott_ros/testing/node_process.h"

namespace {

struct Motion {
  std::mutex mutex;
  double v = 0, w = 0;  // ground-truth speeds
  void On(const nav_msgs::Odometry& m) {
    std::lock_guard<std::mutex> lock(mutex);
    v = std::hypot(m.twist.twist.linear.x, m.twist.twist.linear.y);
    w = m.twist.twist.angular.z;
  }
  std::pair<double, double> Get() {
    std::lock_guard<std::mutex> lock(mutex);
    return {v, w};
  }
};

geometry_msgs::Twist Twist(double v, double w) {
  geometry_msgs::Twist t;
  t.linear.x = v;
  t.angular.z = w;
  return t;
}

// Sends `cmd` on `pub` at 10 Hz for `seconds` of simulated time.
void SendFor(ros::Publisher& pub, const geometry_msgs::Twist& cmd, double seconds) {
  const ros::Time end = ros::Time::now() + ros::Duration(seconds);
  while (ros::ok() && ros::Time::now() < end) {
    pub.publish(cmd);
    ros::Duration(0.1).sleep();
  }
}

const spott_msgs::ArbiterSource* Source(const spott_msgs::ArbiterStatus& s,
                                        const std::string& name) {
  for (const auto& src : s.sources)
    if (src.name == name) return &src;
  return nullptr;
}

TEST(ArbiterNode, PrioritiesTakeReleaseTimeoutAndRefusalOnTheRealRobot) {
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(2);
  spinner.start();
  ASSERT_TRUE(ros::Time::waitForValid(ros::WallDuration(30.0)));
  Motion motion;
  ros::Subscriber truth = nh.subscribe("/sim/ground_truth", 10, &Motion::On, &motion);
  std::mutex status_mutex;
  spott_msgs::ArbiterStatus status;
  ros::Subscriber status_sub = nh.subscribe<spott_msgs::ArbiterStatus>(
      "cmd_vel_arbiter/status", 10, [&](const spott_msgs::ArbiterStatus::ConstPtr& s) {
        std::lock_guard<std::mutex> lock(status_mutex);
        status = *s;
      });
  const auto Status = [&] {
    std::lock_guard<std::mutex> lock(status_mutex);
    return status;
  };
  ros::Publisher planner = nh.advertise<geometry_msgs::Twist>("cmd_vel/planner", 10);
  ros::Publisher wander = nh.advertise<geometry_msgs::Twist>("cmd_vel/wander", 10);
  ASSERT_TRUE(ros::service::waitForService("cmd_vel_arbiter/take_wheels", ros::Duration(30)));
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(20.0);
  while ((planner.getNumSubscribers() == 0 || wander.getNumSubscribers() == 0) &&
         ros::WallTime::now() < end) {
    ros::WallDuration(0.05).sleep();
  }

  // The planner alone drives: the robot moves straight.
  SendFor(planner, Twist(0.2, 0.0), 1.5);
  EXPECT_NEAR(motion.Get().first, 0.2, 0.05);
  EXPECT_EQ(Status().driver, "planner");

  // wander takes the wheels and turns in place: the planner is told (PREEMPTED) and its
  // commands no longer move the robot.
  spott_msgs::TakeWheels take;
  take.request.source = "wander";
  ASSERT_TRUE(ros::service::call("cmd_vel_arbiter/take_wheels", take));
  ASSERT_TRUE(take.response.success) << take.response.message;
  const ros::Time turn_end = ros::Time::now() + ros::Duration(1.5);
  while (ros::Time::now() < turn_end) {
    planner.publish(Twist(0.2, 0.0));
    wander.publish(Twist(0.0, 0.5));
    ros::Duration(0.1).sleep();
  }
  EXPECT_LT(motion.Get().first, 0.03);
  EXPECT_NEAR(motion.Get().second, 0.5, 0.1);
  auto s = Status();
  EXPECT_EQ(s.driver, "wander");
  EXPECT_EQ(s.exclusive_holder, "wander");
  ASSERT_TRUE(Source(s, "planner"));
  EXPECT_EQ(Source(s, "planner")->state, spott_msgs::ArbiterSource::PREEMPTED);

  // Released: the planner, still sending, drives again.
  spott_msgs::ReleaseWheels release;
  release.request.source = "wander";
  ASSERT_TRUE(ros::service::call("cmd_vel_arbiter/release_wheels", release));
  ASSERT_TRUE(release.response.success) << release.response.message;
  SendFor(planner, Twist(0.2, 0.0), 1.5);
  EXPECT_NEAR(motion.Get().first, 0.2, 0.05);
  EXPECT_EQ(Status().driver, "planner");

  // The planner falls silent: after its 0.5 s timeout the arbiter stops the robot (well
  // before the simulator's own 1 s command timeout). Stopped by 1.1 s: 0.5 s timeout, one 50 Hz
  // check, 0.4 s braking from 0.2 m/s at the Nomad's 0.5 m/s^2. Had only the simulator's timeout
  // stopped it, it would still move at 0.15 m/s then. (At 0.8 s it read 0.045 m/s once: braking.)
  ros::Duration(1.1).sleep();
  EXPECT_LT(motion.Get().first, 0.03);
  s = Status();
  EXPECT_EQ(s.driver, "");
  EXPECT_EQ(Source(s, "planner")->state, spott_msgs::ArbiterSource::TIMED_OUT);

  // NaN commands are refused, counted, and stop the robot.
  SendFor(planner, Twist(0.2, 0.0), 1.0);
  ASSERT_NEAR(motion.Get().first, 0.2, 0.05);
  const auto refused_before = Status().refused;
  SendFor(planner, Twist(std::numeric_limits<double>::quiet_NaN(), 0.0), 1.0);
  EXPECT_LT(motion.Get().first, 0.03);
  EXPECT_GT(Status().refused, refused_before);
}

TEST(ArbiterNode, AnUnknownParameterStopsTheNodeNamingIt) {
  const auto run = spott_ros::testing::RunNode(
      ARBITER_EXE, "__name:=bad_arbiter _limits/max_speed_mps:=1.0 _sources/x/priority:=one");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("~limits/max_speed_mps is not a parameter"), std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("~sources/x/priority must be an integer"), std::string::npos)
      << run.output;
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "arbiter_rostest");
  return RUN_ALL_TESTS();
}
