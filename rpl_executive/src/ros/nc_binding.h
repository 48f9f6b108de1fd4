// The Noreils-Chatila executive on the stack (sections 4 to 6, issue 18): HILARE's on-board
// modules (the Pilot, wall following, obstacle avoidance: on_board_modules.h) and the executive
// with its surveillance manager, fed by the sonar belt (spott_msgs/RangeRing), the pose (tf
// odom -> base_link placed in the map by the localization's map -> odom at the mission's start, or
// the localization's map -> base_link live: nc/pose_source), the
// laser (sensor_msgs/LaserScan) and the battery (sensor_msgs/BatteryState); zones and paths from
// world_server's world_places. The modules' wheel commands go to the arbiter as the executive's
// source (cmd_vel/executive), which takes the wheels while a mission runs (the Pilot is the only
// effector, section 6.1). Every fired monitor is published as spott_msgs/MonitorEvent; draw
// operators become rviz markers. Glue only; single-threaded like the rest of the node.
//
// Reflexes are not held back by the control cycle: a sensor message is handed to the executive
// (whose surveillance manager runs the reflex at once) and the modules' new command is sent in the
// same callback.
#pragma once

#include <geometry_msgs/Twist.h>
#include <ros/ros.h>
#include <sensor_msgs/BatteryState.h>
#include <sensor_msgs/LaserScan.h>
#include <spott_msgs/ArbiterStatus.h>
#include <spott_msgs/MonitorEvent.h>
#include <spott_msgs/RangeRing.h>
#include <spott_msgs/WorldPlaces.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "parameters.h"
#include "rpl_executive/noreils_chatila/executive.h"
#include "rpl_executive/noreils_chatila/mission_parser.h"
#include "rpl_executive/noreils_chatila/on_board_modules.h"
#include "spott_ros/input_refusals.h"

namespace rpl_executive {

class NcBinding {
 public:
  /// `refusals` counts the input refused at the node's edge (the node's; outlives this).
  NcBinding(ros::NodeHandle& nh, const ros_parameters::NodeParameters& params,
            spott_ros::InputRefusals* refusals, std::function<void()> changed);
  ~NcBinding();

  /// "" when missions can start; else why not (no sonar ring yet, no robot description).
  std::string NotReady() const;
  /// Parses, checks and starts a mission. "" or the errors (file:line:column) / the PRE: refusal.
  std::string Start(const std::string& text, const std::string& file);
  void Abort(const std::string& reason);

  bool running() const;
  noreils_chatila::MissionState state() const;
  const std::string& mission_name() const;
  /// The diagnosis of a failed mission.
  std::string FailureText() const;
  std::string CurrentCommand() const;
  std::vector<std::string> ActiveMonitors() const;
  /// The monitors fired in the current (or last) mission, O-surveillances included.
  std::vector<spott_msgs::MonitorEvent> Fired() const;
  const std::optional<spott_msgs::MonitorEvent>& last_event() const { return last_event_; }
  /// Fig. 5's messages since the last call, one line each.
  std::vector<std::string> TakeEvents();

 private:
  double Now() const { return ros::Time::now().toSec(); }
  void Create(const spott_msgs::RangeRing& ring);
  void ApplyPlaces();
  void OnSonar(const spott_msgs::RangeRing& ring);
  void OnLaser(const sensor_msgs::LaserScan& scan);
  void OnBattery(const sensor_msgs::BatteryState& battery);
  void OnPlaces(const spott_msgs::WorldPlaces& places);
  void OnArbiter(const spott_msgs::ArbiterStatus& status);
  /// One control cycle: pose, the modules' reports, a step of the executive, the wheels.
  void Cycle();
  void UpdatePose(double now);
  /// Anchors the odometry in the map (map -> odom now); "" or why not.
  std::string AnchorOdometry();
  void SendWheels(double now);
  void PublishMonitorEvents();
  void Wheels(bool take);

  ros_parameters::NodeParameters params_;
  std::function<void()> changed_;
  ros::NodeHandle nh_;
  spott_ros::InputRefusals* refusals_;
  std::string not_ready_ = "no sonar ring on the sonar topic yet";
  std::unique_ptr<noreils_chatila::OnBoardModules> kit_;
  std::unique_ptr<noreils_chatila::Executive> exec_;
  noreils_chatila::SonarRing ring_;
  noreils_chatila::MissionFile mission_;  // the running mission (the executive refers to it)
  noreils_chatila::MissionFile o_surveillances_;
  std::optional<spott_msgs::WorldPlaces> places_;
  bool motors_on_ = false;
  bool have_wheels_ = false;
  bool sent_nonzero_ = false;
  std::optional<double> laser_yaw_;
  std::string laser_frame_;
  std::optional<ros::Time> last_pose_stamp_;
  std::optional<geometry_msgs::Pose2D>
      map_to_odom_;  // the odometry's anchor (pose_source odometry)
  std::size_t log_read_ = 0;
  std::optional<spott_msgs::MonitorEvent> last_event_;
  int marker_id_ = 0;
  noreils_chatila::MissionState last_state_ = noreils_chatila::MissionState::kIdle;

  tf2_ros::Buffer tf_;
  tf2_ros::TransformListener listener_;
  ros::Subscriber sonar_sub_, laser_sub_, battery_sub_, places_sub_, arbiter_sub_;
  ros::Publisher cmd_pub_, events_pub_, markers_pub_;
  ros::ServiceClient take_, release_;
  ros::Timer timer_;
};

}  // namespace rpl_executive
