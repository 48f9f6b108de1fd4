// cmd_vel_arbiter: the one node that publishes the robot's cmd_vel (see arbiter.h for the
// rules). Glue only: reads and validates parameters, feeds the core from the sources' inputs,
// the bumper and a timer, serves take/release/limits and publishes the status.
//
// Subscribes: cmd_vel/<source> (geometry_msgs/Twist) for every configured source, bumper
// (spott_msgs/BumperRing), clearance/topics (spott_msgs/RangeRing: sonar, infrared),
// clearance/scan_topics (sensor_msgs/LaserScan: the laser; its pose from tf). Publishes:
// cmd_vel (geometry_msgs/Twist), ~status (spott_msgs/ArbiterStatus, latched), ~driver_marker
// (visualization_msgs/Marker, latched: who drives, as text over the robot for rviz). Services:
// ~take_wheels, ~release_wheels, ~set_speed_limits. Parameters: config/cmd_vel_arbiter.yaml.
#include <ros/ros.h>
#include <spott_msgs/ReleaseWheels.h>
#include <spott_msgs/SetSpeedLimits.h>
#include <spott_msgs/TakeWheels.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "cmd_vel_arbiter/ros/conversions.h"
#include "cmd_vel_arbiter/ros/parameters.h"
#include "spott_ros/input_refusals.h"
#include "spott_ros/parameter_reader.h"
#include "spott_ros/pose_conversions.h"
#include "spott_ros/robot_geometry.h"

namespace cmd_vel_arbiter {
namespace {

namespace conv = ros_conversions;

class ArbiterNode {
 public:
  ArbiterNode(ros::NodeHandle& nh, ros::NodeHandle& pnh, const NodeParameters& p)
      : arbiter_(p.arbiter),
        params_(p),
        clearance_names_(ClearanceTopicNames(p)),
        rings_(clearance_names_.size(), p.clearance_max_age_s),
        refusals_(nh, "cmd_vel_arbiter") {
    cmd_pub_ = nh.advertise<geometry_msgs::Twist>("cmd_vel", 10);
    status_pub_ = pnh.advertise<spott_msgs::ArbiterStatus>("status", 1, true);
    marker_pub_ = pnh.advertise<visualization_msgs::Marker>("driver_marker", 1, true);
    const ros::TransportHints hints = ros::TransportHints().tcpNoDelay();
    for (const SourceParameters& s : p.arbiter.sources) {
      const std::string name = s.name;
      inputs_.push_back(nh.subscribe<geometry_msgs::Twist>(
          "cmd_vel/" + name, 10,
          [this, name](const geometry_msgs::Twist::ConstPtr& m) { OnCommand(name, *m); },
          ros::VoidConstPtr(), hints));
    }
    bumper_sub_ = nh.subscribe("bumper", 10, &ArbiterNode::OnBumper, this, hints);
    for (std::size_t i = 0; p.clearance_enabled && i < p.clearance_topics.size(); ++i) {
      ring_subs_.push_back(nh.subscribe<spott_msgs::RangeRing>(
          p.clearance_topics[i], 10,
          [this, i](const spott_msgs::RangeRing::ConstPtr& m) { OnRing(i, *m); },
          ros::VoidConstPtr(), hints));
    }
    for (std::size_t i = 0; p.clearance_enabled && i < p.clearance_scan_topics.size(); ++i) {
      const std::size_t index = p.clearance_topics.size() + i;
      ring_subs_.push_back(nh.subscribe<sensor_msgs::LaserScan>(
          p.clearance_scan_topics[i], 10,
          [this, index](const sensor_msgs::LaserScan::ConstPtr& m) { OnScan(index, *m); },
          ros::VoidConstPtr(), hints));
    }
    if (p.clearance_enabled && !p.clearance_scan_topics.empty()) {
      tf_listener_ = std::make_unique<tf2_ros::TransformListener>(tf_);
      std::string error;
      if (const auto r = spott_ros::FootprintRadiusFromParameter(nh, "robot_description",
                                                                 p.base_frame, &error))
        radius_m_ = *r;
      else if (p.clearance.footprint_radius_m <= 0.0)
        ROS_WARN(
            "cmd_vel_arbiter: no footprint radius (%s) and clearance/footprint_radius_m is 0: "
            "laser scans cap nothing",
            error.c_str());
    }
    take_srv_ = pnh.advertiseService("take_wheels", &ArbiterNode::OnTake, this);
    release_srv_ = pnh.advertiseService("release_wheels", &ArbiterNode::OnRelease, this);
    limits_srv_ = pnh.advertiseService("set_speed_limits", &ArbiterNode::OnLimits, this);
    update_timer_ = nh.createTimer(ros::Duration(1.0 / p.update_rate_hz),
                                   [this](const ros::TimerEvent&) { OnTimer(); });
    if (p.status_rate_hz > 0) {
      status_timer_ = nh.createTimer(ros::Duration(1.0 / p.status_rate_hz),
                                     [this](const ros::TimerEvent&) { PublishStatus(); });
    }
    PublishStatus();
    std::string sources;
    for (const SourceStatus& s : arbiter_.Sources())
      sources += (sources.empty() ? "" : ", ") + s.name + " (" + std::to_string(s.priority) + ")";
    ROS_INFO("cmd_vel_arbiter: sources by priority: %s; limits %.2f m/s, %.2f rad/s",
             sources.c_str(), arbiter_.max_linear_mps(), arbiter_.max_angular_rps());
  }

