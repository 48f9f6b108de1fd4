// The ActiveLocalize action on the simulator (see active_localize.test): bad requests are
// refused with their reason and the node goes on; from a uniform belief the random motion, then
// a* sent to the harmonic planner; the status says ACTIVE while it runs; the belief grid is
// published; a run can be preempted and the robot stops.
#include <gtest/gtest.h>

#include <actionlib/client/simple_action_client.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <spott_msgs/ActiveLocalizeAction.h>
#include <spott_msgs/LocalizationStatus.h>
#include <spott_msgs/NavigateAction.h>
#include <tf2/utils.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <string>

#include "spott_ros/testing/node_process.h"

namespace {

using Client = actionlib::SimpleActionClient<spott_msgs::ActiveLocalizeAction>;

struct Listener {
  std::mutex mutex;
  nav_msgs::Odometry truth;
  nav_msgs::OccupancyGrid belief;
  spott_msgs::LocalizationStatus status;
  bool have_truth = false, have_belief = false, saw_active = false;
  int feedbacks_with_target = 0;
  double first_target_x = NAN, first_target_y = NAN;
  double driven_m = 0.0;  // path length on the ground truth
  void OnTruth(const nav_msgs::Odometry& t) {
    std::lock_guard<std::mutex> lock(mutex);
    if (have_truth)
      driven_m += std::hypot(t.pose.pose.position.x - truth.pose.pose.position.x,
                             t.pose.pose.position.y - truth.pose.pose.position.y);
    truth = t;
    have_truth = true;
  }
  void OnBelief(const nav_msgs::OccupancyGrid& g) {
    std::lock_guard<std::mutex> lock(mutex);
    belief = g;
    have_belief = true;
  }
  void OnStatus(const spott_msgs::LocalizationStatus& s) {
    std::lock_guard<std::mutex> lock(mutex);
    status = s;
    if (s.mode == spott_msgs::LocalizationStatus::ACTIVE) saw_active = true;
  }
  void OnFeedback(const spott_msgs::ActiveLocalizeFeedbackConstPtr& f) {
    std::lock_guard<std::mutex> lock(mutex);
    if (f->target.x != 0.0 || f->target.y != 0.0) {
      if (feedbacks_with_target++ == 0) {
        first_target_x = f->target.x;
        first_target_y = f->target.y;
      }
    }
  }
};

bool WaitDone(Client& client, double wall_s) {
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(wall_s);
  while (ros::ok() && ros::WallTime::now() < end) {
    if (client.getState().isDone()) return true;
    ros::WallDuration(0.05).sleep();
  }
  return false;
}

spott_msgs::ActiveLocalizeGoal Goal(double threshold, double timeout, bool uniform) {
  spott_msgs::ActiveLocalizeGoal g;
  g.certainty_threshold = threshold;
  g.timeout = timeout;
  g.start_uniform = uniform;
  return g;
}

class ActiveLocalizeTest : public ::testing::Test {
 protected:
  void SetUp() override {
    truth_sub_ = nh_.subscribe("sim/ground_truth", 5, &Listener::OnTruth, &l_);
    belief_sub_ = nh_.subscribe("belief", 1, &Listener::OnBelief, &l_);
    status_sub_ = nh_.subscribe("localization_status", 5, &Listener::OnStatus, &l_);
    spinner_.start();
    client_ = std::make_unique<Client>(nh_, "active_localize", true);
    ASSERT_TRUE(client_->waitForServer(ros::Duration(60.0))) << "active_localize not served";
    // The node builds its models from the first ring: wait for its first status.
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(60.0);
    while (ros::WallTime::now() < end) {
      {
        std::lock_guard<std::mutex> lock(l_.mutex);
        if (l_.status.header.stamp != ros::Time(0) && l_.have_truth) break;
      }
      ros::WallDuration(0.1).sleep();
    }
  }

