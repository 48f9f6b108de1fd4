// harmonic_planner: SPOTT's local dynamic path planner (III.D.1) as a ROS node, and the stack's
// Navigate server: the one way every client sends the robot to a pose. Glue only: reads and
// validates parameters, feeds the core LocalPlanner from topics and tf, runs its cycle on a
// timer, and drives a NavigateSession (navigate_session.h) for the running goal.
//
// Subscribes: map_features (spott_msgs/MapFeatureArray), room_door_graph
// (spott_msgs/RoomDoorGraph), projected_goal (spott_msgs/ProjectedGoal), global_plan_status
// (spott_msgs/GlobalPlanStatus), odom (nav_msgs/Odometry), bumper (spott_msgs/BumperRing).
// tf: map -> base_link. Action: ~navigate (spott_msgs/Navigate).
// Publishes: global_goal (spott_msgs/GlobalGoal, latched: the target handed to the global
// planner), ~cmd_vel (geometry_msgs/Twist, the arbiter's planner input), local_window
// (latched), ~status, ~steering, ~potential (latched), ~contours, ~path.
#include <actionlib/server/simple_action_server.h>
#include <geometry_msgs/PolygonStamped.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <spott_msgs/BumperRing.h>
#include <spott_msgs/GlobalGoal.h>
#include <spott_msgs/GlobalPlanStatus.h>
#include <spott_msgs/LocalizationStatus.h>
#include <spott_msgs/MapFeatureArray.h>
#include <spott_msgs/NavigateAction.h>
#include <spott_msgs/ProjectedGoal.h>
#include <spott_msgs/RoomDoorGraph.h>
#include <tf2_ros/transform_listener.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include "spott_harmonic_planner/contact_memory.h"
#include "spott_harmonic_planner/navigate_session.h"
#include "spott_harmonic_planner/ros/conversions.h"
#include "spott_harmonic_planner/ros/parameters.h"
#include "spott_map/ros/conversions.h"
#include "spott_ros/input_refusals.h"
#include "spott_ros/pose_conversions.h"
#include "spott_ros/robot_geometry.h"
#include "spott_ros/robot_pose.h"

namespace spott_harmonic_planner {

namespace conv = ros_conversions;
namespace mconv = spott_map::ros_conversions;

class HarmonicPlannerNode {
 public:
  HarmonicPlannerNode(ros::NodeHandle& nh, ros::NodeHandle& pnh, const NodeParameters& p)
      : params_(p),
        planner_(p.planner),
        contacts_(p.contact_memory_s, p.contact_size_m),
        server_(pnh, "navigate", false),
        listener_(tf_),
        refusals_(nh, "harmonic_planner") {
    cmd_pub_ = pnh.advertise<geometry_msgs::Twist>("cmd_vel", 1);
    goal_pub_ = nh.advertise<spott_msgs::GlobalGoal>("global_goal", 1, true);
    status_pub_ = pnh.advertise<spott_msgs::PotentialFieldStatus>("status", 1);
    window_pub_ = nh.advertise<geometry_msgs::PolygonStamped>("local_window", 1, true);
    steering_pub_ = pnh.advertise<spott_msgs::SteeringStatus>("steering", 1);
    potential_pub_ = pnh.advertise<nav_msgs::OccupancyGrid>("potential", 1, true);
    contours_pub_ = pnh.advertise<visualization_msgs::Marker>("contours", 1, true);
    path_pub_ = pnh.advertise<nav_msgs::Path>("path", 1);
    features_sub_ = nh.subscribe("map_features", 1, &HarmonicPlannerNode::OnFeatures, this);
    graph_sub_ = nh.subscribe("room_door_graph", 1, &HarmonicPlannerNode::OnGraph, this);
    projected_sub_ = nh.subscribe("projected_goal", 5, &HarmonicPlannerNode::OnProjected, this);
    plan_status_sub_ =
        nh.subscribe("global_plan_status", 5, &HarmonicPlannerNode::OnPlanStatus, this);
    odom_sub_ = nh.subscribe("odom", 10, &HarmonicPlannerNode::OnOdom, this);
    bumper_sub_ = nh.subscribe("bumper", 10, &HarmonicPlannerNode::OnBumper, this);
    if (!params_.localization_topic.empty())
      localization_sub_ =
          nh.subscribe(params_.localization_topic, 5, &HarmonicPlannerNode::OnLocalization, this);
    if (!params_.localization_status_topic.empty())
      status_sub_ = nh.subscribe(params_.localization_status_topic, 5,
                                 &HarmonicPlannerNode::OnLocalizationStatus, this);
    server_.registerGoalCallback([this] { OnGoal(); });
    server_.registerPreemptCallback([this] { OnPreempt(); });
    server_.start();
    timer_ =
        nh.createTimer(ros::Duration(1.0 / p.cycle_rate_hz), &HarmonicPlannerNode::Cycle, this);
  }

