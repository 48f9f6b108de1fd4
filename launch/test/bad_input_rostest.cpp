// Issue 21, end to end on cim_office with every node real: each harmful input of the issue is
// sent to the running stack and the test asserts that it was refused (counted by the node on
// /diagnostics) and that nothing changed (judged on the simulator's ground truth). The tests run
// in order on one stack; the robot starts at (1.2, 8.25) in the west hallway.
#include <actionlib/client/simple_action_client.h>
#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <geometry_msgs/Twist.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/master.h>
#include <ros/ros.h>
#include <spott_msgs/MapFeatureArray.h>
#include <spott_msgs/MapUpdate.h>
#include <spott_msgs/NavigateAction.h>
#include <spott_msgs/RangeRing.h>
#include <spott_msgs/RoomDoorGraph.h>
#include <xmlrpcpp/XmlRpc.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <string>

#include "demo_navigation.h"
#include "executive_test_support.h"
#include "spott_ros/testing/node_process.h"

namespace {

using spott_launch::testing::Truth;
using spott_launch::testing::WaitUntil;
using NavigateClient = actionlib::SimpleActionClient<spott_msgs::NavigateAction>;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The refusal counts every node publishes on /diagnostics ("<node>: input", "topic field" ->
// "count: reason"), the estimate, and every /cmd_vel that was not finite.
class Watch {
 public:
  explicit Watch(ros::NodeHandle& nh)
      : diagnostics_(nh.subscribe("/diagnostics", 50, &Watch::OnDiagnostics, this)),
        pose_(nh.subscribe("/amcl_pose", 5, &Watch::OnPose, this)),
        cmd_(nh.subscribe("/cmd_vel", 100, &Watch::OnCmd, this)) {}
  std::uint64_t Refused(const std::string& node, const std::string& cause) {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = counts_.find(node + ": input/" + cause);
    return it == counts_.end() ? 0 : it->second;
  }
  std::string Reason(const std::string& node, const std::string& cause) {
    std::lock_guard<std::mutex> lock(mutex_);
    return reasons_[node + ": input/" + cause];
  }
  bool EstimateNear(const Truth& truth, double m) {
    std::lock_guard<std::mutex> lock(mutex_);
    return have_pose_ && truth.DistanceTo(x_, y_) < m;
  }
  double EstimateError(const Truth& truth) {
    std::lock_guard<std::mutex> lock(mutex_);
    return have_pose_ ? truth.DistanceTo(x_, y_) : kNaN;
  }
  int non_finite_cmd() const { return non_finite_cmd_; }
  int cmds() const { return cmds_; }

 private:
  void OnDiagnostics(const diagnostic_msgs::DiagnosticArray& a) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& s : a.status) {
      for (const auto& kv : s.values) {
        counts_[s.name + "/" + kv.key] = std::stoull(kv.value);
        reasons_[s.name + "/" + kv.key] = kv.value;
      }
    }
  }
  void OnPose(const geometry_msgs::PoseWithCovarianceStamped& m) {
    std::lock_guard<std::mutex> lock(mutex_);
    x_ = m.pose.pose.position.x;
    y_ = m.pose.pose.position.y;
    have_pose_ = std::isfinite(x_) && std::isfinite(y_);
  }
  void OnCmd(const geometry_msgs::Twist& t) {
    ++cmds_;
    if (!std::isfinite(t.linear.x) || !std::isfinite(t.angular.z)) ++non_finite_cmd_;
  }
  std::mutex mutex_;
  std::map<std::string, std::uint64_t> counts_;
  std::map<std::string, std::string> reasons_;
  double x_ = kNaN, y_ = kNaN;
  bool have_pose_ = false;
  std::atomic<int> non_finite_cmd_{0}, cmds_{0};
  ros::Subscriber diagnostics_, pose_, cmd_;
};

// How many nodes the master lists as subscribers of `topic` (getSystemState).
int MasterSubscribers(const std::string& topic) {
  XmlRpc::XmlRpcValue args, result, payload;
  args[0] = ros::this_node::getName();
  if (!ros::master::execute("getSystemState", args, result, payload, false)) return 0;
  XmlRpc::XmlRpcValue& subscribed = payload[1];
  for (int i = 0; i < subscribed.size(); ++i)
    if (static_cast<std::string>(subscribed[i][0]) == topic) return subscribed[i][1].size();
  return 0;
}