  ros::NodeHandle nh_;
  Listener l_;
  ros::Subscriber truth_sub_, belief_sub_, status_sub_;
  ros::AsyncSpinner spinner_{2};
  std::unique_ptr<Client> client_;
  int navigate_goals_ = 0;
  spott_msgs::NavigateActionGoal last_navigate_;
};

// Only in active_localize_success.test (the whole chain at its defaults): from a uniform
// belief the action must end certain and within 0.5 m / 10 degrees of the ground truth.
TEST_F(ActiveLocalizeTest, FromAUniformBeliefEndsCertainAndRight) {
  client_->sendGoal(Goal(0.8, 400.0, true));
  ASSERT_TRUE(WaitDone(*client_, 300.0)) << "no result within 300 s of wall time";
  const auto result = client_->getResult();
  ASSERT_TRUE(result);
  ASSERT_TRUE(result->success) << result->reason << " (certainty " << result->certainty << ")";
  std::lock_guard<std::mutex> lock(l_.mutex);
  const auto& t = l_.truth.pose.pose;
  const double error =
      std::hypot(result->estimate.x - t.position.x, result->estimate.y - t.position.y);
  const double heading =
      std::abs(std::remainder(result->estimate.theta - tf2::getYaw(t.orientation), 2 * M_PI));
  EXPECT_LT(error, 0.5);
  EXPECT_LT(heading, 10.0 * M_PI / 180.0);
  std::printf("ActiveLocalize: success after %u targets, error %.2f m / %.1f deg\n",
              result->targets_visited, error, heading * 180.0 / M_PI);
}

TEST_F(ActiveLocalizeTest, RefusesBadRequestsAndGoesOn) {
  client_->sendGoal(Goal(0.8, -5.0, true));
  ASSERT_TRUE(WaitDone(*client_, 10.0));
  EXPECT_EQ(client_->getState(), actionlib::SimpleClientGoalState::ABORTED);
  EXPECT_NE(client_->getResult()->reason.find("timeout must be >= 0"), std::string::npos)
      << client_->getResult()->reason;
  EXPECT_FALSE(client_->getResult()->success);
  for (double bad : {1.5, -0.1, 1.0}) {
    client_->sendGoal(Goal(bad, 100.0, true));
    ASSERT_TRUE(WaitDone(*client_, 10.0));
    EXPECT_EQ(client_->getState(), actionlib::SimpleClientGoalState::ABORTED);
    EXPECT_NE(client_->getResult()->reason.find("certainty_threshold must be in (0, 1)"),
              std::string::npos)
        << client_->getResult()->reason;
  }
  // The node goes on: it still localizes (status keeps coming) after the refusals.
  ros::Time before;
  {
    std::lock_guard<std::mutex> lock(l_.mutex);
    before = l_.status.header.stamp;
  }
  ros::WallDuration(1.0).sleep();
  std::lock_guard<std::mutex> lock(l_.mutex);
  EXPECT_GT(l_.status.header.stamp, before);
}

// From a uniform belief: the random motion (4 m here) by the sonar ring alone, then a* chosen
// from the modes and sent to the harmonic planner as a Navigate goal in the map frame; the
// status says ACTIVE; a cancel preempts the run and the robot stops. (Success within 0.5 m /
// 10 degrees is not asserted: see the README, "what does not work yet".)
TEST_F(ActiveLocalizeTest, RandomMotionThenTargetsToNavigationThenPreempted) {
  ros::Subscriber nav_goals = nh_.subscribe<spott_msgs::NavigateActionGoal>(
      "harmonic_planner/navigate/goal", 5, [this](const spott_msgs::NavigateActionGoalConstPtr& g) {
        std::lock_guard<std::mutex> lock(l_.mutex);
        ++navigate_goals_;
        last_navigate_ = *g;
      });
  double driven0;
  {
    std::lock_guard<std::mutex> lock(l_.mutex);
    driven0 = l_.driven_m;
  }
  client_->sendGoal(
      Goal(0.0, 0.0, true), Client::SimpleDoneCallback(), Client::SimpleActiveCallback(),
      [this](const spott_msgs::ActiveLocalizeFeedbackConstPtr& f) { l_.OnFeedback(f); });
  // Wait (at most 90 s of wall time) for the first Navigate goal.
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(90.0);
  bool sent = false;
  while (ros::ok() && ros::WallTime::now() < end && !client_->getState().isDone()) {
    {
      std::lock_guard<std::mutex> lock(l_.mutex);
      sent = navigate_goals_ > 0 && l_.feedbacks_with_target > 0;
    }
    if (sent) break;
    ros::WallDuration(0.1).sleep();
  }
  ASSERT_TRUE(sent) << "no target was sent to navigation; state " << client_->getState().toString();
  {
    std::lock_guard<std::mutex> lock(l_.mutex);
    // The random motion came first: 4 m of odometry, measured as the path driven on the ground
    // truth (the straight-line distance can be small: the wander may turn back).
    EXPECT_GT(l_.driven_m - driven0, 3.0) << "the random motion did not move the robot";
    EXPECT_TRUE(l_.saw_active) << "status never said ACTIVE during the run";
    // The goal is a* in the map frame, without heading, inside the building.
    EXPECT_EQ(last_navigate_.goal.target.header.frame_id, "map");
    EXPECT_TRUE(last_navigate_.goal.ignore_heading);
    const auto& p = last_navigate_.goal.target.pose.position;
    EXPECT_GT(p.x, 0.0);
    EXPECT_LT(p.x, 27.0);
    EXPECT_GT(p.y, 0.0);
    EXPECT_LT(p.y, 20.0);
    EXPECT_DOUBLE_EQ(p.x, l_.first_target_x);
    // The belief grid (marginal over theta) for rviz: latched, maximum 100, 20 cm cells.
    ASSERT_TRUE(l_.have_belief);
    EXPECT_EQ(*std::max_element(l_.belief.data.begin(), l_.belief.data.end()), 100);
    EXPECT_FLOAT_EQ(l_.belief.info.resolution, 0.2f);
  }
  client_->cancelGoal();
  ASSERT_TRUE(WaitDone(*client_, 10.0));
  EXPECT_EQ(client_->getState(), actionlib::SimpleClientGoalState::PREEMPTED);
  EXPECT_EQ(client_->getResult()->reason, "preempted");
  ros::WallDuration(2.0).sleep();  // navigation cancelled, the last command zero: it stands
  std::lock_guard<std::mutex> lock(l_.mutex);
  EXPECT_LT(std::abs(l_.truth.twist.twist.linear.x), 0.02);
  EXPECT_NE(l_.status.mode, spott_msgs::LocalizationStatus::ACTIVE);
}

// Bad parameters (spott_ros::ParameterReader): the node refuses to start (exit 1) and names
// each one at once: out of range, a wrong type, a key without its unit, an unknown key.
TEST(MarkovLocalizationNode, BadParametersAreNamedAndTheNodeExits) {
  const auto run = spott_ros::testing::RunNode(
      NODE_EXE,
      "__name:=bad_params _world_file:=/nonexistent.yaml _map/resolution_m:=-1 "
      "_grid/threshold_fraction:=2.0 _sensor/beams:=true _laser/max_range_m:=far "
      "_gate/update_min_d:=0.3 _no_such_key:=1");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  for (const char* expected :
       {"~map/resolution_m must be in [0.01, 2] m", "~grid/threshold_fraction must be in (0, 1)",
        "~sensor/beams must be an integer", "~laser/max_range_m must be a number",
        "~gate/update_min_d is not a parameter of this node",
        "~no_such_key is not a parameter of this node"})
    EXPECT_NE(run.output.find(expected), std::string::npos) << expected << "\n" << run.output;
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "active_localize_rostest");
  return RUN_ALL_TESTS();
}