 private:
  // --- the map -------------------------------------------------------------------------------

  void OnFeatures(const spott_msgs::MapFeatureArray& msg) {
    if (msg.features.empty() && !db_.features().empty()) {
      // An empty array would remove every wall: a publisher clears features through MapUpdate.
      refusals_.Refuse("map_features", "features",
                       "an empty array would remove all " + std::to_string(db_.features().size()) +
                           " obstacles, walls included (remove features with a MapUpdate)");
      return;
    }
    if (!msg.header.frame_id.empty() && msg.header.frame_id != params_.frame_id) {
      refusals_.Refuse("map_features", "header.frame_id",
                       "'" + msg.header.frame_id + "' is not '" + params_.frame_id + "'");
      return;
    }
    spott_map::MapDatabase db;
    db.SetGraph(db_.graph());
    for (const auto& f : msg.features) {
      std::string error;
      const auto feature = mconv::FromMsg(f, &error);
      if (!feature) {  // the feature is left out, the others are kept
        refusals_.Refuse("map_features", "features[]", error);
        continue;
      }
      db.AddFeature(*feature);
    }
    db_ = db;
    ApplyMap();
  }

  void OnGraph(const spott_msgs::RoomDoorGraph& msg) {
    std::string error;
    auto graph = mconv::FromMsg(msg, &error);
    if (!graph) {
      refusals_.Refuse("room_door_graph", "rooms/doors", error);
      return;
    }
    if (graph->rooms().empty() && !db_.graph().rooms().empty()) {
      refusals_.Refuse("room_door_graph", "rooms", "an empty graph would replace the building's");
      return;
    }
    db_.SetGraph(*graph);
    ApplyMap();
  }

  // The served map plus the bumper contacts remembered as obstacles.
  void ApplyMap() {
    if (contacts_.size() == 0) {
      planner_.SetMap(db_);
      return;
    }
    spott_map::MapDatabase db = db_;
    for (const auto& f : contacts_.Features()) db.AddFeature(f);
    planner_.SetMap(db);
  }

  // --- the global planner's answers ----------------------------------------------------------

  void OnProjected(const spott_msgs::ProjectedGoal& msg) {
    if (!session_ || msg.goal_id != goal_id_) return;  // another goal's answer
    if (msg.on_border) {
      planner_.SetBorderGoal(
          {Vec2(msg.border_start.x, msg.border_start.y), Vec2(msg.border_end.x, msg.border_end.y)});
    } else {
      planner_.ClearBorderGoal();  // the way to the target lies inside the window
    }
    session_->ProjectionArrived();
  }

  void OnPlanStatus(const spott_msgs::GlobalPlanStatus& msg) {
    if (!session_ || msg.goal_id != goal_id_) return;
    GlobalAnswer a;
    a.message = msg.message;
    a.path_summary = msg.path_summary;
    switch (msg.state) {
      case spott_msgs::GlobalPlanStatus::PLANNED:
        a.state = GlobalAnswer::State::kPlanned;
        break;
      case spott_msgs::GlobalPlanStatus::FAILED:
        a.state = GlobalAnswer::State::kFailed;
        break;
      case spott_msgs::GlobalPlanStatus::REFUSED:
        a.state = GlobalAnswer::State::kRefused;
        break;
      default:
        return;
    }
    session_->Answer(a);
    if (session_->finished()) Finish();
  }

  // The localization's estimates (AMCL's amcl_pose: one per update, stamped with its reading):
  // an arrival is judged again on one of the standing robot (NavigateSession::Settled).
  void OnLocalization(const geometry_msgs::PoseWithCovarianceStamped& msg) {
    if (session_) session_->LocalizationUpdated(msg.header.stamp.toSec());
  }