// A publisher connected to every subscriber the master knows of (at least `subscribers`): a
// message sent when only the first of them had connected is lost to the others. /map_updates
// has three (world_server, global_planner, markov_localization) and the test waited for one:
// the likely cause of a CI run where world_server never refused the absurd feature.
template <class Msg>
ros::Publisher Advertise(ros::NodeHandle& nh, const std::string& topic, int subscribers = 1) {
  ros::Publisher pub = nh.advertise<Msg>(topic, 10);
  WaitUntil(
      [&] {
        const int n = static_cast<int>(pub.getNumSubscribers());
        return n >= subscribers && n >= MasterSubscribers(topic);
      },
      20.0);
  return pub;
}

class BadInput : public spott_launch::testing::StackTest {
 protected:
  static void SetUpTestSuite() {
    StackTest::SetUpTestSuite();
    watch_ = new Watch(*nh_);
  }
  static void TearDownTestSuite() {
    spinner_->stop();
    delete watch_;
    StackTest::TearDownTestSuite();
  }
  // Refusal counts rise at the next diagnostics period (1 s, simulated).
  static bool WaitRefused(const std::string& node, const std::string& cause, std::uint64_t above) {
    return WaitUntil([&] { return watch_->Refused(node, cause) > above; }, 10.0);
  }
  static inline Watch* watch_ = nullptr;
};

TEST_F(BadInput, TheRobotIsLocalizedAtTheStart) {
  ASSERT_TRUE(WaitUntil([] { return truth_->seen() && watch_->EstimateNear(*truth_, 0.5); }, 60.0))
      << "estimate " << watch_->EstimateError(*truth_) << " m from the truth";
}

// A NaN /initialpose moved a robot at (1.2, 8.25) to its mirror pose 27.5 m away, certain.
TEST_F(BadInput, ANonFiniteOrWrongFrameInitialPoseIsRefusedAndTheEstimateStays) {
  auto pub = Advertise<geometry_msgs::PoseWithCovarianceStamped>(*nh_, "/initialpose");
  const auto before = watch_->Refused("markov_localization", "initialpose pose.pose");
  geometry_msgs::PoseWithCovarianceStamped p;
  p.header.frame_id = "map";
  p.pose.pose.position.x = kNaN;
  p.pose.pose.position.y = 8.25;
  p.pose.pose.orientation.w = 1.0;
  pub.publish(p);
  ASSERT_TRUE(WaitRefused("markov_localization", "initialpose pose.pose", before));
  // One at a time: the node's queue on /initialpose holds one message.
  p.pose.pose.position.x = 20.0;  // finite, but a quaternion of zeros has no yaw
  p.pose.pose.orientation.w = 0.0;
  pub.publish(p);
  ASSERT_TRUE(WaitRefused("markov_localization", "initialpose pose.pose", before + 1));
  p.pose.pose.orientation.w = 1.0;  // finite and real, but in the odometry's frame
  p.header.frame_id = "odom";
  pub.publish(p);
  ASSERT_TRUE(WaitRefused("markov_localization", "initialpose header.frame_id", 0));
  ros::Duration(3.0).sleep();
  EXPECT_TRUE(watch_->EstimateNear(*truth_, 0.5))
      << "estimate " << watch_->EstimateError(*truth_) << " m from the truth";
}

