// The ActiveLocalize action end to end on the simulator (see active_localize.test): bad
// requests are refused with their reason; from a uniform belief in the symmetric corridor the
// action ends in success with the estimate within 0.5 m / 10 degrees of the ground truth; the
// status says ACTIVE while it runs; the belief grid is published; a run can be preempted.
#include <gtest/gtest.h>

#include <actionlib/client/simple_action_client.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <spott_msgs/ActiveLocalizeAction.h>
#include <spott_msgs/LocalizationStatus.h>
#include <tf2/utils.h>

#include <algorithm>
#include <cmath>
#include <mutex>

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
  void OnTruth(const nav_msgs::Odometry& t) {
    std::lock_guard<std::mutex> lock(mutex);
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
};

TEST_F(ActiveLocalizeTest, RefusesBadRequestsThenLocalizesActivelyFromAUniformBelief) {
  // Bad requests: refused with the reason, the node goes on.
  client_->sendGoal(Goal(0.8, -5.0, true));
  ASSERT_TRUE(WaitDone(*client_, 10.0));
  EXPECT_EQ(client_->getState(), actionlib::SimpleClientGoalState::ABORTED);
  EXPECT_NE(client_->getResult()->reason.find("timeout must be >= 0"), std::string::npos)
      << client_->getResult()->reason;
  client_->sendGoal(Goal(1.5, 100.0, true));
  ASSERT_TRUE(WaitDone(*client_, 10.0));
  EXPECT_EQ(client_->getState(), actionlib::SimpleClientGoalState::ABORTED);
  EXPECT_NE(client_->getResult()->reason.find("certainty_threshold must be in (0, 1)"),
            std::string::npos)
      << client_->getResult()->reason;

  // The real run: uniform belief, random motion, then targets until certain (simulated time
  // limit 200 s; the wall-clock wait is the test's bound).
  const ros::Time started = ros::Time::now();
  client_->sendGoal(
      Goal(0.0, 200.0, true), Client::SimpleDoneCallback(), Client::SimpleActiveCallback(),
      [this](const spott_msgs::ActiveLocalizeFeedbackConstPtr& f) { l_.OnFeedback(f); });
  ASSERT_TRUE(WaitDone(*client_, 170.0)) << "no result within 170 s of wall time";
  const double took = (ros::Time::now() - started).toSec();
  const auto result = client_->getResult();
  ASSERT_EQ(client_->getState(), actionlib::SimpleClientGoalState::SUCCEEDED)
      << "reason: " << result->reason << "; certainty " << result->certainty;
  EXPECT_TRUE(result->success);
  EXPECT_GT(result->certainty, 0.8);
  std::lock_guard<std::mutex> lock(l_.mutex);
  ASSERT_TRUE(l_.have_truth);
  const auto& t = l_.truth.pose.pose;
  const double error_m =
      std::hypot(result->estimate.x - t.position.x, result->estimate.y - t.position.y);
  const double error_deg =
      std::abs(std::remainder(result->estimate.theta - tf2::getYaw(t.orientation), 2 * M_PI)) *
      180.0 / M_PI;
  std::cout << "[ active ] success after " << took << " s simulated, " << result->targets_visited
            << " targets reached, " << l_.feedbacks_with_target
            << " feedbacks with a target (first at " << l_.first_target_x << ", "
            << l_.first_target_y << "); error " << error_m << " m, " << error_deg
            << " deg; certainty " << result->certainty << std::endl;
  EXPECT_LT(error_m, 0.5);
  EXPECT_LT(error_deg, 10.0);
  EXPECT_TRUE(l_.saw_active) << "status never said ACTIVE during the run";
  // The belief grid (marginal over theta) for rviz: latched, maximum 100.
  ASSERT_TRUE(l_.have_belief);
  EXPECT_EQ(*std::max_element(l_.belief.data.begin(), l_.belief.data.end()), 100);
  EXPECT_FLOAT_EQ(l_.belief.info.resolution, 0.2f);
}

TEST_F(ActiveLocalizeTest, ARunCanBePreemptedAndTheRobotStops) {
  client_->sendGoal(Goal(0.0, 0.0, true));
  ros::WallDuration(4.0).sleep();
  EXPECT_FALSE(client_->getState().isDone());
  client_->cancelGoal();
  ASSERT_TRUE(WaitDone(*client_, 10.0));
  EXPECT_EQ(client_->getState(), actionlib::SimpleClientGoalState::PREEMPTED);
  EXPECT_EQ(client_->getResult()->reason, "preempted");
  ros::WallDuration(1.5).sleep();  // the last command was zero: the robot stands
  std::lock_guard<std::mutex> lock(l_.mutex);
  EXPECT_LT(std::abs(l_.truth.twist.twist.linear.x), 0.02);
  EXPECT_NE(l_.status.mode, spott_msgs::LocalizationStatus::ACTIVE);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "active_localize_rostest");
  return RUN_ALL_TESTS();
}