 private:
  static double Now() { return ros::Time::now().toSec(); }

  void OnCommand(const std::string& source, const geometry_msgs::Twist& msg) {
    bool ignored = false;
    std::string refused;
    const Output out = arbiter_.Command(source, conv::FromTwist(msg, &ignored), Now(), &refused);
    if (!refused.empty()) {  // the source stops (arbiter.h)
      refusals_.Refuse("cmd_vel/" + source, "linear.x/angular.z", refused);
    } else if (ignored) {
      ROS_WARN_THROTTLE(10.0,
                        "cmd_vel_arbiter: '%s' sends linear.y/z or angular.x/y, which a planar "
                        "base ignores",
                        source.c_str());
    }
    Emit(out);
  }

  void OnBumper(const spott_msgs::BumperRing& ring) {
    if (!ring.header.frame_id.empty()) base_frame_ = ring.header.frame_id;  // for the marker
    std::string error;
    const auto angles = conv::PressedAngles(ring, &error);
    if (!angles) {
      refusals_.Refuse("bumper", "pressed/segment_angles", error);
      return;
    }
    Emit(arbiter_.SetContacts(*angles, Now()));
  }

  void OnRing(std::size_t index, const spott_msgs::RangeRing& ring) {
    const std::string& topic = clearance_names_[index];
    std::string error;
    const auto bounds = conv::RingBounds(ring, params_.clearance, &error);
    if (!bounds) {
      refusals_.Refuse(topic, "ranges/mounts", error);
      return;
    }
    OnBounds(index, *bounds);
  }

  void OnBounds(std::size_t index, const SpeedBounds& bounds) {
    const double now = Now();
    rings_.Set(index, bounds, now);
    const std::uint32_t before = arbiter_.clearance_slowdowns();
    const SpeedBounds tightest = Tightest(now, nullptr);
    Emit(arbiter_.SetClearance(tightest.forward_mps, tightest.backward_mps, now));
    if (arbiter_.clearance_slowdowns() != before) {
      ROS_INFO_THROTTLE(5.0,
                        "cmd_vel_arbiter: %s slowed to %.2f m/s: an echo %.2f m ahead, %.2f m "
                        "behind",
                        arbiter_.driver().c_str(), tightest.forward_mps, tightest.forward_gap_m,
                        tightest.backward_gap_m);
    }
  }

  // A laser scan: its rays' points bound alike, the scanner's pose from tf (a static mount, looked
  // up once per frame).
  void OnScan(std::size_t index, const sensor_msgs::LaserScan& scan) {
    const std::string& topic = clearance_names_[index];
    auto mount = mounts_.find(scan.header.frame_id);
    if (mount == mounts_.end()) {
      try {
        const auto t = tf_.lookupTransform(params_.base_frame, scan.header.frame_id, ros::Time(0));
        const auto pose = spott_ros::ToPose2D(t.transform);
        if (!pose) {  // not cached: a later, finite transform is taken
          refusals_.Refuse(topic, "header.frame_id",
                           "the pose of '" + scan.header.frame_id + "' in '" + params_.base_frame +
                               "' is not finite or has no yaw");
          return;
        }
        mount =
            mounts_.emplace(scan.header.frame_id, Transducer{pose->x, pose->y, pose->theta}).first;
      } catch (const tf2::TransformException& e) {
        ROS_WARN_THROTTLE(10.0, "cmd_vel_arbiter: %s: no pose of '%s' in '%s' yet: %s",
                          topic.c_str(), scan.header.frame_id.c_str(), params_.base_frame.c_str(),
                          e.what());
        return;
      }
    }
    std::string error;
    const auto bounds = conv::ScanBounds(scan, mount->second, radius_m_, params_.clearance, &error);
    if (!bounds) {
      refusals_.Refuse(topic, "ranges/angles", error);
      return;
    }
    OnBounds(index, *bounds);
  }

