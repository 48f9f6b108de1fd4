// Drives the real harmonic_planner node: this test integrates its ~cmd_vel as a unicycle and
// publishes the pose as tf map -> base_link (a kinematic stand-in for robot_sim, which is not
// on main yet), sends a Navigate goal through the door of hilare_room and checks the outcome and
// the clearance of the driven path. Also checks parameter validation by name.
#include <actionlib/client/simple_action_client.h>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/Twist.h>
#include <gtest/gtest.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/ros.h>
#include <spott_msgs/NavigateAction.h>
#include <spott_msgs/PotentialFieldStatus.h>
#include <tf2_ros/transform_broadcaster.h>

#include <atomic>
#include <cmath>
#include <mutex>

#include "spott_ros/testing/node_process.h"

namespace {

struct KinematicRobot {
  std::mutex mutex;
  double x = 6.5, y = 3.0, yaw = 0.0, v = 0.0, w = 0.0;
  double min_wall_distance = 1e9;  // to the wall x = 8 (outside the door) and the room walls
  bool crossed_door = false;
};

// Distance from (x, y) to the walls of hilare_room near the route: the wall x = 8 with the door
// y in [0.6, 1.8], the south wall y = 0 and the corridor's east wall x = 10.5.
double WallDistance(double x, double y) {
  double d = std::min(std::abs(y - 0.0), std::abs(10.5 - x));
  const double wy = std::clamp(y, 0.0, 9.0);
  if (wy < 0.6 || wy > 1.8) {
    d = std::min(d, std::hypot(x - 8.0, y - wy));
  } else {
    d = std::min(d, std::min(std::hypot(x - 8.0, y - 0.6), std::hypot(x - 8.0, y - 1.8)));
  }
  return d;
}

TEST(HarmonicPlannerNode, DrivesThroughDoorAroundWallToGoalInWindow) {
  ros::NodeHandle nh;
  KinematicRobot robot;
  tf2_ros::TransformBroadcaster broadcaster;
  ros::Subscriber cmd_sub = nh.subscribe<geometry_msgs::Twist>(
      "harmonic_planner/cmd_vel", 10, [&](const geometry_msgs::Twist::ConstPtr& m) {
        std::lock_guard<std::mutex> lock(robot.mutex);
        robot.v = m->linear.x;
        robot.w = m->angular.z;
      });
  std::atomic<bool> converged_seen{false};
  std::atomic<bool> potential_seen{false};
  ros::Subscriber status_sub = nh.subscribe<spott_msgs::PotentialFieldStatus>(
      "harmonic_planner/status", 10, [&](const spott_msgs::PotentialFieldStatus::ConstPtr& s) {
        if (s->converged) converged_seen = true;
      });
  ros::Subscriber potential_sub = nh.subscribe<nav_msgs::OccupancyGrid>(
      "harmonic_planner/potential", 1,
      [&](const nav_msgs::OccupancyGrid::ConstPtr& g) { potential_seen = !g->data.empty(); });
  const double dt = 0.02;
  ros::Timer sim = nh.createTimer(ros::Duration(dt), [&](const ros::TimerEvent&) {
    std::lock_guard<std::mutex> lock(robot.mutex);
    robot.x += robot.v * std::cos(robot.yaw) * dt;
    robot.y += robot.v * std::sin(robot.yaw) * dt;
    robot.yaw += robot.w * dt;
    robot.min_wall_distance = std::min(robot.min_wall_distance, WallDistance(robot.x, robot.y));
    if (std::abs(robot.x - 8.0) < 0.05 && robot.y > 0.6 && robot.y < 1.8) robot.crossed_door = true;
    geometry_msgs::TransformStamped t;
    t.header.stamp = ros::Time::now();
    t.header.frame_id = "map";
    t.child_frame_id = "base_link";
    t.transform.translation.x = robot.x;
    t.transform.translation.y = robot.y;
    t.transform.rotation.z = std::sin(robot.yaw / 2);
    t.transform.rotation.w = std::cos(robot.yaw / 2);
    broadcaster.sendTransform(t);
  });
  ros::AsyncSpinner spinner(2);
  spinner.start();

  actionlib::SimpleActionClient<spott_msgs::NavigateAction> client("harmonic_planner/navigate",
                                                                   false);
  ASSERT_TRUE(client.waitForServer(ros::Duration(30.0)));
  ros::Duration(1.0).sleep();  // map_features latched in, first cycles run
  spott_msgs::NavigateGoal goal;
  goal.target.header.frame_id = "map";
  goal.target.pose.position.x = 9.3;  // in the corridor, behind the wall x = 8
  goal.target.pose.position.y = 4.0;
  goal.target.pose.orientation.z = std::sin(M_PI / 4);  // final heading: north (pi / 2)
  goal.target.pose.orientation.w = std::cos(M_PI / 4);
  goal.speed_mode = spott_msgs::NavigateGoal::QUICKLY;
  goal.direction_bias = std::nan("");
  goal.position_tolerance = 0.25;
  goal.heading_tolerance = 0.1;
  goal.ignore_heading = false;
  client.sendGoal(goal);
  ASSERT_TRUE(client.waitForResult(ros::Duration(80.0)));
  const auto result = client.getResult();
  EXPECT_EQ(result->outcome, spott_msgs::NavigateResult::SUCCEEDED) << result->reason;
  robot.mutex.lock();
  EXPECT_LT(std::hypot(robot.x - 9.3, robot.y - 4.0), 0.35);
  EXPECT_TRUE(robot.crossed_door);
  EXPECT_LT(std::abs(std::remainder(robot.yaw - M_PI / 2, 2 * M_PI)), 0.15);
  // Robot radius 0.2285 m (the URDF's): the padded field keeps the body clear of the walls.
  EXPECT_GT(robot.min_wall_distance, 0.2285);
  EXPECT_TRUE(converged_seen);
  EXPECT_TRUE(potential_seen);
  const double x_end = robot.x, y_end = robot.y;
  robot.mutex.unlock();

  // Bad requests are refused with a reason, and the node keeps serving.
  goal.ignore_heading = true;
  spott_msgs::NavigateGoal bad = goal;
  bad.target.pose.position.x = std::nan("");
  client.sendGoal(bad);
  ASSERT_TRUE(client.waitForResult(ros::Duration(10.0)));
  EXPECT_EQ(client.getResult()->outcome, spott_msgs::NavigateResult::FAILED);
  EXPECT_NE(client.getResult()->reason.find("finite"), std::string::npos);

  // A goal inside the wall x = 8: UNREACHABLE, with the reason, and the robot stays put.
  spott_msgs::NavigateGoal in_wall = goal;
  in_wall.target.pose.position.x = 8.0;
  client.sendGoal(in_wall);
  ASSERT_TRUE(client.waitForResult(ros::Duration(20.0)));
  EXPECT_EQ(client.getResult()->outcome, spott_msgs::NavigateResult::UNREACHABLE);
  EXPECT_NE(client.getResult()->reason.find("obstacle"), std::string::npos)
      << client.getResult()->reason;

  // Preemption: a goal back in the room, cancelled after a second; the robot stops.
  spott_msgs::NavigateGoal back = goal;
  back.target.pose.position.x = 6.5;
  back.target.pose.position.y = 3.0;
  client.sendGoal(back);
  ros::Duration(1.0).sleep();
  client.cancelGoal();
  ASSERT_TRUE(client.waitForResult(ros::Duration(10.0)));
  EXPECT_EQ(client.getState(), actionlib::SimpleClientGoalState::PREEMPTED);
  ros::Duration(0.3).sleep();
  std::lock_guard<std::mutex> relock(robot.mutex);
  EXPECT_EQ(robot.v, 0.0);
  EXPECT_EQ(robot.w, 0.0);
  EXPECT_LT(std::hypot(robot.x - x_end, robot.y - y_end), 1.0);
}

TEST(HarmonicPlannerNode, BadParametersAreRefusedByName) {
  const auto run = spott_ros::testing::RunNode(
      HARMONIC_PLANNER_EXE,
      "__name:=bad_planner _window/resoluton_m:=0.1 _solver/kind:=conjugate_gradient "
      "_solver/omega:=2.5 _cycle_rate_hz:=0.0");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  for (const char* key : {"~window/resoluton_m is not a parameter", "~solver/kind", "solver/omega",
                          "~cycle_rate_hz"}) {
    EXPECT_NE(run.output.find(key), std::string::npos) << key << " in:\n" << run.output;
  }
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "harmonic_planner_rostest");
  return RUN_ALL_TESTS();
}
