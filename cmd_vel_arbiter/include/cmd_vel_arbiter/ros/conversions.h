// cmd_vel_arbiter core types <-> ROS messages.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <geometry_msgs/Twist.h>
#include <ros/time.h>
#include <sensor_msgs/LaserScan.h>
#include <spott_msgs/ArbiterStatus.h>
#include <spott_msgs/BumperRing.h>
#include <spott_msgs/RangeRing.h>
#include <visualization_msgs/Marker.h>

#include "cmd_vel_arbiter/arbiter.h"
#include "cmd_vel_arbiter/clearance.h"

namespace cmd_vel_arbiter::ros_conversions {

/// linear.x and angular.z; the components a planar base cannot follow (linear.y/z, angular.x/y)
/// are dropped, and `*ignored` says so when one of them is not zero.
Velocity FromTwist(const geometry_msgs::Twist& t, bool* ignored);
geometry_msgs::Twist ToTwist(const Velocity& v);

/// The angles (rad, base frame) of the pressed segments; nullopt with `error` when the arrays
/// do not match or an angle of a pressed segment is not finite.
std::optional<std::vector<double>> PressedAngles(const spott_msgs::BumperRing& ring,
                                                 std::string* error);

/// The speed bounds from a range ring (in the robot's frame: the mounts are in the header's
/// frame, base_link); nullopt with `error` when the arrays do not match or a mount or the cone
/// is not finite.
std::optional<SpeedBounds> RingBounds(const spott_msgs::RangeRing& ring,
                                      const ClearanceParameters& p, std::string* error);

/// The speed bounds from a laser scan whose frame sits at `mount` in the robot's frame (from tf),
/// the body round with `radius_m`; nullopt with `error` naming the field when an angle, the
/// range limits, the mount or the radius is not finite, range_min is negative or above
/// range_max, or the increment is 0 with more than one reading.
std::optional<SpeedBounds> ScanBounds(const sensor_msgs::LaserScan& scan, const Transducer& mount,
                                      double radius_m, const ClearanceParameters& p,
                                      std::string* error);

spott_msgs::ArbiterStatus ToStatus(const Arbiter& arbiter, const ros::Time& stamp);

/// rviz text over the robot (in `base_frame`): who drives ("wheels: planner"), whether it holds
/// them exclusively, a bumper stop (red) and run-time limits with their reason.
visualization_msgs::Marker ToDriverMarker(const spott_msgs::ArbiterStatus& status,
                                          const std::string& base_frame);

}  // namespace cmd_vel_arbiter::ros_conversions