  // The rings' tightest bounds; a ring silent for clearance/max_age_s bounds nothing (the bumper
  // and the planners' maps still guard), said once when it falls silent.
  SpeedBounds Tightest(double now, bool* went_silent) {
    std::vector<std::size_t> silent;
    const SpeedBounds t = rings_.Tightest(now, &silent);
    for (std::size_t i : silent) {
      ROS_WARN("cmd_vel_arbiter: no %s for %.1f s: it caps nothing until it is back",
               clearance_names_[i].c_str(), params_.clearance_max_age_s);
    }
    if (went_silent) *went_silent = !silent.empty();
    return t;
  }

  void OnTimer() {
    const double now = Now();
    bool went_silent = false;
    const SpeedBounds t = Tightest(now, &went_silent);
    if (went_silent) {
      Emit(arbiter_.SetClearance(t.forward_mps, t.backward_mps, now));
      return;
    }
    Emit(arbiter_.Update(now));
  }
  bool OnTake(spott_msgs::TakeWheels::Request& req, spott_msgs::TakeWheels::Response& res) {
    Output out;
    res.success = arbiter_.Take(req.source, Now(), &res.message, &res.preempted, &out);
    ROS_INFO("cmd_vel_arbiter: take_wheels: %s", res.message.c_str());
    Emit(out);
    return true;
  }

  bool OnRelease(spott_msgs::ReleaseWheels::Request& req,
                 spott_msgs::ReleaseWheels::Response& res) {
    Output out;
    res.success = arbiter_.Release(req.source, Now(), &res.message, &out);
    ROS_INFO("cmd_vel_arbiter: release_wheels: %s", res.message.c_str());
    Emit(out);
    return true;
  }

  bool OnLimits(spott_msgs::SetSpeedLimits::Request& req,
                spott_msgs::SetSpeedLimits::Response& res) {
    Output out;
    res.success = arbiter_.SetSpeedLimits(req.max_linear_mps, req.max_angular_rps, req.reason,
                                          &res.message, Now(), &out);
    if (res.success) {
      ROS_INFO("cmd_vel_arbiter: set_speed_limits (%s): %s", req.reason.c_str(),
               res.message.c_str());
    } else {
      ROS_WARN("cmd_vel_arbiter: set_speed_limits refused: %s", res.message.c_str());
    }
    Emit(out);
    return true;
  }

  void Emit(const Output& out) {
    if (out.publish) cmd_pub_.publish(conv::ToTwist(out.command));
    if (arbiter_.revision() != published_revision_) PublishStatus();
  }

  void PublishStatus() {
    published_revision_ = arbiter_.revision();
    const spott_msgs::ArbiterStatus status = conv::ToStatus(arbiter_, ros::Time::now());
    status_pub_.publish(status);
    marker_pub_.publish(conv::ToDriverMarker(status, base_frame_));
  }

  Arbiter arbiter_;
  NodeParameters params_;
  std::vector<std::string> clearance_names_;  ///< Rings' topics, then scans' (ClearanceTopicNames).
  RingBoundsSet rings_;                       ///< The clearance rings' and scans' latest bounds.
  tf2_ros::Buffer tf_;
  std::unique_ptr<tf2_ros::TransformListener> tf_listener_;
  std::map<std::string, Transducer> mounts_;  ///< Scanners' poses in base_frame by frame id.
  double radius_m_ = 0.0;                     ///< From the robot description (0: unknown).
  spott_ros::InputRefusals refusals_;
  std::uint64_t published_revision_ = ~std::uint64_t{0};
  ros::Publisher cmd_pub_, status_pub_, marker_pub_;
  std::string base_frame_ = "base_link";  ///< The bumper ring's frame once one came (REP-105).
  std::vector<ros::Subscriber> inputs_;
  ros::Subscriber bumper_sub_;
  std::vector<ros::Subscriber> ring_subs_;
  ros::ServiceServer take_srv_, release_srv_, limits_srv_;
  ros::Timer update_timer_, status_timer_;
};

}  // namespace
}  // namespace cmd_vel_arbiter

int main(int argc, char** argv) {
  ros::init(argc, argv, "cmd_vel_arbiter");
  ros::NodeHandle nh, pnh("~");
  const auto params = spott_ros::ReadNodeParameters<cmd_vel_arbiter::NodeParameters>(
      pnh, "cmd_vel_arbiter", cmd_vel_arbiter::Read);
  if (!params) return 1;
  cmd_vel_arbiter::ArbiterNode node(nh, pnh, *params);
  ros::spin();
  return 0;
}
