// Issue 21, end to end on cim_office: kill -9 each node of the stack (robot_sim, the robot
// itself, excepted: it stays required), wait for roslaunch to respawn it under a new PID, and
// check on the simulator's ground truth that the stack still finishes a goal. markov_localization
// is killed while the robot drives and must resume near the truth from its saved map -> odom.
#include <actionlib/client/simple_action_client.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <gtest/gtest.h>
#include <nav_msgs/Path.h>
#include <ros/master.h>
#include <ros/network.h>
#include <ros/ros.h>
#include <spott_msgs/NavigateAction.h>
#include <xmlrpcpp/XmlRpc.h>

#include <signal.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <string>

#include "demo_navigation.h"
#include "executive_test_support.h"

namespace {

using spott_launch::testing::Truth;
using spott_launch::testing::WaitUntil;
using NavigateClient = actionlib::SimpleActionClient<spott_msgs::NavigateAction>;

// The PID of a running node (the master's lookupNode, then the node's getPid), or -1.
int PidOf(const std::string& node) {
  XmlRpc::XmlRpcValue args, result, payload;
  args[0] = ros::this_node::getName();
  args[1] = node;
  if (!ros::master::execute("lookupNode", args, result, payload, false)) return -1;
  std::string host;
  uint32_t port = 0;
  if (!ros::network::splitURI(static_cast<std::string>(payload), host, port)) return -1;
  XmlRpc::XmlRpcClient client(host.c_str(), static_cast<int>(port), "/");
  XmlRpc::XmlRpcValue pid_args, pid;
  pid_args[0] = ros::this_node::getName();
  const bool ok = client.execute("getPid", pid_args, pid) && pid.getType() == pid.TypeArray &&
                  pid.size() == 3 && static_cast<int>(pid[0]) == 1;
  client.close();
  return ok ? static_cast<int>(pid[2]) : -1;
}

// Kills the node and waits (wall time) until a new process of it answers.
::testing::AssertionResult KillAndWaitForRespawn(const std::string& node) {
  const int pid = PidOf(node);
  if (pid <= 0) return ::testing::AssertionFailure() << node << ": no PID";
  if (kill(pid, SIGKILL) != 0) return ::testing::AssertionFailure() << node << ": kill failed";
  int now = -1;
  if (!WaitUntil(
          [&] {
            now = PidOf(node);
            return now > 0 && now != pid;
          },
          60.0))
    return ::testing::AssertionFailure() << node << " (pid " << pid << ") not respawned";
  return ::testing::AssertionSuccess() << node << ": pid " << pid << " -> " << now;
}

class Estimate {
 public:
  explicit Estimate(ros::NodeHandle& nh)
      : sub_(nh.subscribe("/amcl_pose", 5, &Estimate::On, this)) {}
  double ErrorTo(const Truth& t) {
    std::lock_guard<std::mutex> lock(mutex_);
    return count_ > 0 ? t.DistanceTo(x_, y_) : std::numeric_limits<double>::infinity();
  }
  int count() {
    std::lock_guard<std::mutex> lock(mutex_);
    return count_;
  }
  // The reading the last estimate is of (a respawned node first works off its queue of readings
  // from while it built its models: those estimates are of where the robot was then).
  ros::Time stamp() {
    std::lock_guard<std::mutex> lock(mutex_);
    return stamp_;
  }

 private:
  void On(const geometry_msgs::PoseWithCovarianceStamped& m) {
    std::lock_guard<std::mutex> lock(mutex_);
    x_ = m.pose.pose.position.x;
    y_ = m.pose.pose.position.y;
    stamp_ = m.header.stamp;
    ++count_;
  }
  std::mutex mutex_;
  double x_ = 0, y_ = 0;
  int count_ = 0;
  ros::Time stamp_;
  ros::Subscriber sub_;
};

// How far the harmonic planner's own pose (the first pose of its predicted path) strays from the
// truth: while the localization is dead it must go on with the odometry, not stay where the
// robot was when the last map -> odom came (spott_ros/robot_pose.h).
class PlannerPoseGap {
 public:
  PlannerPoseGap(ros::NodeHandle& nh, const Truth& truth)
      : truth_(truth), sub_(nh.subscribe("/harmonic_planner/path", 5, &PlannerPoseGap::On, this)) {}
  void Reset() {
    std::lock_guard<std::mutex> lock(mutex_);
    max_gap_m_ = 0.0;
    count_ = 0;
  }
  double max_gap_m() {
    std::lock_guard<std::mutex> lock(mutex_);
    return max_gap_m_;
  }
  int count() {
    std::lock_guard<std::mutex> lock(mutex_);
    return count_;
  }

