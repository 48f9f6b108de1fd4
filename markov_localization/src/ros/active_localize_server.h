// The ActiveLocalize action of the node (spott_msgs/ActiveLocalize): actionlib glue around the
// core's ActiveLocalizationRun (sequencing), Wanderer (the random motion) and ActiveLocalizer
// (a*). The node calls Update after every localization update; all decisions are the core's,
// this class only turns them into cmd_vel, Navigate goals, feedback and the result.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <actionlib/client/simple_action_client.h>
#include <actionlib/server/simple_action_server.h>
#include <ros/ros.h>
#include <spott_msgs/ActiveLocalizeAction.h>
#include <spott_msgs/NavigateAction.h>

#include "markov_localization/active_localization.h"
#include "markov_localization/active_run.h"
#include "markov_localization/ros/parameters.h"
#include "markov_localization/wander.h"
#include "spott_ros/goal_resend.h"

namespace markov_localization {

/// What one localization update tells the action.
struct LocalizationUpdate {
  ros::Time stamp;
  double certainty = 0.0;
  double entropy = 0.0;
  Pose2 estimate;     ///< The published estimate (sticky: see sticky_estimate.h), map frame.
  Pose2 best;         ///< The refined pose at the global maximum (POS-CERTAINTY's).
  Pose2 map_to_odom;  ///< the transform published with it
  Pose2 odom;         ///< odometry pose of the robot
  double odom_distance_m = 0.0;
  const std::vector<Mode>* modes = nullptr;
  const ActiveLocalizer* localizer = nullptr;
  const MapModel* map = nullptr;
  const std::vector<double>* beam_angles_rad = nullptr;  ///< relative to the heading
  const std::vector<double>* ranges_m = nullptr;
  double max_range_m = 0.0;
};

class ActiveLocalizeServer {
 public:
  /// `reset_uniform` sets the belief to uniform (for start_uniform requests).
  ActiveLocalizeServer(ros::NodeHandle& nh, const NodeParameters& params,
                       std::function<void()> reset_uniform);
  ~ActiveLocalizeServer();

  /// A goal is being served (status mode ACTIVE).
  bool active() { return server_.isActive(); }
  void Update(const LocalizationUpdate& u);

 private:
  using NavClient = actionlib::SimpleActionClient<spott_msgs::NavigateAction>;
  void OnGoal();
  void OnPreempt();
  void OnNavigationDone(int generation, const actionlib::SimpleClientGoalState& state,
                        const spott_msgs::NavigateResultConstPtr& result);
  void Choose(const LocalizationUpdate& u, const RunInput& in);
  void CancelNavigation();
  /// Sends nav_goal_ for generation_ (again, when actionlib lost it).
  void PublishNavigate();
  void StopMotion();
  void Finish(bool success, std::string reason, const LocalizationUpdate& u);
  RunInput InputOf(const LocalizationUpdate& u) const;

  NodeParameters params_;
  std::function<void()> reset_uniform_;
  actionlib::SimpleActionServer<spott_msgs::ActiveLocalizeAction> server_;
  std::unique_ptr<NavClient> nav_;
  ros::Publisher cmd_pub_;
  std::optional<ActiveRequest> request_;
  std::optional<ActiveLocalizationRun> run_;
  std::unique_ptr<Wanderer> wanderer_;
  std::uint64_t runs_ = 0;
  int generation_ = 0;  ///< Of the Navigate goal in flight; stale results are ignored.
  spott_msgs::NavigateGoal nav_goal_;  ///< The goal in flight, kept to send it again.
  spott_ros::GoalAckWatch nav_ack_;
  bool navigating_ = false;
  bool wandering_ = false;
  RunInput last_input_;
  spott_msgs::ActiveLocalizeFeedback feedback_;
};

}  // namespace markov_localization