  // Whether the localization is lost (spott_msgs/LocalizationStatus): no arrival is taken on an
  // estimate it does not trust. Its ActiveLocalize drives on the modes it chose: not lost then.
  void OnLocalizationStatus(const spott_msgs::LocalizationStatus& msg) {
    localization_lost_ = msg.lost && msg.mode != spott_msgs::LocalizationStatus::ACTIVE;
    if (session_) session_->LocalizationLost(localization_lost_);
  }

  // --- sensors -------------------------------------------------------------------------------

  void OnOdom(const nav_msgs::Odometry& msg) {
    const auto pose = spott_ros::ToPose2D(msg.pose.pose);
    if (!pose) {
      refusals_.Refuse("odom", "pose.pose", "not finite or no yaw in the quaternion");
      return;
    }
    odom_ = spott_map::Pose2{pose->x, pose->y, pose->theta};
    planner_.Odometry(odom_);
  }

  // A contact while driving: remembered as an obstacle, and the robot backs off (the arbiter
  // has already stopped the motion towards it) unless ~navigate/bumper_backoff is false: then
  // the TR+ controller owns the bumper (its reflex moves the robot away, its map records the
  // contact and takes it back before a retry; a copy kept here outlived that clearing and cut
  // the robot off beside a box in teleop_bumper.test).
  void OnBumper(const spott_msgs::BumperRing& ring) {
    if (!params_.bumper_backoff || !session_ || session_->phase() == NavigatePhase::kPlanning ||
        ring.pressed.size() != ring.segment_angles.size()) {
      return;
    }
    bool any = false;
    double angle = 0.0;
    const double now = ros::Time::now().toSec();
    for (std::size_t i = 0; i < ring.pressed.size(); ++i) {
      if (!ring.pressed[i] || !std::isfinite(ring.segment_angles[i])) continue;
      contacts_.Add(planner_.pose(), planner_.parameters().window.robot_radius_m,
                    ring.segment_angles[i], now);
      angle = ring.segment_angles[i];
      any = true;
    }
    if (!any) return;
    if (!session_->backing_off()) {
      ROS_WARN(
          "harmonic_planner: bumper contact at %.0f deg: backing off, remembered as an "
          "obstacle",
          angle * 180.0 / M_PI);
    }
    session_->Contact(angle, odom_);
    ApplyMap();
  }

  // --- the Navigate action -------------------------------------------------------------------

  void OnGoal() {
    const auto goal = server_.acceptNewGoal();
    std::string error;
    auto request = conv::FromGoal(*goal, params_.frame_id, params_.planner.goal_tolerance_m,
                                  params_.heading_tolerance_rad, &error);
    // The global planner would refuse it too, but only after the round trip.
    if (request && params_.navigate.use_global_planner && !db_.graph().rooms().empty() &&
        !db_.graph().RoomContaining(request->target)) {
      char where[96];
      std::snprintf(where, sizeof where, "target (%.6g, %.6g)", request->target.x(),
                    request->target.y());
      error = std::string(where) + " is outside every room of the map";
      request.reset();
    }
    if (!request) {
      refusals_.Refuse("~navigate", "goal", error);
      spott_msgs::NavigateResult r;
      r.outcome = spott_msgs::NavigateResult::FAILED;
      r.reason = "bad Navigate goal: " + error;
      server_.setAborted(r, r.reason);
      if (session_) Finish();  // the goal this one preempted stops too
      return;
    }
    request_ = *request;
    session_ = std::make_unique<NavigateSession>(params_.navigate, ros::Time::now().toSec());
    session_->LocalizationLost(localization_lost_);
    if (have_pose_) session_->PoseAvailable();
    goal_id_ = ros::this_node::getName() + "/" + std::to_string(++goal_count_);
    planner_.ClearBorderGoal();
    planner_.SetGoal(request_.target, request_.tolerance_m);
    snap_said_ = false;
    turning_ = false;
    travelled_ = 0.0;
    last_position_ = planner_.pose().Position();
    spott_msgs::GlobalGoal g;
    g.header.frame_id = params_.frame_id;
    g.header.stamp = ros::Time::now();
    g.goal_id = goal_id_;
    g.target.x = request_.target.x();
    g.target.y = request_.target.y();
    goal_pub_.publish(g);  // the global planner answers with this id
    ROS_INFO("harmonic_planner: navigate to (%.2f, %.2f) [%s]", request_.target.x(),
             request_.target.y(), goal_id_.c_str());
  }

