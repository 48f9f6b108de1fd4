#include "active_localize_server.h"

#include <geometry_msgs/Twist.h>

#include "markov_localization/navigable_target.h"
#include "markov_localization/ros/conversions.h"

#include <cstdio>

namespace markov_localization {

namespace conv = ros_conversions;

ActiveLocalizeServer::ActiveLocalizeServer(ros::NodeHandle& nh, const NodeParameters& params,
                                           std::function<void()> reset_uniform)
    : params_(params),
      reset_uniform_(std::move(reset_uniform)),
      server_(nh, "active_localize", false) {
  nav_ = std::make_unique<NavClient>(nh, params.navigate_action, false);
  cmd_pub_ = nh.advertise<geometry_msgs::Twist>(params.cmd_vel_topic, 1);
  server_.registerGoalCallback([this] { OnGoal(); });
  server_.registerPreemptCallback([this] { OnPreempt(); });
  server_.start();
}

ActiveLocalizeServer::~ActiveLocalizeServer() {
  if (server_.isActive()) {
    CancelNavigation();
    StopMotion();
  }
}

RunInput ActiveLocalizeServer::InputOf(const LocalizationUpdate& u) const {
  RunInput in;
  in.now_s = u.stamp.toSec();
  in.certainty = u.certainty;
  in.odom_distance_m = u.odom_distance_m;
  in.map_to_odom = u.map_to_odom;
  in.odom = u.odom;
  return in;
}

void ActiveLocalizeServer::OnGoal() {
  // A new goal while one runs: actionlib preempts the old one; stop what it was doing.
  if (run_) {
    CancelNavigation();
    StopMotion();
    run_.reset();
  }
  const auto goal = server_.acceptNewGoal();
  ActiveRequest request;
  request.certainty_threshold = goal->certainty_threshold;
  request.timeout_s = goal->timeout;
  request.start_uniform = goal->start_uniform;
  const std::string refused = CheckRequest(request);
  if (!refused.empty()) {
    spott_msgs::ActiveLocalizeResult result;
    result.success = false;
    result.reason = "refused: " + refused;
    ROS_WARN("markov_localization: ActiveLocalize %s", result.reason.c_str());
    server_.setAborted(result, result.reason);
    return;
  }
  if (request.start_uniform) reset_uniform_();
  request_ = request;
  feedback_ = spott_msgs::ActiveLocalizeFeedback();
  ROS_INFO("markov_localization: ActiveLocalize accepted (threshold %.2f, timeout %.0f s%s)",
           EffectiveThreshold(request, params_.certainty.threshold), request.timeout_s,
           request.start_uniform ? ", uniform start" : "");
}

void ActiveLocalizeServer::OnPreempt() {
  if (!server_.isActive()) return;
  CancelNavigation();
  StopMotion();
  spott_msgs::ActiveLocalizeResult result;
  result.success = false;
  result.reason = "preempted";
  if (run_) result.targets_visited = run_->targets_visited();
  result.certainty = feedback_.certainty;
  run_.reset();
  request_.reset();
  server_.setPreempted(result, result.reason);
  ROS_INFO("markov_localization: ActiveLocalize preempted");
}

void ActiveLocalizeServer::CancelNavigation() {
  if (!navigating_) return;
  ++generation_;  // its result, if any comes, is stale
  navigating_ = false;
  nav_ack_.Stop();
  nav_->cancelGoal();
}

void ActiveLocalizeServer::PublishNavigate() {
  const int generation = generation_;
  spott_ros::MarkGoalSent(nav_ack_);
  nav_->sendGoal(nav_goal_, [this, generation](const actionlib::SimpleClientGoalState& state,
                                               const spott_msgs::NavigateResultConstPtr& result) {
    OnNavigationDone(generation, state, result);
  });
}

void ActiveLocalizeServer::StopMotion() {
  if (!wandering_) return;
  wandering_ = false;
  cmd_pub_.publish(geometry_msgs::Twist());
}

void ActiveLocalizeServer::OnNavigationDone(int generation,
                                            const actionlib::SimpleClientGoalState& state,
                                            const spott_msgs::NavigateResultConstPtr& result) {
  if (generation != generation_ || !run_) return;
  navigating_ = false;
  const bool reached = result && result->outcome == spott_msgs::NavigateResult::SUCCEEDED &&
                       state == actionlib::SimpleClientGoalState::SUCCEEDED;
  std::string reason = result && !result->reason.empty() ? result->reason : state.getText();
  if (reason.empty()) reason = state.toString();
  ROS_INFO("markov_localization: target %s%s%s", reached ? "reached" : "not reached",
           reached ? "" : ": ", reached ? "" : reason.c_str());
  run_->OnNavigationDone(reached, reason, last_input_);
}

void ActiveLocalizeServer::Choose(const LocalizationUpdate& u, const RunInput& in) {
  StopMotion();
  if (!nav_->isServerConnected()) {
    Finish(false, "navigation action '" + params_.navigate_action + "' is not served", u);
    return;
  }
  if (u.modes->empty()) {
    Finish(false,
           "the belief has no modes to choose a target from (still nearly uniform after the "
           "random motion)",
           u);
    return;
  }
  const ActiveChoice choice = u.localizer->Choose(*u.modes);
  // a* is relative to the robot; the planner drives by tf, i.e. by the published estimate. The
  // point sent is the nearest one outside the planner's padding.
  const Vec2 a_star = TargetInWorld(u.estimate, choice.ax, choice.ay);
  std::optional<Vec2> navigable;
  if (choice.found)
    navigable =
        NavigableTarget(*u.map, a_star, params_.target_clearance_m, params_.target_search_m);
  if (choice.found && !navigable) {
    char text[128];
    std::snprintf(text, sizeof(text), "no point with %.2f m clearance within %.2f m of a*",
                  params_.target_clearance_m, params_.target_search_m);
    ROS_INFO("markov_localization: a* = (%.2f, %.2f): %s", a_star.x(), a_star.y(), text);
    run_->OnChoice(true, choice.ax, choice.ay, in);
    if (run_->phase() == RunPhase::kNavigate) run_->OnNavigationDone(false, text, in);
    return;
  }
  // The target relative to the robot, after the shift (what the robot will really drive).
  double ahead = choice.ax, left = choice.ay;
  if (navigable) {
    const double c = std::cos(u.estimate.yaw), s = std::sin(u.estimate.yaw);
    const double dx = navigable->x() - u.estimate.x, dy = navigable->y() - u.estimate.y;
    ahead = c * dx + s * dy;
    left = -s * dx + c * dy;
  }
  run_->OnChoice(choice.found, ahead, left, in);
  if (run_->phase() != RunPhase::kNavigate) {
    if (run_->phase() == RunPhase::kWander) {
      ROS_INFO(
          "markov_localization: a* = (%.2f ahead, %.2f left) is where the robot stands; "
          "random motion again",
          choice.ax, choice.ay);
      wandering_ = true;
    }
    return;
  }
  const Vec2 target = *navigable;
  feedback_.target.x = target.x();
  feedback_.target.y = target.y();
  feedback_.target_relative.x = choice.ax;
  feedback_.target_relative.y = choice.ay;
  feedback_.expected_entropy = choice.expected_entropy;
  feedback_.expected_cost = choice.cost;
  ++generation_;
  navigating_ = true;
  nav_goal_ =
      conv::NavigateGoalTo(target, params_.position_tolerance_m, params_.map_frame, u.stamp);
  PublishNavigate();
  ROS_INFO(
      "markov_localization: a* = (%.2f ahead, %.2f left) -> (%.2f, %.2f) in %s; E[H] %.3f, "
      "v %.3f, %zu modes",
      choice.ax, choice.ay, target.x(), target.y(), params_.map_frame.c_str(),
      choice.expected_entropy, choice.cost, u.modes->size());
}

void ActiveLocalizeServer::Finish(bool success, std::string reason, const LocalizationUpdate& u) {
  CancelNavigation();
  StopMotion();
  spott_msgs::ActiveLocalizeResult result;
  result.success = success;
  result.reason = reason;
  result.certainty = u.certainty;
  result.estimate.x = u.best.x;
  result.estimate.y = u.best.y;
  result.estimate.theta = u.best.yaw;
  result.targets_visited = run_ ? run_->targets_visited() : 0;
  run_.reset();
  request_.reset();
  if (success) {
    ROS_INFO(
        "markov_localization: ActiveLocalize succeeded: certainty %.3f at (%.2f, %.2f, %.1f "
        "deg), %u targets",
        u.certainty, u.estimate.x, u.estimate.y, u.estimate.yaw * 180.0 / M_PI,
        result.targets_visited);
    server_.setSucceeded(result, "certain");
  } else {
    ROS_WARN("markov_localization: ActiveLocalize gave up: %s", reason.c_str());
    server_.setAborted(result, reason);
  }
}

void ActiveLocalizeServer::Update(const LocalizationUpdate& u) {
  if (!server_.isActive() || !request_ || !u.localizer || !u.modes) return;
  const RunInput in = InputOf(u);
  last_input_ = in;
  if (navigating_ && spott_ros::GoalLostInTransport(nav_ack_, *nav_, "markov_localization",
                                                    params_.navigate_action)) {
    PublishNavigate();
  }
  if (!run_) {
    // From a uniform belief (or one without modes) the paper's random motion comes first.
    const bool random_first = request_->start_uniform || u.modes->empty();
    run_.emplace(params_.run, EffectiveThreshold(*request_, params_.certainty.threshold),
                 request_->timeout_s, random_first, in);
    wanderer_ = std::make_unique<Wanderer>(params_.wander, params_.seed + runs_++);
    ROS_INFO("markov_localization: ActiveLocalize starts with %s", ToString(run_->phase()));
  }
  switch (run_->Step(in)) {
    case RunAction::kWander: {
      const WanderCommand c = wanderer_->Step(*u.beam_angles_rad, *u.ranges_m, u.max_range_m,
                                              u.odom.x, u.odom.y, u.odom.yaw);
      geometry_msgs::Twist t;
      t.linear.x = c.linear_mps;
      t.angular.z = c.angular_rps;
      cmd_pub_.publish(t);
      wandering_ = true;
      break;
    }
    case RunAction::kCancelAndChoose:
      ROS_INFO(
          "markov_localization: re-choosing (map->odom now %.2f %.2f %.0f deg; estimate "
          "jumped or target timed out)",
          u.map_to_odom.x, u.map_to_odom.y, u.map_to_odom.yaw * 180 / M_PI);
      CancelNavigation();
      Choose(u, in);
      break;
    case RunAction::kChoose:
      Choose(u, in);
      break;
    case RunAction::kWait:
      break;
    case RunAction::kSucceed:
      Finish(true, "", u);
      return;
    case RunAction::kAbort:
      Finish(false, run_->reason(), u);
      return;
  }
  if (!run_) return;  // Choose finished it
  if (run_->phase() == RunPhase::kAborted) {
    Finish(false, run_->reason(), u);
    return;
  }
  feedback_.certainty = u.certainty;
  feedback_.entropy = u.entropy;
  feedback_.num_modes = u.modes->size();
  server_.publishFeedback(feedback_);
}

}  // namespace markov_localization
