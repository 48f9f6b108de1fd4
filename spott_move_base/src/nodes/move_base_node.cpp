// move_base: the stack seen as move_base (move_base_msgs/MoveBase at /move_base and
// /move_base_simple/goal), so rviz's "2D Nav Goal" and any script written for move_base drive
// it unchanged. Every goal becomes a Navigate goal of the harmonic planner (the stack's one way
// to send the robot somewhere); its feedback's pose is move_base's base_position, its outcome
// move_base's terminal state with the reason as text. A new goal preempts the running one, as
// in move_base; so does a /move_base_simple/goal (sent to this server, like move_base does).
#include <actionlib/client/simple_action_client.h>
#include <actionlib/server/simple_action_server.h>
#include <geometry_msgs/PoseStamped.h>
#include <move_base_msgs/MoveBaseAction.h>
#include <ros/ros.h>

#include <spott_msgs/NavigateAction.h>
#include <atomic>

#include "spott_move_base/conversions.h"
#include "spott_move_base/parameters.h"
#include "spott_ros/goal_resend.h"
#include "spott_ros/parameter_reader.h"

namespace spott_move_base {
namespace {

using NavigateClient = actionlib::SimpleActionClient<spott_msgs::NavigateAction>;
using MoveBaseServer = actionlib::SimpleActionServer<move_base_msgs::MoveBaseAction>;
using MoveBaseClient = actionlib::SimpleActionClient<move_base_msgs::MoveBaseAction>;

class MoveBaseNode {
 public:
  MoveBaseNode(ros::NodeHandle& nh, const NodeParameters& p)
      : params_(p),
        navigate_(nh, p.navigate_action, true),
        server_(nh, "move_base", false),
        self_(nh, "move_base", true) {
    server_.registerGoalCallback([this] { OnGoal(); });
    server_.registerPreemptCallback([this] { OnPreempt(); });
    server_.start();
    simple_sub_ = nh.subscribe("move_base_simple/goal", 1, &MoveBaseNode::OnSimpleGoal, this);
    ack_timer_ = nh.createSteadyTimer(
        ros::WallDuration(0.5), [this](const ros::SteadyTimerEvent&) { CheckAcknowledged(); });
    ROS_INFO("move_base: /move_base and /move_base_simple/goal map onto %s",
             p.navigate_action.c_str());
  }

 private:
  void OnGoal() {
    const auto goal = server_.acceptNewGoal();
    if (!navigate_.isServerConnected() &&
        !navigate_.waitForServer(ros::Duration(params_.server_timeout_s))) {
      server_.setAborted(move_base_msgs::MoveBaseResult(),
                         "the Navigate server " + params_.navigate_action + " is not offered");
      return;
    }
    ++generation_;
    navigate_goal_ = ToNavigateGoal(*goal);
    PublishNavigate();
  }

  // Sends navigate_goal_ (again, when actionlib lost it: spott_ros/goal_ack_watch.h).
  void PublishNavigate() {
    const int generation = generation_;
    spott_ros::MarkGoalSent(ack_watch_);
    navigate_.sendGoal(
        navigate_goal_,
        [this, generation](const actionlib::SimpleClientGoalState&,
                           const spott_msgs::NavigateResultConstPtr& result) {
          OnDone(generation, result);
        },
        NavigateClient::SimpleActiveCallback(),
        [this](const spott_msgs::NavigateFeedbackConstPtr& fb) {
          move_base_msgs::MoveBaseFeedback f;
          f.base_position = fb->current_pose;
          if (server_.isActive()) server_.publishFeedback(f);
        });
  }

  void OnDone(int generation, const spott_msgs::NavigateResultConstPtr& result) {
    if (generation != generation_ || !server_.isActive()) return;  // an older goal's end
    const move_base_msgs::MoveBaseResult r;
    if (!result) {
      server_.setAborted(r, "the Navigate goal ended without a result");
      return;
    }
    const std::string text = TextOf(*result);
    switch (EndOf(*result)) {
      case MoveBaseEnd::kSucceeded:
        server_.setSucceeded(r, text);
        break;
      case MoveBaseEnd::kPreempted:
        server_.setPreempted(r, text);
        break;
      case MoveBaseEnd::kAborted:
        ROS_WARN("move_base: goal aborted: %s", text.c_str());
        server_.setAborted(r, text);
        break;
    }
  }

  void CheckAcknowledged() {
    if (!server_.isActive()) {
      ack_watch_.Stop();
      return;
    }
    if (spott_ros::GoalLostInTransport(ack_watch_, navigate_, "move_base",
                                       params_.navigate_action)) {
      PublishNavigate();
    }
  }

  void OnPreempt() {
    ++generation_;  // the Navigate goal's late end is not this goal's
    ack_watch_.Stop();
    navigate_.cancelGoal();
    server_.setPreempted(move_base_msgs::MoveBaseResult(), "preempted");
  }

  // rviz's "2D Nav Goal": sent to this very server, as move_base does.
  void OnSimpleGoal(const geometry_msgs::PoseStamped& pose) {
    move_base_msgs::MoveBaseGoal goal;
    goal.target_pose = pose;
    self_.sendGoal(goal);
  }

  NodeParameters params_;
  NavigateClient navigate_;
  MoveBaseServer server_;
  MoveBaseClient self_;
  ros::Subscriber simple_sub_;
  ros::SteadyTimer ack_timer_;
  spott_msgs::NavigateGoal navigate_goal_;  ///< The running goal, kept to send it again.
  spott_ros::GoalAckWatch ack_watch_;
  std::atomic<int> generation_{0};
};

}  // namespace
}  // namespace spott_move_base

int main(int argc, char** argv) {
  ros::init(argc, argv, "move_base");
  ros::NodeHandle nh, pnh("~");
  const auto params = spott_ros::ReadNodeParameters<spott_move_base::NodeParameters>(
      pnh, "move_base", spott_move_base::Read);
  if (!params) return 1;
  spott_move_base::MoveBaseNode node(nh, *params);
  ros::spin();
  return 0;
}