  void OnPreempt() {
    if (!session_) return;
    session_->Preempt();
    Finish();
  }

  // Sends the result of the finished session and hands the goal back.
  void Finish() {
    Stop();
    if (!server_.isActive()) {
      session_.reset();
      return;
    }
    spott_msgs::NavigateResult r;
    r.final_pose = CurrentPose();
    r.distance_travelled = travelled_;
    r.reason = session_->reason();
    switch (session_->outcome()) {
      case NavigateOutcome::kSucceeded:
        r.outcome = spott_msgs::NavigateResult::SUCCEEDED;
        server_.setSucceeded(r, r.reason);
        break;
      case NavigateOutcome::kPreempted:
        r.outcome = spott_msgs::NavigateResult::PREEMPTED;
        server_.setPreempted(r, r.reason);
        break;
      case NavigateOutcome::kUnreachable:
        r.outcome = spott_msgs::NavigateResult::UNREACHABLE;
        server_.setAborted(r, r.reason);
        break;
      case NavigateOutcome::kFailed:
        r.outcome = spott_msgs::NavigateResult::FAILED;
        server_.setAborted(r, r.reason);
        break;
    }
    if (r.outcome != spott_msgs::NavigateResult::SUCCEEDED) {
      ROS_WARN("harmonic_planner: goal %s ended: %s", goal_id_.c_str(), r.reason.c_str());
    }
    session_.reset();
    spott_msgs::GlobalGoal none;  // the global planner drops its goal
    none.header.frame_id = params_.frame_id;
    none.header.stamp = ros::Time::now();
    goal_pub_.publish(none);
    goal_id_.clear();
  }

  void Stop() {
    planner_.ClearGoal();
    cmd_pub_.publish(geometry_msgs::Twist());
  }

  geometry_msgs::PoseStamped CurrentPose() const {
    const auto& p = planner_.pose();
    return spott_ros::ToPoseStamped(spott_ros::MakePose2D(p.x, p.y, p.yaw), params_.frame_id,
                                    ros::Time::now());
  }

  void Drive(double linear, double angular) {
    if (!std::isfinite(linear) || !std::isfinite(angular)) {  // never on the wheels
      ROS_ERROR_THROTTLE(5.0, "harmonic_planner: a steering command was not finite: stopped");
      linear = angular = 0.0;
    }
    geometry_msgs::Twist twist;
    twist.linear.x = linear;
    twist.angular.z = angular;
    cmd_pub_.publish(twist);
  }

  // The window b_pf, so that the global planner projects onto this very window (SPOTT III.D.2).
  void PublishWindow(const ros::Time& now) {
    const spott_map::Box b = planner_.window().bounds();
    geometry_msgs::PolygonStamped w;
    w.header.frame_id = params_.frame_id;
    w.header.stamp = now;
    for (const Vec2& c : {b.min, Vec2(b.max.x(), b.min.y()), b.max, Vec2(b.min.x(), b.max.y())}) {
      geometry_msgs::Point32 p;
      p.x = static_cast<float>(c.x());
      p.y = static_cast<float>(c.y());
      w.polygon.points.push_back(p);
    }
    window_pub_.publish(w);
  }

