// move_base's Navigate goal, lost once: the adapter must send it again (spott_ros's
// GoalAckWatch) and the MoveBase goal must still end SUCCEEDED.
#include <actionlib/client/simple_action_client.h>
#include <actionlib/server/action_server.h>
#include <gtest/gtest.h>
#include <move_base_msgs/MoveBaseAction.h>
#include <ros/ros.h>
#include <spott_msgs/NavigateAction.h>

#include <atomic>

namespace {

using NavigateServer = actionlib::ActionServer<spott_msgs::NavigateAction>;

// Leaves the first goal PENDING for ever (the client sees what it sees when the goal was lost:
// no acknowledgement) and succeeds every later one at once.
class ForgetfulNavigate {
 public:
  explicit ForgetfulNavigate(ros::NodeHandle& nh)
      : server_(nh, "harmonic_planner/navigate", false) {
    server_.registerGoalCallback([this](NavigateServer::GoalHandle g) {
      if (goals_++ == 0) {
        first_ = g;  // kept, never accepted
        return;
      }
      g.setAccepted();
      spott_msgs::NavigateResult r;
      r.outcome = spott_msgs::NavigateResult::SUCCEEDED;
      r.reason = "reached";
      g.setSucceeded(r, r.reason);
    });
    server_.start();
  }
  int goals() const { return goals_; }

 private:
  NavigateServer server_;
  NavigateServer::GoalHandle first_;
  std::atomic<int> goals_{0};
};

TEST(MoveBaseLostGoal, AnUnacknowledgedNavigateGoalIsSentAgain) {
  ros::NodeHandle nh;
  ForgetfulNavigate navigate(nh);
  ros::AsyncSpinner spinner(2);
  spinner.start();
  actionlib::SimpleActionClient<move_base_msgs::MoveBaseAction> client("move_base", true);
  ASSERT_TRUE(client.waitForServer(ros::Duration(20.0)));
  move_base_msgs::MoveBaseGoal goal;
  goal.target_pose.header.frame_id = "map";
  goal.target_pose.header.stamp = ros::Time::now();
  goal.target_pose.pose.position.x = 1.0;
  goal.target_pose.pose.orientation.w = 1.0;
  client.sendGoal(goal);
  ASSERT_TRUE(client.waitForResult(ros::Duration(20.0)));
  EXPECT_EQ(client.getState(), actionlib::SimpleClientGoalState::SUCCEEDED);
  // The first goal was never answered: only a second one can have succeeded.
  EXPECT_EQ(navigate.goals(), 2);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "lost_goal_rostest");
  return RUN_ALL_TESTS();
}