 private:
  void On(const nav_msgs::Path& m) {
    if (m.poses.empty()) return;
    const double gap =
        truth_.DistanceTo(m.poses.front().pose.position.x, m.poses.front().pose.position.y);
    std::lock_guard<std::mutex> lock(mutex_);
    max_gap_m_ = std::max(max_gap_m_, gap);
    ++count_;
  }
  const Truth& truth_;
  std::mutex mutex_;
  double max_gap_m_ = 0.0;
  int count_ = 0;
  ros::Subscriber sub_;
};

class NodeKill : public spott_launch::testing::StackTest {
 protected:
  static void SetUpTestSuite() {
    StackTest::SetUpTestSuite();
    estimate_ = new Estimate(*nh_);
    planner_gap_ = new PlannerPoseGap(*nh_, *truth_);
  }
  static void TearDownTestSuite() {
    spinner_->stop();
    delete estimate_;
    delete planner_gap_;
    StackTest::TearDownTestSuite();
  }
  // A leg along the west hallway; true when it SUCCEEDED within 0.3 m of the truth.
  static ::testing::AssertionResult Leg(double x, double y) {
    NavigateClient client("harmonic_planner/navigate", true);
    if (!client.waitForServer(ros::Duration(60.0)))
      return ::testing::AssertionFailure() << "no Navigate server";
    truth_->ResetContacts();
    client.sendGoal(spott_launch::NavigateGoalTo(spott_map::Pose2{x, y, 0.0}, true));
    if (!client.waitForResult(ros::Duration(120.0)))
      return ::testing::AssertionFailure() << "no result in 120 s";
    const auto r = client.getResult();
    if (r->outcome != spott_msgs::NavigateResult::SUCCEEDED)
      return ::testing::AssertionFailure() << "outcome " << int(r->outcome) << ": " << r->reason;
    if (truth_->DistanceTo(x, y) > 0.3)
      return ::testing::AssertionFailure() << "ended " << truth_->DistanceTo(x, y) << " m off";
    if (truth_->contacts() > 0)
      return ::testing::AssertionFailure() << truth_->contacts() << " bumper contacts";
    return ::testing::AssertionSuccess();
  }
  static inline Estimate* estimate_ = nullptr;
  static inline PlannerPoseGap* planner_gap_ = nullptr;
};

TEST_F(NodeKill, TheStackFinishesALegBeforeAnyKill) {
  ASSERT_TRUE(WaitUntil([] { return truth_->seen() && estimate_->ErrorTo(*truth_) < 0.5; }, 60.0));
  EXPECT_TRUE(Leg(4.0, 8.25));
}

// Killed while the robot drives: the leg goes on (the last map -> odom stays in tf), and the
// respawned node resumes at its saved map -> odom composed with the odometry of the moment.
TEST_F(NodeKill, TheLocalizationKilledWhileDrivingResumesNearTheTruth) {
  NavigateClient client("harmonic_planner/navigate", true);
  ASSERT_TRUE(client.waitForServer(ros::Duration(30.0)));
  truth_->ResetContacts();
  client.sendGoal(spott_launch::NavigateGoalTo(spott_map::Pose2{8.0, 8.25, 0.0}, true));
  ros::Duration(3.0).sleep();  // simulated: on its way east
  ros::Duration(2.5).sleep();  // at least one save of map -> odom (every 2 s)
  const int before = estimate_->count();
  planner_gap_->Reset();
  ASSERT_TRUE(KillAndWaitForRespawn("/markov_localization"));
  ASSERT_TRUE(client.waitForResult(ros::Duration(120.0)));
  const ros::Time stopped = ros::Time::now();
  // The respawned node rebuilds its models for seconds: meanwhile the robot drove on odometry.
  EXPECT_GT(planner_gap_->count(), 5);
  EXPECT_LT(planner_gap_->max_gap_m(), 0.6) << "the planner's pose strayed from the truth";
  EXPECT_EQ(client.getResult()->outcome, spott_msgs::NavigateResult::SUCCEEDED)
      << client.getResult()->reason;
  EXPECT_LT(truth_->DistanceTo(8.0, 8.25), 0.3);
  EXPECT_EQ(truth_->contacts(), 0);
  ASSERT_TRUE(WaitUntil([&] { return estimate_->count() > before + 2; }, 60.0))
      << "the respawned node publishes no estimate";
  // Judged on an estimate of a reading taken with the robot standing at the leg's end.
  ASSERT_TRUE(WaitUntil([&] { return estimate_->stamp() > stopped; }, 60.0))
      << "the respawned node publishes no estimate of the standing robot";
  EXPECT_LT(estimate_->ErrorTo(*truth_), 0.5);
  EXPECT_TRUE(Leg(5.0, 8.25));
}

TEST_F(NodeKill, EachOtherNodeIsRespawnedAndTheStackFinishesTheNextLeg) {
  double x = 3.0;
  for (const char* node : {"/harmonic_planner", "/global_planner", "/cmd_vel_arbiter",
                           "/world_server", "/robot_state_publisher"}) {
    ASSERT_TRUE(KillAndWaitForRespawn(node));
    ros::Duration(2.0).sleep();  // simulated: it reads its parameters and latched topics
    EXPECT_TRUE(Leg(x, 8.25)) << "after killing " << node;
    x = x == 3.0 ? 6.0 : 3.0;
  }
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "node_kill_rostest");
  const int failed = RUN_ALL_TESTS();
  ros::shutdown();
  return failed;
}