  void Cycle(const ros::TimerEvent&) {
    const ros::Time now = ros::Time::now();
    try {  // (b) the localization estimate, map -> odom -> base_link
      const spott_ros::RobotPose r = spott_ros::LookupRobotPose(
          tf_, {params_.frame_id, params_.odom_frame, params_.base_frame});
      planner_.CorrectPose({r.pose.x, r.pose.y, r.pose.theta});
      if (!have_pose_) ROS_INFO("harmonic_planner: the robot has a pose");
      have_pose_ = true;
      if (session_) session_->PoseAvailable();
      if (r.map_to_odom_age_s > spott_ros::kSilentLocalizationS)
        ROS_WARN_THROTTLE(5.0,
                          "harmonic_planner: %s -> %s is %.1f s old (is the localization "
                          "running?): driving on odometry",
                          params_.frame_id.c_str(), params_.odom_frame.c_str(),
                          r.map_to_odom_age_s);
    } catch (const tf2::TransformException& e) {
      ROS_WARN_THROTTLE(5.0, "harmonic_planner: no pose (%s)%s", e.what(),
                        have_pose_ ? "; dead-reckoning" : "");
    }
    if (!have_pose_) {  // no window before the robot is somewhere; a goal waits in PLANNING
      if (session_ && server_.isActive()) {
        session_->Update(now.toSec());
        if (session_->finished()) return Finish();
        spott_msgs::NavigateFeedback fb;
        fb.state = fb.PLANNING;
        fb.distance_remaining = std::numeric_limits<double>::quiet_NaN();
        fb.note = session_->note();
        server_.publishFeedback(fb);
      }
      return;
    }
    if (contacts_.Expire(now.toSec())) ApplyMap();
    const ros::WallTime t0 = ros::WallTime::now();
    planner_.Cycle();
    solve_time_ += (ros::WallTime::now() - t0).toSec();
    if (planner_.status().goal_snapped_m > 0.0 && !snap_said_) {
      snap_said_ = true;
      ROS_INFO(
          "harmonic_planner: the goal lies in the padding: aiming at the free cell %.2f m "
          "from it (within its tolerance %.2f m)",
          planner_.status().goal_snapped_m, request_.tolerance_m);
    }
    status_pub_.publish(conv::ToStatus(planner_, solve_time_, params_.frame_id, now));
    if (planner_.status().recentred) PublishWindow(now);
    if (++cycle_ % params_.visualization_every == 0 && planner_.status().has_goal) {
      potential_pub_.publish(conv::ToPotentialImage(planner_.field(), params_.frame_id, now));
      contours_pub_.publish(conv::ToContours(planner_.field(), params_.frame_id, now));
      path_pub_.publish(conv::ToPath(planner_.PredictedPath(), params_.frame_id, now));
    }
    if (!session_ || !server_.isActive()) return;
    travelled_ += (planner_.pose().Position() - last_position_).norm();
    last_position_ = planner_.pose().Position();
    session_->Update(now.toSec());
    if (session_->finished()) return Finish();
    double remaining = std::numeric_limits<double>::quiet_NaN();
    if (session_->phase() != NavigatePhase::kPlanning) {
      remaining = DriveOneCycle(now);
      if (!session_) return;  // finished this cycle
    }
    spott_msgs::NavigateFeedback fb;
    fb.state = session_->phase() == NavigatePhase::kPlanning     ? fb.PLANNING
               : session_->phase() == NavigatePhase::kRecovering ? fb.RECOVERING
                                                                 : fb.DRIVING;
    fb.distance_remaining = remaining;
    fb.current_pose = CurrentPose();
    fb.global_path_summary = session_->path_summary();
    fb.note = session_->note();
    server_.publishFeedback(fb);
  }

  // One cycle of DRIVING / RECOVERING; returns the distance remaining (m).
  double DriveOneCycle(const ros::Time& now) {
    if (const auto v = session_->BackOff(odom_)) {
      session_->PauseProgress();
      Drive(*v, 0.0);
      return planner_.DistanceToGoal();
    }
    if (session_->waiting_for_way()) {  // stopped until the global planner finds a way again
      session_->PauseProgress();
      if (!waiting_said_) {
        waiting_said_ = true;
        ROS_WARN("harmonic_planner: %s (at most %.1f s)", session_->note().c_str(),
                 params_.navigate.planner_patience_s);
      }
      Drive(0.0, 0.0);
      return planner_.DistanceToGoal();
    }
    waiting_said_ = false;
    const double to_target = (planner_.pose().Position() - request_.target).norm();
    if (turning_ || session_->Arrived(to_target, request_.tolerance_m, now.toSec())) {
      turning_ = true;  // arrived: only the final heading is left
      session_->PauseProgress();
      bool done = true;
      SteeringCommand turn;
      if (request_.yaw) {
        turn = TurnInPlace(planner_.pose().yaw, *request_.yaw, request_.heading_tolerance_rad,
                           params_.planner.steering, &done);
      }
      if (done) {
        switch (session_->Settled(to_target, request_.tolerance_m, now.toSec())) {
          case NavigateSession::Settle::kWait:
            Drive(0.0, 0.0);
            return to_target;
          case NavigateSession::Settle::kDriveOn:
            ROS_INFO(
                "harmonic_planner: the localization's update of the standing robot puts it "
                "%.2f m from the target (tolerance %.2f m): driving on",
                to_target, request_.tolerance_m);
            turning_ = false;
            Drive(0.0, 0.0);
            return to_target;
          case NavigateSession::Settle::kNotLocalized:
            ROS_WARN("harmonic_planner: %s", session_->reason().c_str());
            Finish();
            return to_target;
          case NavigateSession::Settle::kArrived:
            break;
        }
        session_->Succeed();
        Finish();
        return 0.0;
      }
      Drive(0.0, turn.angular);
      return to_target;
    }
    const SteeringCommand cmd =
        planner_.Steer(request_.mode, request_.bias.HeadingAt(planner_.pose().Position()));
    const double remaining = planner_.DistanceToGoal();
    steering_pub_.publish(conv::ToSteering(cmd, request_.mode, remaining, params_.frame_id, now));
    session_->Steered(cmd.valid, cmd.escaping, planner_.status().border_widened, cmd.reason,
                      planner_.status().exploring);
    session_->Descending(odom_, now.toSec());
    if (session_->finished()) {
      Finish();
      return remaining;
    }
    Drive(cmd.linear, cmd.angular);
    return remaining;
  }

