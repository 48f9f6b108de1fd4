// Conversions between robot_sim's core types and ROS messages.
#pragma once

#include <string>
#include <vector>

#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/BatteryState.h>
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/Range.h>
#include <spott_msgs/AddObstacle.h>
#include <spott_msgs/BumperRing.h>
#include <spott_msgs/Kidnap.h>
#include <spott_msgs/OdometrySlip.h>
#include <spott_msgs/RangeProfile.h>
#include <spott_msgs/RangeRing.h>
#include <spott_msgs/SensorFault.h>
#include <spott_msgs/SetDoorState.h>
#include <visualization_msgs/MarkerArray.h>

#include "robot_sim/battery.h"
#include "robot_sim/fault_events.h"
#include "robot_sim/robot_spec.h"
#include "robot_sim/sim_world.h"

namespace robot_sim::ros_conversions {

Twist2 FromMsg(const geometry_msgs::Twist& msg);

/// A whole ring (NaN stays NaN: a dropped-out transducer). The rings ride on the turret
/// (`PlaceMount`): their mounts are given in `base_frame`, turned by `turret_yaw` (rad).
spott_msgs::RangeRing ToRangeRing(const RangeRingSpec& ring, const std::vector<double>& ranges,
                                  const std::string& base_frame, const ros::Time& stamp,
                                  double turret_yaw = 0.0);
/// One transducer for rviz; no echo (max range) and dropouts become +inf / NaN (REP-117).
sensor_msgs::Range ToRange(const RangeRingSpec& ring, std::size_t index, double range,
                           const ros::Time& stamp);
sensor_msgs::LaserScan ToLaserScan(const LaserSpec& laser, const std::vector<double>& ranges,
                                   double scan_period, const ros::Time& stamp);
/// A QUADRIS profile in the head's frame (the URDF link below its pan and tilt joints).
spott_msgs::RangeProfile ToRangeProfile(const ProfilerSpec& profiler, bool horizontal, double pan,
                                        double tilt, const std::vector<double>& angles,
                                        const std::vector<double>& ranges, const ros::Time& stamp);
spott_msgs::BumperRing ToBumperRing(const BumperSpec& bumper, const std::vector<bool>& pressed,
                                    const std::string& base_frame, const ros::Time& stamp);
/// rviz: the pressed segments as red spheres on the body's shell (`radius_m`, in `base_frame`),
/// or a DELETEALL when none is pressed.
visualization_msgs::MarkerArray ToBumperMarkers(const BumperSpec& bumper, double radius_m,
                                                const std::vector<bool>& pressed,
                                                const std::string& base_frame,
                                                const ros::Time& stamp);
nav_msgs::Odometry ToOdometry(const spott_map::Pose2& pose, const Twist2& twist,
                              const std::string& frame, const std::string& child,
                              const ros::Time& stamp);
/// The battery (percentage in [0, 1] as sensor_msgs/BatteryState has it; current negative while
/// discharging; charge and capacity in Ah at the nominal voltage).
sensor_msgs::BatteryState ToBatteryState(const Battery& battery, const std::string& frame,
                                         const ros::Time& stamp);
/// Occupied OctoMap leaves as cube lists (one per leaf size), coloured by height.
visualization_msgs::MarkerArray ToVoxelMarkers(const std::vector<VoxelLeaf>& leaves,
                                               const std::string& frame, const ros::Time& stamp);

/// Service requests as fault events; false with a message for a request that cannot be one.
bool FromRequest(const spott_msgs::Kidnap::Request& req, FaultEvent& e, std::string* error);
bool FromRequest(const spott_msgs::SetDoorState::Request& req, FaultEvent& e, std::string* error);
bool FromRequest(const spott_msgs::SensorFault::Request& req, FaultEvent& e, std::string* error);
bool FromRequest(const spott_msgs::OdometrySlip::Request& req, FaultEvent& e, std::string* error);
bool FromRequest(const spott_msgs::AddObstacle::Request& req, FaultEvent& e, std::string* error);

}  // namespace robot_sim::ros_conversions
