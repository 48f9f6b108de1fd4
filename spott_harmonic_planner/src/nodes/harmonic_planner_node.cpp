// harmonic_planner: SPOTT's local dynamic path planner (III.D.1) as a ROS node. Glue only: reads
// and validates parameters, feeds the core LocalPlanner from topics and tf, runs its cycle on a
// timer, serves the Navigate action and publishes command, status and visualization.
//
// Subscribes: map_features (spott_msgs/MapFeatureArray), room_door_graph
// (spott_msgs/RoomDoorGraph), projected_goal (spott_msgs/ProjectedGoal), odom
// (nav_msgs/Odometry). tf: map -> base_link. Action: ~navigate (spott_msgs/Navigate).
// Publishes: ~cmd_vel (geometry_msgs/Twist, for the arbiter), ~status
// (spott_msgs/PotentialFieldStatus), ~steering (spott_msgs/SteeringStatus), ~potential
// (nav_msgs/OccupancyGrid, latched), ~contours (visualization_msgs/Marker), ~path (nav_msgs/Path).
#include <actionlib/server/simple_action_server.h>
#include <geometry_msgs/PolygonStamped.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <spott_msgs/MapFeatureArray.h>
#include <spott_msgs/NavigateAction.h>
#include <spott_msgs/ProjectedGoal.h>
#include <spott_msgs/RoomDoorGraph.h>
#include <tf2/utils.h>
#include <tf2_ros/transform_listener.h>

#include <cmath>

#include "spott_harmonic_planner/ros/conversions.h"
#include "spott_harmonic_planner/ros/parameters.h"
#include "spott_map/ros/conversions.h"

namespace spott_harmonic_planner {

namespace conv = ros_conversions;
namespace mconv = spott_map::ros_conversions;

class HarmonicPlannerNode {
 public:
  HarmonicPlannerNode(ros::NodeHandle& nh, ros::NodeHandle& pnh, const NodeParameters& p)
      : params_(p), planner_(p.planner), server_(pnh, "navigate", false), listener_(tf_) {
    cmd_pub_ = pnh.advertise<geometry_msgs::Twist>("cmd_vel", 1);
    status_pub_ = pnh.advertise<spott_msgs::PotentialFieldStatus>("status", 1);
    window_pub_ = nh.advertise<geometry_msgs::PolygonStamped>("local_window", 1, true);
    steering_pub_ = pnh.advertise<spott_msgs::SteeringStatus>("steering", 1);
    potential_pub_ = pnh.advertise<nav_msgs::OccupancyGrid>("potential", 1, true);
    contours_pub_ = pnh.advertise<visualization_msgs::Marker>("contours", 1, true);
    path_pub_ = pnh.advertise<nav_msgs::Path>("path", 1);
    features_sub_ = nh.subscribe("map_features", 1, &HarmonicPlannerNode::OnFeatures, this);
    graph_sub_ = nh.subscribe("room_door_graph", 1, &HarmonicPlannerNode::OnGraph, this);
    projected_sub_ = nh.subscribe("projected_goal", 1, &HarmonicPlannerNode::OnProjected, this);
    odom_sub_ = nh.subscribe("odom", 10, &HarmonicPlannerNode::OnOdom, this);
    server_.registerGoalCallback([this] { OnGoal(); });
    server_.registerPreemptCallback([this] { OnPreempt(); });
    server_.start();
    timer_ =
        nh.createTimer(ros::Duration(1.0 / p.cycle_rate_hz), &HarmonicPlannerNode::Cycle, this);
  }

 private:
  void OnFeatures(const spott_msgs::MapFeatureArray& msg) {
    spott_map::MapDatabase db;
    db.SetGraph(db_.graph());
    for (const auto& f : msg.features) {
      std::string error;
      const auto feature = mconv::FromMsg(f, &error);
      if (!feature) {
        ROS_WARN("harmonic_planner: map_features: feature '%s' ignored: %s", f.id.c_str(),
                 error.c_str());
        continue;
      }
      db.AddFeature(*feature);
    }
    db_ = db;
    planner_.SetMap(db_);
  }

