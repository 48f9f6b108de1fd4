// The stack's contract, end to end on cim_office with every node real (stack.launch): move_base
// clients and rviz's /move_base_simple/goal drive the robot through Navigate; a goal behind a
// closed door ends UNREACHABLE at once, naming the door; a new goal preempts the running one.
// Judged on the simulator's ground truth.
#include <actionlib/client/simple_action_client.h>
#include <geometry_msgs/PoseStamped.h>
#include <gtest/gtest.h>
#include <move_base_msgs/MoveBaseAction.h>
#include <ros/ros.h>
#include <spott_msgs/NavigateAction.h>

#include <atomic>
#include <cmath>

#include "demo_navigation.h"
#include "executive_test_support.h"
#include "spott_ros/pose_conversions.h"
#include "spott_ros/testing/node_process.h"

namespace {

using NavigateClient = actionlib::SimpleActionClient<spott_msgs::NavigateAction>;
using MoveBaseClient = actionlib::SimpleActionClient<move_base_msgs::MoveBaseAction>;

using spott_launch::testing::Truth;

geometry_msgs::PoseStamped Pose(double x, double y, double yaw) {
  return spott_ros::ToPoseStamped(spott_ros::MakePose2D(x, y, yaw), "map", ros::Time::now());
}

class Contract : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    spinner_ = new ros::AsyncSpinner(2);
    spinner_->start();
  }
  // Stopped before the process exits: a spinner thread still running while roscpp's statics
  // are destroyed aborted the process (boost::lock_error) after the results were written.
  static void TearDownTestSuite() {
    spinner_->stop();
    delete spinner_;
    spinner_ = nullptr;
  }
  static ros::AsyncSpinner* spinner_;
  ros::NodeHandle nh_;
};
ros::AsyncSpinner* Contract::spinner_ = nullptr;

// The tests run in order on one stack: the robot starts at (1.2, 8.25) in the west hallway.
TEST_F(Contract, AMoveBaseClientBringsTheRobotToAGoal) {
  Truth truth(nh_);
  MoveBaseClient client("move_base", true);
  ASSERT_TRUE(client.waitForServer(ros::Duration(60.0)));
  move_base_msgs::MoveBaseGoal goal;
  goal.target_pose = Pose(6.0, 8.25, 0.0);
  std::atomic<int> feedback{0};
  client.sendGoal(goal, MoveBaseClient::SimpleDoneCallback(),
                  MoveBaseClient::SimpleActiveCallback(),
                  [&](const move_base_msgs::MoveBaseFeedbackConstPtr& f) {
                    if (f->base_position.header.frame_id == "map") ++feedback;
                  });
  ASSERT_TRUE(client.waitForResult(ros::Duration(120.0)));
  EXPECT_EQ(client.getState(), actionlib::SimpleClientGoalState::SUCCEEDED)
      << client.getState().getText();
  EXPECT_LT(truth.DistanceTo(6.0, 8.25), 0.25);
  EXPECT_GT(feedback, 0) << "move_base feedback carries the robot's pose";
  EXPECT_EQ(truth.contacts(), 0);
}

TEST_F(Contract, RvizsNavGoalOnMoveBaseSimpleBringsTheRobotToAGoal) {
  Truth truth(nh_);
  spott_ros::testing::Latest<move_base_msgs::MoveBaseActionResult> result(nh_, "move_base/result");
  ros::Publisher pub = nh_.advertise<geometry_msgs::PoseStamped>("move_base_simple/goal", 1);
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(20.0);
  while (pub.getNumSubscribers() == 0 && ros::WallTime::now() < end)
    ros::WallDuration(0.05).sleep();
  pub.publish(Pose(3.0, 8.0, M_PI));
  ASSERT_TRUE(result.WaitFor(
      [](const auto& r) {
        return r.status.status == actionlib_msgs::GoalStatus::SUCCEEDED ||
               r.status.status == actionlib_msgs::GoalStatus::ABORTED;
      },
      120.0));
  EXPECT_EQ(result.msg()->status.status, actionlib_msgs::GoalStatus::SUCCEEDED)
      << result.msg()->status.text;
  EXPECT_LT(truth.DistanceTo(3.0, 8.0), 0.25);
  EXPECT_EQ(truth.contacts(), 0);
}

TEST_F(Contract, AGoalBehindAClosedDoorIsUnreachableAtOnceNamingTheDoor) {
  NavigateClient client("harmonic_planner/navigate", true);
  ASSERT_TRUE(client.waitForServer(ros::Duration(30.0)));
  // office_102's only door d_102 is closed in cim_office.
  const ros::Time sent = ros::Time::now();
  client.sendGoal(spott_launch::NavigateGoalTo(spott_map::Pose2{7.5, 3.5, 0.0}, true));
  ASSERT_TRUE(client.waitForResult(ros::Duration(30.0)));
  const double took_s = (ros::Time::now() - sent).toSec();
  const auto r = client.getResult();
  EXPECT_EQ(r->outcome, spott_msgs::NavigateResult::UNREACHABLE) << r->reason;
  EXPECT_NE(r->reason.find("d_102"), std::string::npos) << r->reason;
  EXPECT_LT(took_s, 2.0) << "simulated seconds from the goal to UNREACHABLE";
}

TEST_F(Contract, ASecondGoalPreemptsTheFirst) {
  Truth truth(nh_);
  NavigateClient first("harmonic_planner/navigate", true),
      second("harmonic_planner/navigate", true);
  ASSERT_TRUE(first.waitForServer(ros::Duration(30.0)));
  ASSERT_TRUE(second.waitForServer(ros::Duration(30.0)));
  first.sendGoal(spott_launch::NavigateGoalTo(spott_map::Pose2{14.0, 8.25, 0.0}, true));
  ros::Duration(3.0).sleep();  // simulated: it drives east
  second.sendGoal(spott_launch::NavigateGoalTo(spott_map::Pose2{4.0, 8.25, 0.0}, true, 0.25));
  ASSERT_TRUE(first.waitForResult(ros::Duration(10.0)));
  EXPECT_EQ(first.getState(), actionlib::SimpleClientGoalState::PREEMPTED);
  EXPECT_EQ(first.getResult()->outcome, spott_msgs::NavigateResult::PREEMPTED);
  ASSERT_TRUE(second.waitForResult(ros::Duration(120.0)));
  EXPECT_EQ(second.getResult()->outcome, spott_msgs::NavigateResult::SUCCEEDED)
      << second.getResult()->reason;
  EXPECT_LT(truth.DistanceTo(4.0, 8.25), 0.25);
}

// The contract's two nodes of this package's stack refuse a misspelt or mistyped key by name.
TEST(ContractParameters, MoveBaseAndDemoReportRefuseBadParametersByName) {
  auto run = spott_ros::testing::RunNode(
      MOVE_BASE_EXE, "__name:=bad_move_base _navigate_acton:=/navigate _server_timeout_s:=soon");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  for (const char* key : {"~navigate_acton is not a parameter", "~server_timeout_s"}) {
    EXPECT_NE(run.output.find(key), std::string::npos) << key << " in:\n" << run.output;
  }
  run = spott_ros::testing::RunNode(DEMO_REPORT_EXE, "__name:=bad_report _legz:=[]");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("~legz is not a parameter"), std::string::npos) << run.output;
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "contract_rostest");
  return RUN_ALL_TESTS();
}