// NaN odometry and impossible sonar ranges (negative, 1e9 m on a 6.5 m sonar).
TEST_F(BadInput, NonFiniteOdometryAndImpossibleRangesAreRefusedAndTheEstimateStays) {
  spott_ros::testing::Latest<spott_msgs::RangeRing> ring(*nh_, "/sonar");
  ASSERT_TRUE(ring.WaitFor([](const auto& r) { return !r.ranges.empty(); }, 20.0));
  auto odom_pub = Advertise<nav_msgs::Odometry>(*nh_, "/odom", 2);
  auto sonar_pub = Advertise<spott_msgs::RangeRing>(*nh_, "/sonar", 2);
  const auto odom_before = watch_->Refused("markov_localization", "odom pose.pose");
  const auto sonar_before = watch_->Refused("markov_localization", "sonar ranges");
  nav_msgs::Odometry o;
  o.header.stamp = ros::Time::now();
  o.header.frame_id = "odom";
  o.pose.pose.position.x = kNaN;
  o.pose.pose.orientation.w = 1.0;
  spott_msgs::RangeRing bad = *ring.msg();
  for (std::size_t i = 0; i < bad.ranges.size(); ++i) bad.ranges[i] = i % 2 ? -1.0f : 1e9f;
  for (int k = 0; k < 20; ++k) {  // two seconds of both
    o.header.stamp = bad.header.stamp = ros::Time::now();
    odom_pub.publish(o);
    sonar_pub.publish(bad);
    ros::Duration(0.1).sleep();
  }
  EXPECT_TRUE(WaitRefused("markov_localization", "odom pose.pose", odom_before));
  EXPECT_TRUE(WaitRefused("harmonic_planner", "odom pose.pose", 0));
  EXPECT_TRUE(WaitRefused("markov_localization", "sonar ranges", sonar_before));
  ros::Duration(3.0).sleep();
  EXPECT_TRUE(watch_->EstimateNear(*truth_, 0.5))
      << "estimate " << watch_->EstimateError(*truth_) << " m from the truth";
}

// An empty MapFeatureArray replaced the harmonic planner's walls (the next leg pushed into a
// wall for 120 s); an empty RoomDoorGraph left the global planner nothing to plan in. The leg
// after them goes through d_201 into office 201: it needs both the walls and the graph.
TEST_F(BadInput, EmptyFeaturesAndGraphAreRefusedAndTheNextLegGoesThroughTheDoor) {
  auto features = Advertise<spott_msgs::MapFeatureArray>(*nh_, "/map_features", 2);
  auto graph = Advertise<spott_msgs::RoomDoorGraph>(*nh_, "/room_door_graph", 2);
  spott_msgs::MapFeatureArray no_features;
  no_features.header.frame_id = "map";
  spott_msgs::RoomDoorGraph no_graph;
  no_graph.header.frame_id = "map";
  features.publish(no_features);
  graph.publish(no_graph);
  EXPECT_TRUE(WaitRefused("harmonic_planner", "map_features features", 0));
  EXPECT_TRUE(WaitRefused("harmonic_planner", "room_door_graph rooms", 0));
  EXPECT_TRUE(WaitRefused("global_planner", "map_features features", 0));
  EXPECT_TRUE(WaitRefused("global_planner", "room_door_graph rooms", 0));

  NavigateClient client("harmonic_planner/navigate", true);
  ASSERT_TRUE(client.waitForServer(ros::Duration(30.0)));
  truth_->ResetContacts();
  client.sendGoal(spott_launch::NavigateGoalTo(spott_map::Pose2{2.5, 11.5, 0.0}, true));
  ASSERT_TRUE(client.waitForResult(ros::Duration(150.0)));
  EXPECT_EQ(client.getResult()->outcome, spott_msgs::NavigateResult::SUCCEEDED)
      << client.getResult()->reason;
  // In office 201, not short of its door (over 1 m away): Navigate's 0.2 m on the estimate plus
  // the localization's error in an office (up to 0.2 m; 0.3 failed once at 0.300279 m, CI of
  // 2026-12-05).
  EXPECT_LT(truth_->DistanceTo(2.5, 11.5), 0.4);
  EXPECT_EQ(truth_->contacts(), 0);
}

// A 1e9 m feature was accepted into the map database and republished to every copy.
TEST_F(BadInput, AnAbsurdFeatureInAMapUpdateIsRefusedAndNotRepublished) {
  auto updates = Advertise<spott_msgs::MapUpdate>(*nh_, "/map_updates", 1);
  spott_msgs::MapUpdate u;
  u.header.frame_id = "map";
  u.header.stamp = ros::Time::now();
  spott_msgs::MapFeature f;
  f.id = "absurd";
  f.type = spott_msgs::MapFeature::RECTANGLE;
  f.source = spott_msgs::MapFeature::SOURCE_SENSED;
  f.pose.position.x = 3.0;
  f.pose.position.y = 8.0;
  f.pose.orientation.w = 1.0;
  f.size.x = f.size.y = 1e9;
  f.size.z = 1.0;
  u.added.push_back(f);
  updates.publish(u);
  EXPECT_TRUE(WaitRefused("world_server", "map_updates update", 0));
  spott_ros::testing::Latest<spott_msgs::MapFeatureArray> served(*nh_, "/map_features");
  ASSERT_TRUE(served.WaitFor([](const auto& m) { return !m.features.empty(); }, 10.0));
  for (const auto& g : served.msg()->features) EXPECT_NE(g.id, "absurd");
  EXPECT_NE(watch_->Reason("world_server", "map_updates update").find("size over 1 km"),
            std::string::npos)
      << watch_->Reason("world_server", "map_updates update");
}