  void OnGraph(const spott_msgs::RoomDoorGraph& msg) {
    std::string error;
    auto graph = mconv::FromMsg(msg, &error);
    if (!graph) {
      ROS_WARN("harmonic_planner: room_door_graph ignored: %s", error.c_str());
      return;
    }
    db_.SetGraph(*graph);
    planner_.SetMap(db_);
  }

  void OnProjected(const spott_msgs::ProjectedGoal& msg) {
    if (!server_.isActive()) return;
    if (!msg.on_border) {  // the way to the target lies inside the window
      planner_.ClearBorderGoal();
      return;
    }
    planner_.SetBorderGoal(
        {Vec2(msg.border_start.x, msg.border_start.y), Vec2(msg.border_end.x, msg.border_end.y)});
  }

  void OnOdom(const nav_msgs::Odometry& msg) {
    planner_.Odometry({msg.pose.pose.position.x, msg.pose.pose.position.y,
                       tf2::getYaw(msg.pose.pose.orientation)});
  }

  void OnGoal() {
    const auto goal = server_.acceptNewGoal();
    const auto& t = goal->target;
    if (!std::isfinite(t.pose.position.x) || !std::isfinite(t.pose.position.y) ||
        goal->speed_mode > spott_msgs::NavigateGoal::QUICKLY) {
      spott_msgs::NavigateResult r;
      r.outcome = spott_msgs::NavigateResult::FAILED;
      r.reason = "bad Navigate goal: target must be finite and speed_mode 0..2";
      server_.setAborted(r, r.reason);
      return;
    }
    if (!t.header.frame_id.empty() && t.header.frame_id != params_.frame_id) {
      spott_msgs::NavigateResult r;
      r.outcome = spott_msgs::NavigateResult::FAILED;
      r.reason = "target frame '" + t.header.frame_id + "' is not '" + params_.frame_id + "'";
      server_.setAborted(r, r.reason);
      return;
    }
    mode_ = static_cast<SpeedMode>(goal->speed_mode);
    bias_ = std::isfinite(goal->direction_bias) ? std::optional<double>(goal->direction_bias)
                                                : std::nullopt;
    tolerance_ = goal->position_tolerance > 0.0 ? goal->position_tolerance
                                                : params_.planner.goal_tolerance_m;
    target_ = Vec2(t.pose.position.x, t.pose.position.y);
    target_yaw_.reset();
    if (!goal->ignore_heading) target_yaw_ = tf2::getYaw(t.pose.orientation);
    heading_tolerance_ =
        goal->heading_tolerance > 0.0 ? goal->heading_tolerance : params_.heading_tolerance_rad;
    planner_.SetGoal(*target_);
    start_ = planner_.pose();
    solve_time_ = 0.0;
    bad_cycles_ = 0;
    ROS_INFO("harmonic_planner: navigate to (%.2f, %.2f)", target_->x(), target_->y());
  }

  void OnPreempt() {
    Stop();
    spott_msgs::NavigateResult r;
    r.outcome = spott_msgs::NavigateResult::PREEMPTED;
    r.reason = "preempted";
    server_.setPreempted(r, r.reason);
  }

