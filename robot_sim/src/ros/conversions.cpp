#include "robot_sim/ros/conversions.h"

#include <cmath>
#include <limits>
#include <map>

#include <spott_msgs/Door.h>
#include <tf2/LinearMath/Quaternion.h>

#include "spott_map/geometry.h"
#include "spott_ros/markers.h"

namespace robot_sim::ros_conversions {

namespace {

geometry_msgs::Quaternion YawToQuaternion(double yaw) {
  geometry_msgs::Quaternion q;
  q.z = std::sin(yaw / 2);
  q.w = std::cos(yaw / 2);
  return q;
}

}  // namespace

Twist2 FromMsg(const geometry_msgs::Twist& msg) { return {msg.linear.x, msg.angular.z}; }

spott_msgs::RangeRing ToRangeRing(const RangeRingSpec& ring, const std::vector<double>& ranges,
                                  const std::string& base_frame, const ros::Time& stamp,
                                  double turret_yaw) {
  spott_msgs::RangeRing msg;
  msg.header.frame_id = base_frame;
  msg.header.stamp = stamp;
  msg.radiation_type = ring.kind == RangeKind::kUltrasound ? spott_msgs::RangeRing::ULTRASOUND
                                                           : spott_msgs::RangeRing::INFRARED;
  msg.field_of_view = ring.field_of_view;
  msg.min_range = ring.min_range;
  msg.max_range = ring.max_range;
  const double c = std::cos(turret_yaw), s = std::sin(turret_yaw);
  for (const Mount& m : ring.mounts) {
    geometry_msgs::Pose2D p;
    p.x = c * m.x - s * m.y;
    p.y = s * m.x + c * m.y;
    p.theta = spott_map::NormalizeAngle(m.yaw + turret_yaw);
    msg.mounts.push_back(p);
    msg.frame_ids.push_back(m.frame_id);
  }
  msg.ranges.assign(ranges.begin(), ranges.end());
  return msg;
}

sensor_msgs::Range ToRange(const RangeRingSpec& ring, std::size_t index, double range,
                           const ros::Time& stamp) {
  sensor_msgs::Range msg;
  msg.header.frame_id = ring.mounts.at(index).frame_id;
  msg.header.stamp = stamp;
  msg.radiation_type = ring.kind == RangeKind::kUltrasound ? sensor_msgs::Range::ULTRASOUND
                                                           : sensor_msgs::Range::INFRARED;
  msg.field_of_view = ring.field_of_view;
  msg.min_range = ring.min_range;
  msg.max_range = ring.max_range;
  msg.range =
      range >= ring.max_range ? std::numeric_limits<float>::infinity() : static_cast<float>(range);
  return msg;
}

sensor_msgs::LaserScan ToLaserScan(const LaserSpec& laser, const std::vector<double>& ranges,
                                   double scan_period, const ros::Time& stamp) {
  sensor_msgs::LaserScan msg;
  msg.header.frame_id = laser.mount.frame_id;
  msg.header.stamp = stamp;
  msg.angle_min = laser.angle_min;
  msg.angle_max = laser.angle_max;
  msg.angle_increment = (laser.angle_max - laser.angle_min) / (laser.beams - 1);
  msg.scan_time = scan_period;
  msg.time_increment = 0.0;  // all beams at one instant
  msg.range_min = laser.min_range;
  msg.range_max = laser.max_range;
  msg.ranges.assign(ranges.begin(), ranges.end());
  return msg;
}

spott_msgs::RangeProfile ToRangeProfile(const ProfilerSpec& profiler, bool horizontal, double pan,
                                        double tilt, const std::vector<double>& angles,
                                        const std::vector<double>& ranges, const ros::Time& stamp) {
  spott_msgs::RangeProfile msg;
  msg.header.frame_id = profiler.mount.frame_id;
  msg.header.stamp = stamp;
  msg.orientation =
      horizontal ? spott_msgs::RangeProfile::HORIZONTAL : spott_msgs::RangeProfile::VERTICAL;
  msg.pan = pan;
  msg.tilt = tilt;
  msg.max_range = profiler.max_range;
  for (std::size_t k = 0; k < ranges.size(); ++k) {
    const double a = angles.at(k), r = ranges[k];
    msg.angles.push_back(a);
    msg.ranges.push_back(r);
    geometry_msgs::Point32 p;
    if (std::isfinite(r)) {
      p.x = r * std::cos(a);
      p.y = horizontal ? r * std::sin(a) : 0.0;
      p.z = horizontal ? 0.0 : -r * std::sin(a);  // positive angles look down
    } else {
      p.x = p.y = p.z = std::numeric_limits<float>::quiet_NaN();
    }
    msg.points.push_back(p);
  }
  return msg;
}

spott_msgs::BumperRing ToBumperRing(const BumperSpec& bumper, const std::vector<bool>& pressed,
                                    const std::string& base_frame, const ros::Time& stamp) {
  spott_msgs::BumperRing msg;
  msg.header.frame_id = base_frame;
  msg.header.stamp = stamp;
  msg.segment_width = 2 * M_PI / bumper.segments;
  for (int i = 0; i < bumper.segments; ++i) {
    msg.segment_angles.push_back(std::remainder(i * msg.segment_width, 2 * M_PI));
  }
  msg.pressed.assign(pressed.begin(), pressed.end());
  return msg;
}

visualization_msgs::MarkerArray ToBumperMarkers(const BumperSpec& bumper, double radius_m,
                                                const std::vector<bool>& pressed,
                                                const std::string& base_frame,
                                                const ros::Time& stamp) {
  visualization_msgs::MarkerArray out;
  visualization_msgs::Marker m = spott_ros::MakeMarker(
      "bumper", 0, visualization_msgs::Marker::SPHERE_LIST, base_frame, stamp);
  m.scale.x = m.scale.y = m.scale.z = 0.08;
  m.color = spott_ros::Colour(1.0f, 0.1f, 0.1f);
  const double width = 2 * M_PI / bumper.segments;
  for (std::size_t i = 0; i < pressed.size() && static_cast<int>(i) < bumper.segments; ++i) {
    if (!pressed[i]) continue;
    geometry_msgs::Point p;
    p.x = radius_m * std::cos(i * width);
    p.y = radius_m * std::sin(i * width);
    p.z = 0.1;
    m.points.push_back(p);
  }
  if (m.points.empty()) m.action = visualization_msgs::Marker::DELETEALL;
  out.markers.push_back(m);
  return out;
}

sensor_msgs::BatteryState ToBatteryState(const Battery& battery, const std::string& frame,
                                         const ros::Time& stamp) {
  sensor_msgs::BatteryState msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = frame;
  msg.voltage = static_cast<float>(battery.voltage_v());
  msg.current = static_cast<float>(-battery.current_a());
  msg.charge = static_cast<float>(battery.charge_ah());
  msg.capacity = static_cast<float>(battery.capacity_ah());
  msg.design_capacity = msg.capacity;
  msg.percentage = static_cast<float>(battery.percent() / 100.0);
  msg.power_supply_status = sensor_msgs::BatteryState::POWER_SUPPLY_STATUS_DISCHARGING;
  msg.power_supply_health = sensor_msgs::BatteryState::POWER_SUPPLY_HEALTH_GOOD;
  msg.power_supply_technology = sensor_msgs::BatteryState::POWER_SUPPLY_TECHNOLOGY_UNKNOWN;
  msg.present = true;
  return msg;
}

nav_msgs::Odometry ToOdometry(const spott_map::Pose2& pose, const Twist2& twist,
                              const std::string& frame, const std::string& child,
                              const ros::Time& stamp) {
  nav_msgs::Odometry msg;
  msg.header.frame_id = frame;
  msg.header.stamp = stamp;
  msg.child_frame_id = child;
  msg.pose.pose.position.x = pose.x;
  msg.pose.pose.position.y = pose.y;
  msg.pose.pose.orientation = YawToQuaternion(pose.yaw);
  msg.twist.twist.linear.x = twist.v;
  msg.twist.twist.angular.z = twist.w;
  return msg;
}

visualization_msgs::MarkerArray ToVoxelMarkers(const std::vector<VoxelLeaf>& leaves,
                                               const std::string& frame, const ros::Time& stamp) {
  std::map<double, visualization_msgs::Marker> by_size;
  for (const VoxelLeaf& leaf : leaves) {
    auto [it, inserted] = by_size.try_emplace(leaf.size);
    visualization_msgs::Marker& m = it->second;
    if (inserted) {
      m.header.frame_id = frame;
      m.header.stamp = stamp;
      m.ns = "octomap";
      m.id = static_cast<int>(by_size.size());
      m.type = visualization_msgs::Marker::CUBE_LIST;
      m.action = visualization_msgs::Marker::ADD;
      m.pose.orientation.w = 1.0;
      m.scale.x = m.scale.y = m.scale.z = leaf.size;
      m.color.a = 1.0;
    }
    geometry_msgs::Point p;
    p.x = leaf.centre.x();
    p.y = leaf.centre.y();
    p.z = leaf.centre.z();
    m.points.push_back(p);
    std_msgs::ColorRGBA c;  // height ramp: blue low, yellow high
    const double h = std::clamp(leaf.centre.z() / 2.5, 0.0, 1.0);
    c.r = h;
    c.g = 0.4 + 0.5 * h;
    c.b = 1.0 - h;
    c.a = 1.0;
    m.colors.push_back(c);
  }
  visualization_msgs::MarkerArray out;
  visualization_msgs::Marker clear;
  clear.action = visualization_msgs::Marker::DELETEALL;
  clear.ns = "octomap";
  out.markers.push_back(clear);
  for (auto& [size, m] : by_size) out.markers.push_back(std::move(m));
  return out;
}

bool FromRequest(const spott_msgs::Kidnap::Request& req, FaultEvent& e, std::string*) {
  e = FaultEvent{};
  e.kind = FaultEvent::Kind::kKidnap;
  e.relative = req.relative;
  e.pose = {req.pose.x, req.pose.y, req.pose.theta};
  return true;
}

bool FromRequest(const spott_msgs::SetDoorState::Request& req, FaultEvent& e, std::string* error) {
  e = FaultEvent{};
  e.kind = FaultEvent::Kind::kDoor;
  e.name = req.door_id;
  if (req.state != spott_msgs::Door::OPEN && req.state != spott_msgs::Door::CLOSED) {
    if (error)
      *error = "door state must be OPEN (1) or CLOSED (2) in the simulator, got " +
               std::to_string(req.state);
    return false;
  }
  e.closed = req.state == spott_msgs::Door::CLOSED;
  return true;
}

bool FromRequest(const spott_msgs::SensorFault::Request& req, FaultEvent& e, std::string* error) {
  e = FaultEvent{};
  e.kind = FaultEvent::Kind::kSensor;
  e.name = req.sensor;
  e.noise_stddev = req.noise_stddev;
  e.duration = req.duration;
  switch (req.fault) {
    case spott_msgs::SensorFault::Request::DROPOUT:
      e.sensor_fault = FaultKind::kDropout;
      break;
    case spott_msgs::SensorFault::Request::STUCK:
      e.sensor_fault = FaultKind::kStuck;
      break;
    case spott_msgs::SensorFault::Request::NOISE:
      e.sensor_fault = FaultKind::kNoise;
      break;
    case spott_msgs::SensorFault::Request::CLEAR:
      e.kind = FaultEvent::Kind::kClearSensor;
      break;
    default:
      if (error) *error = "unknown fault " + std::to_string(req.fault) + " (0 to 3)";
      return false;
  }
  return true;
}

bool FromRequest(const spott_msgs::OdometrySlip::Request& req, FaultEvent& e, std::string*) {
  e = FaultEvent{};
  e.kind = FaultEvent::Kind::kSlip;
  e.linear_scale = req.linear_scale;
  e.angular_scale = req.angular_scale;
  e.duration = req.duration;
  return true;
}

bool FromRequest(const spott_msgs::AddObstacle::Request& req, FaultEvent& e, std::string* error) {
  e = FaultEvent{};
  e.kind = FaultEvent::Kind::kAddObstacle;
  static const char* const kKinds[] = {"chair", "desk", "partition", "cuboid", "cylinder"};
  if (std::find(std::begin(kKinds), std::end(kKinds), req.kind) == std::end(kKinds)) {
    if (error)
      *error = "obstacle kind must be chair, desk, partition, cuboid or cylinder, got '" +
               req.kind + "'";
    return false;
  }
  e.obstacle.id = req.id;
  e.obstacle.cylinder = req.kind == "cylinder";
  e.obstacle.pose = {req.pose.x, req.pose.y, req.pose.theta};
  e.obstacle.size_x = req.size.x;
  e.obstacle.size_y = req.size.y;
  e.obstacle.height = req.size.z;
  return true;
}

}  // namespace robot_sim::ros_conversions
