// The robot heads from the west hallway (1.2, 8.25) for the lab bench (26, 16.5) through the
// lab's west door d_lab_w; once it is on its way the door closes, in the simulator and in the
// map database (standing in for the TR+ controller, the map's owner, which would record what
// the robot senses). The global planner must replan through hall_join and d_lab_e, and the
// robot must still arrive.
#include <actionlib/client/simple_action_client.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <spott_msgs/Door.h>
#include <spott_msgs/GlobalPath.h>
#include <spott_msgs/NavigateAction.h>
#include <spott_msgs/SetDoorState.h>

#include <algorithm>
#include <cmath>
#include <mutex>

#include "demo_navigation.h"

namespace {

bool Has(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

TEST(Replan, ClosedDoorOnTheWayIsAvoidedThroughAnotherDoor) {
  ros::NodeHandle nh;
  ASSERT_TRUE(ros::Time::waitForValid(ros::WallDuration(30.0)));
  std::mutex mutex;
  spott_msgs::GlobalPath path;
  nav_msgs::Odometry truth;
  ros::Subscriber path_sub = nh.subscribe<spott_msgs::GlobalPath>(
      "global_path", 5, [&](const spott_msgs::GlobalPath::ConstPtr& m) {
        std::lock_guard<std::mutex> lock(mutex);
        path = *m;
      });
  ros::Subscriber truth_sub = nh.subscribe<nav_msgs::Odometry>(
      "/sim/ground_truth", 5, [&](const nav_msgs::Odometry::ConstPtr& m) {
        std::lock_guard<std::mutex> lock(mutex);
        truth = *m;
      });
  ros::AsyncSpinner spinner(2);
  spinner.start();
  actionlib::SimpleActionClient<spott_msgs::NavigateAction> client("harmonic_planner/navigate",
                                                                   true);
  ASSERT_TRUE(client.waitForServer(ros::Duration(30.0)));

  // Navigate hands the target to the global planner; the first plan goes through the lab's
  // west door.
  const auto path_has = [&](const std::string& door) {
    std::lock_guard<std::mutex> lock(mutex);
    return Has(path.doors, door);
  };
  client.sendGoal(
      spott_launch::NavigateGoalTo(spott_map::Pose2{26.0, 16.5, 0.0}, /*ignore_heading=*/true));
  const ros::WallTime plan_deadline = ros::WallTime::now() + ros::WallDuration(20.0);
  while (!path_has("d_lab_w") && ros::WallTime::now() < plan_deadline) {
    ros::WallDuration(0.05).sleep();
  }
  ASSERT_TRUE(path_has("d_lab_w"));
  ros::Duration(8.0).sleep();  // simulated: the robot is driving east along the hallway
  {
    std::lock_guard<std::mutex> lock(mutex);
    ASSERT_GT(truth.pose.pose.position.x, 2.5) << "the robot did not set off";
    ASSERT_LT(truth.pose.pose.position.x, 11.0) << "the robot is already at the door";
  }
  for (const char* service : {"/sim/set_door_state", "world_server/set_door_state"}) {
    spott_msgs::SetDoorState srv;
    srv.request.door_id = "d_lab_w";
    srv.request.state = spott_msgs::Door::CLOSED;
    ASSERT_TRUE(ros::service::call(service, srv)) << service;
    ASSERT_TRUE(srv.response.success) << service << ": " << srv.response.message;
  }
  const ros::WallTime replan_deadline = ros::WallTime::now() + ros::WallDuration(20.0);
  while (!path_has("d_lab_e") && ros::WallTime::now() < replan_deadline) {
    ros::WallDuration(0.05).sleep();
  }
  EXPECT_TRUE(path_has("d_lab_e"));
  EXPECT_TRUE(path_has("hall_join"));
  EXPECT_FALSE(path_has("d_lab_w"));

  ASSERT_TRUE(client.waitForResult(ros::Duration(240.0)));  // simulated seconds
  const auto result = client.getResult();
  ASSERT_TRUE(result);
  EXPECT_EQ(result->outcome, spott_msgs::NavigateResult::SUCCEEDED) << result->reason;
  std::lock_guard<std::mutex> lock(mutex);
  EXPECT_LT(std::hypot(truth.pose.pose.position.x - 26.0, truth.pose.pose.position.y - 16.5), 0.3);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "replan_rostest");
  return RUN_ALL_TESTS();
}