  void Stop() {
    planner_.ClearGoal();
    target_.reset();
    cmd_pub_.publish(geometry_msgs::Twist());
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
    try {  // (b) the localization estimate, map -> base_link
      const auto tf = tf_.lookupTransform(params_.frame_id, params_.base_frame, ros::Time(0));
      planner_.CorrectPose({tf.transform.translation.x, tf.transform.translation.y,
                            tf2::getYaw(tf.transform.rotation)});
    } catch (const tf2::TransformException& e) {
      ROS_WARN_THROTTLE(5.0, "harmonic_planner: no pose (%s); dead-reckoning", e.what());
    }
    const ros::WallTime t0 = ros::WallTime::now();
    planner_.Cycle();
    solve_time_ += (ros::WallTime::now() - t0).toSec();
    status_pub_.publish(conv::ToStatus(planner_, solve_time_, params_.frame_id, now));
    if (planner_.status().recentred) PublishWindow(now);
    if (++cycle_ % params_.visualization_every == 0 && planner_.status().has_goal) {
      potential_pub_.publish(conv::ToPotentialImage(planner_.field(), params_.frame_id, now));
      contours_pub_.publish(conv::ToContours(planner_.field(), params_.frame_id, now));
      path_pub_.publish(conv::ToPath(planner_.PredictedPath(), params_.frame_id, now));
    }
    if (!server_.isActive() || !target_) return;
    spott_msgs::NavigateResult result;
    result.final_pose.header.frame_id = params_.frame_id;
    result.final_pose.pose.position.x = planner_.pose().x;
    result.final_pose.pose.position.y = planner_.pose().y;
    result.final_pose.pose.orientation.z = std::sin(planner_.pose().yaw / 2);
    result.final_pose.pose.orientation.w = std::cos(planner_.pose().yaw / 2);
    if ((planner_.pose().Position() - *target_).norm() <= tolerance_) {
      bool done = true;
      SteeringCommand turn;
      if (target_yaw_) {
        turn = TurnInPlace(planner_.pose().yaw, *target_yaw_, heading_tolerance_,
                           params_.planner.steering, &done);
      }
      if (done) {
        Stop();
        result.outcome = spott_msgs::NavigateResult::SUCCEEDED;
        server_.setSucceeded(result, "goal reached");
      } else {
        geometry_msgs::Twist twist;
        twist.angular.z = turn.angular;
        cmd_pub_.publish(twist);
      }
      return;
    }
    const SteeringCommand cmd = planner_.Steer(mode_, bias_);
    const double remaining = planner_.DistanceToGoal();
    steering_pub_.publish(conv::ToSteering(cmd, mode_, remaining, params_.frame_id, now));
    bad_cycles_ = cmd.valid ? 0 : bad_cycles_ + 1;
    if (bad_cycles_ >= params_.unreachable_cycles) {
      Stop();
      result.outcome = spott_msgs::NavigateResult::UNREACHABLE;
      result.reason = cmd.reason;
      server_.setAborted(result, result.reason);
      return;
    }
    geometry_msgs::Twist twist;
    twist.linear.x = cmd.linear;
    twist.angular.z = cmd.angular;
    cmd_pub_.publish(twist);
    spott_msgs::NavigateFeedback fb;
    fb.state = spott_msgs::NavigateFeedback::DRIVING;
    fb.distance_remaining = remaining;
    fb.current_pose = result.final_pose;
    server_.publishFeedback(fb);
  }

  NodeParameters params_;
  LocalPlanner planner_;
  actionlib::SimpleActionServer<spott_msgs::NavigateAction> server_;
  tf2_ros::Buffer tf_;
  tf2_ros::TransformListener listener_;
  ros::Publisher window_pub_;
  ros::Publisher cmd_pub_, status_pub_, steering_pub_, potential_pub_, contours_pub_, path_pub_;
  ros::Subscriber features_sub_, graph_sub_, projected_sub_, odom_sub_;
  ros::Timer timer_;
  spott_map::MapDatabase db_;
  SpeedMode mode_ = SpeedMode::kNormal;
  std::optional<double> bias_;
  std::optional<Vec2> target_;
  std::optional<double> target_yaw_;
  double heading_tolerance_ = 0.1;
  spott_map::Pose2 start_;
  double tolerance_ = 0.2;
  double solve_time_ = 0.0;
  int bad_cycles_ = 0;
  long cycle_ = 0;
};

}  // namespace spott_harmonic_planner

int main(int argc, char** argv) {
  ros::init(argc, argv, "harmonic_planner");
  ros::NodeHandle nh, pnh("~");
  spott_harmonic_planner::NodeParameters params;
  const auto violations = spott_harmonic_planner::ReadParameters(pnh, params);
  if (!violations.empty()) {
    for (const auto& v : violations)
      ROS_FATAL("harmonic_planner: invalid parameter: %s", v.c_str());
    return 1;
  }
  spott_harmonic_planner::HarmonicPlannerNode node(nh, pnh, params);
  ros::spin();
  return 0;
}