// Each bad goal ends at once (FAILED with the reason), and the robot does not move.
TEST_F(BadInput, BadNavigateGoalsEndAtOnceWithTheReasonAndTheRobotStays) {
  NavigateClient client("harmonic_planner/navigate", true);
  ASSERT_TRUE(client.waitForServer(ros::Duration(30.0)));
  struct Case {
    const char* what;
    spott_msgs::NavigateGoal goal;
    const char* reason;
  };
  std::vector<Case> cases;
  auto g = spott_launch::NavigateGoalTo(spott_map::Pose2{2.5, 12.5, 0.0}, false);
  g.target.pose.orientation.z = kNaN;  // a NaN quaternion with the heading asked for
  cases.push_back({"NaN quaternion", g, "orientation"});
  g = spott_launch::NavigateGoalTo(spott_map::Pose2{100.0, 100.0, 0.0}, true);
  cases.push_back({"outside the map", g, "outside every room"});
  g = spott_launch::NavigateGoalTo(spott_map::Pose2{1e300, 1e300, 0.0}, true);
  cases.push_back({"1e300 m", g, "outside every room"});
  g = spott_launch::NavigateGoalTo(spott_map::Pose2{2.5, 12.5, 0.0}, true);
  g.position_tolerance = std::numeric_limits<double>::infinity();
  cases.push_back({"infinite tolerance", g, "tolerance"});
  g = spott_launch::NavigateGoalTo(spott_map::Pose2{kNaN, 12.5, 0.0}, true);
  cases.push_back({"NaN position", g, "finite"});
  for (const Case& c : cases) {
    double x0, y0, yaw0;
    truth_->Pose(&x0, &y0, &yaw0);
    const ros::WallTime sent = ros::WallTime::now();
    client.sendGoal(c.goal);
    ASSERT_TRUE(client.waitForResult(ros::Duration(10.0))) << c.what;
    EXPECT_LT((ros::WallTime::now() - sent).toSec(), 2.0) << c.what << ": not at once";
    const auto r = client.getResult();
    EXPECT_EQ(r->outcome, spott_msgs::NavigateResult::FAILED) << c.what;
    EXPECT_NE(r->reason.find(c.reason), std::string::npos) << c.what << ": " << r->reason;
    ros::Duration(1.0).sleep();
    EXPECT_LT(truth_->DistanceTo(x0, y0), 0.05) << c.what << ": the robot moved";
  }
  EXPECT_GE(watch_->Refused("harmonic_planner", "~navigate goal"), cases.size());
}

// A burst of NaN and over-limit commands from a source: refused by the arbiter, never on the
// wheels; and through the whole test nothing non-finite was on /cmd_vel.
TEST_F(BadInput, NonFiniteCommandsNeverReachTheWheels) {
  auto teleop = Advertise<geometry_msgs::Twist>(*nh_, "/cmd_vel/teleop", 1);
  geometry_msgs::Twist t;
  for (int k = 0; k < 20; ++k) {
    t.linear.x = k % 2 ? kNaN : 1e9;
    t.angular.z = k % 3 ? kNaN : 0.0;
    teleop.publish(t);
    ros::Duration(0.05).sleep();
  }
  EXPECT_TRUE(WaitRefused("cmd_vel_arbiter", "cmd_vel/teleop linear.x/angular.z", 0));
  EXPECT_GT(watch_->cmds(), 0);
  EXPECT_EQ(watch_->non_finite_cmd(), 0);
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "bad_input_rostest");
  const int failed = RUN_ALL_TESTS();
  ros::shutdown();
  return failed;
}
