#include "cmd_vel_arbiter/ros/conversions.h"

#include <cmath>

#include "spott_ros/markers.h"

namespace cmd_vel_arbiter::ros_conversions {

Velocity FromTwist(const geometry_msgs::Twist& t, bool* ignored) {
  *ignored = t.linear.y != 0.0 || t.linear.z != 0.0 || t.angular.x != 0.0 || t.angular.y != 0.0;
  return Velocity{t.linear.x, t.angular.z};
}

geometry_msgs::Twist ToTwist(const Velocity& v) {
  geometry_msgs::Twist t;
  t.linear.x = v.linear_mps;
  t.angular.z = v.angular_rps;
  return t;
}

std::optional<std::vector<double>> PressedAngles(const spott_msgs::BumperRing& ring,
                                                 std::string* error) {
  if (ring.pressed.size() != ring.segment_angles.size()) {
    *error = "bumper: " + std::to_string(ring.pressed.size()) + " pressed flags but " +
             std::to_string(ring.segment_angles.size()) + " segment_angles";
    return std::nullopt;
  }
  std::vector<double> angles;
  for (std::size_t i = 0; i < ring.pressed.size(); ++i) {
    if (!ring.pressed[i]) continue;
    if (!std::isfinite(ring.segment_angles[i])) {
      *error = "bumper: segment_angles[" + std::to_string(i) + "] is not finite";
      return std::nullopt;
    }
    angles.push_back(ring.segment_angles[i]);
  }
  return angles;
}

std::optional<SpeedBounds> RingBounds(const spott_msgs::RangeRing& ring,
                                      const ClearanceParameters& p, std::string* error) {
  if (ring.ranges.size() != ring.mounts.size()) {
    *error = std::to_string(ring.ranges.size()) + " ranges but " +
             std::to_string(ring.mounts.size()) + " mounts";
    return std::nullopt;
  }
  if (!std::isfinite(ring.field_of_view) || !std::isfinite(ring.min_range) ||
      !std::isfinite(ring.max_range)) {
    *error = "field_of_view, min_range or max_range is not finite";
    return std::nullopt;
  }
  std::vector<Transducer> transducers;
  for (std::size_t i = 0; i < ring.mounts.size(); ++i) {
    const auto& m = ring.mounts[i];
    if (!std::isfinite(m.x) || !std::isfinite(m.y) || !std::isfinite(m.theta)) {
      *error = "mounts[" + std::to_string(i) + "] is not finite";
      return std::nullopt;
    }
    transducers.push_back(Transducer{m.x, m.y, m.theta});
  }
  const std::vector<double> ranges(ring.ranges.begin(), ring.ranges.end());
  return BoundsFromRing(transducers, ring.field_of_view, ring.min_range, ring.max_range, ranges, p);
}

std::optional<SpeedBounds> ScanBounds(const sensor_msgs::LaserScan& scan, const Transducer& mount,
                                      double radius_m, const ClearanceParameters& p,
                                      std::string* error) {
  if (!std::isfinite(scan.angle_min) || !std::isfinite(scan.angle_increment)) {
    *error = "angle_min or angle_increment is not finite";
    return std::nullopt;
  }
  if (scan.angle_increment == 0.0f && scan.ranges.size() > 1) {
    *error = "angle_increment is 0 with " + std::to_string(scan.ranges.size()) + " ranges";
    return std::nullopt;
  }
  if (!std::isfinite(scan.range_min) || !std::isfinite(scan.range_max) || scan.range_min < 0.0f ||
      scan.range_min > scan.range_max) {
    *error = "range_min and range_max must be finite with 0 <= range_min <= range_max";
    return std::nullopt;
  }
  if (!std::isfinite(mount.x) || !std::isfinite(mount.y) || !std::isfinite(mount.yaw)) {
    *error = "the scanner's pose in the robot's frame (tf) is not finite";
    return std::nullopt;
  }
  if (!(std::isfinite(radius_m) && radius_m > 0.0) && !(p.footprint_radius_m > 0.0)) {
    *error = "no footprint radius";
    return std::nullopt;
  }
  ScanGeometry g;
  g.mount = mount;
  g.angle_min_rad = scan.angle_min;
  g.angle_increment_rad = scan.angle_increment;
  g.range_min_m = scan.range_min;
  g.range_max_m = scan.range_max;
  const std::vector<double> ranges(scan.ranges.begin(), scan.ranges.end());
  return BoundsFromScan(g, ranges, radius_m, p);
}

spott_msgs::ArbiterStatus ToStatus(const Arbiter& arbiter, const ros::Time& stamp) {
  spott_msgs::ArbiterStatus s;
  s.header.stamp = stamp;
  s.driver = arbiter.driver();
  s.exclusive_holder = arbiter.exclusive_holder();
  for (const SourceStatus& src : arbiter.Sources()) {
    spott_msgs::ArbiterSource m;
    m.name = src.name;
    m.priority = src.priority;
    m.state = static_cast<std::uint8_t>(src.state);
    m.exclusive = src.exclusive;
    m.commands = src.commands;
    m.refused = src.refused;
    s.sources.push_back(m);
  }
  s.max_linear_mps = arbiter.max_linear_mps();
  s.max_angular_rps = arbiter.max_angular_rps();
  s.limits_reason = arbiter.limits_reason();
  s.bumper_stop = arbiter.bumper_stop();
  s.bumper_stops = arbiter.bumper_stops();
  s.refused = arbiter.refused();
  return s;
}

visualization_msgs::Marker ToDriverMarker(const spott_msgs::ArbiterStatus& status,
                                          const std::string& base_frame) {
  visualization_msgs::Marker m =
      spott_ros::MakeMarker("cmd_vel_arbiter", 0, visualization_msgs::Marker::TEXT_VIEW_FACING,
                            base_frame, status.header.stamp);
  m.pose.position.z = 1.0;  // below the TR+ controller's firing rule
  m.scale.z = 0.25;
  std::string text = "wheels: " + (status.driver.empty() ? std::string("nobody") : status.driver);
  if (!status.exclusive_holder.empty()) text += " (held by " + status.exclusive_holder + ")";
  if (status.bumper_stop) text += "; bumper stop";
  if (!status.limits_reason.empty()) text += "; limits: " + status.limits_reason;
  m.text = text;
  m.color = status.bumper_stop ? spott_ros::Colour(1.0f, 0.2f, 0.2f)
                               : spott_ros::Colour(0.6f, 0.9f, 1.0f);
  return m;
}

}  // namespace cmd_vel_arbiter::ros_conversions