  NodeParameters params_;
  LocalPlanner planner_;
  ContactMemory contacts_;
  actionlib::SimpleActionServer<spott_msgs::NavigateAction> server_;
  tf2_ros::Buffer tf_;
  tf2_ros::TransformListener listener_;
  spott_ros::InputRefusals refusals_;
  ros::Publisher cmd_pub_, goal_pub_, window_pub_, status_pub_, steering_pub_, potential_pub_,
      contours_pub_, path_pub_;
  ros::Subscriber features_sub_, graph_sub_, projected_sub_, plan_status_sub_, odom_sub_,
      bumper_sub_, localization_sub_, status_sub_;
  ros::Timer timer_;
  spott_map::MapDatabase db_;
  std::unique_ptr<NavigateSession> session_;  ///< The running goal, if any.
  NavigateRequest request_;
  std::string goal_id_;
  long goal_count_ = 0;
  bool have_pose_ = false;
  bool turning_ = false;            ///< Arrived at the position; turning to the final heading.
  bool snap_said_ = false;          ///< The goal's snap out of the padding was logged.
  bool waiting_said_ = false;       ///< The wait for a way was logged.
  bool localization_lost_ = false;  ///< The localization's newest status said lost.
  spott_map::Pose2 odom_;
  double travelled_ = 0.0;
  Vec2 last_position_{0.0, 0.0};
  double solve_time_ = 0.0;
  long cycle_ = 0;
};

}  // namespace spott_harmonic_planner

int main(int argc, char** argv) {
  ros::init(argc, argv, "harmonic_planner");
  ros::NodeHandle nh, pnh("~");
  spott_ros::ParameterReader reader = spott_ros::ParameterReader::FromNode(pnh);
  spott_harmonic_planner::NodeParameters params;
  spott_harmonic_planner::ReadParameters(reader, params);
  std::string error;  // the radius from the robot description, found from the node's namespace
  const auto radius = spott_ros::FootprintRadiusFromParameter(nh, params.robot_description,
                                                              params.base_frame, &error);
  if (!radius) reader.Fail("robot_description: " + error);
  params.planner.window.robot_radius_m = radius.value_or(0.0);
  for (const auto& v : spott_harmonic_planner::ValidateParameters(params.planner)) reader.Fail(v);
  const auto problems = reader.Finish();
  for (const auto& w : reader.Warnings()) ROS_WARN("harmonic_planner: %s", w.c_str());
  if (!problems.empty()) {
    for (const auto& p : problems) ROS_FATAL("harmonic_planner: parameter %s", p.c_str());
    return 1;
  }
  ROS_INFO(
      "harmonic_planner: robot radius %.4f m (robot description) + localization error "
      "%.3f m = padding %.4f m",
      *radius, params.planner.window.max_localization_error_m, params.planner.window.padding_m());
  spott_harmonic_planner::HarmonicPlannerNode node(nh, pnh, params);
  ros::spin();
  return 0;
}
