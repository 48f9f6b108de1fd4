#include "robot_sim/ros/parameters.h"

#include <sstream>

#include <ros/param.h>

namespace robot_sim::ros_parameters {

namespace {

void Emit(const XmlRpc::XmlRpcValue& v, std::ostringstream& out) {
  switch (v.getType()) {
    case XmlRpc::XmlRpcValue::TypeArray: {
      out << "[";
      for (int i = 0; i < v.size(); ++i) {
        if (i) out << ", ";
        Emit(v[i], out);
      }
      out << "]";
      break;
    }
    case XmlRpc::XmlRpcValue::TypeStruct: {
      out << "{";
      bool first = true;
      for (auto it = v.begin(); it != v.end(); ++it) {
        if (!first) out << ", ";
        first = false;
        out << "\"" << it->first << "\": ";
        Emit(it->second, out);
      }
      out << "}";
      break;
    }
    case XmlRpc::XmlRpcValue::TypeString: {
      std::string s = static_cast<std::string>(const_cast<XmlRpc::XmlRpcValue&>(v));
      std::string quoted;
      for (char c : s) {
        if (c == '"' || c == '\\') quoted += '\\';
        quoted += c;
      }
      out << "\"" << quoted << "\"";
      break;
    }
    case XmlRpc::XmlRpcValue::TypeBoolean:
      out << (static_cast<bool>(const_cast<XmlRpc::XmlRpcValue&>(v)) ? "true" : "false");
      break;
    case XmlRpc::XmlRpcValue::TypeInt:
      out << static_cast<int>(const_cast<XmlRpc::XmlRpcValue&>(v));
      break;
    case XmlRpc::XmlRpcValue::TypeDouble: {
      std::ostringstream d;
      d.precision(17);
      d << static_cast<double>(const_cast<XmlRpc::XmlRpcValue&>(v));
      out << d.str();
      break;
    }
    default:
      out << "null";
  }
}

}  // namespace

void Read(spott_ros::ParameterReader& r, SimNodeParameters& p) {
  r.Accept("faults");  // parsed by ParseFaultSchedule with line numbers (FaultScheduleYaml)
  r.Get("world_file", p.world_file);
  r.Get("robot", p.robot);
  r.Get("robot_file", p.robot_file);
  r.Get("urdf_file", p.urdf_file);
  r.Get("start_pose", p.start_pose);
  r.Get("seed", p.seed);
  r.Get("physics_rate_hz", p.physics_rate_hz, "Hz");
  r.Get("sensor_rate_hz", p.sensor_rate_hz, "Hz");
  r.Get("laser_rate_hz", p.laser_rate_hz, "Hz");
  r.Get("odom_rate_hz", p.odom_rate_hz, "Hz");
  r.Get("profile_rate_hz", p.profile_rate_hz, "Hz");
  r.Get("real_time_factor", p.real_time_factor);
  r.Get("cmd_vel_timeout_s", p.cmd_vel_timeout_s, "s");
  r.Get("map_frame", p.map_frame);
  r.Get("odom_frame", p.odom_frame);
  r.Get("base_frame", p.base_frame);
  r.Get("wall_height_m", p.world.wall_height_m, "m");
  r.Get("door_leaf_thickness_m", p.world.door_leaf_thickness_m, "m");
  r.Get("octomap_resolution_m", p.world.octomap_resolution_m, "m");
  r.Get("unknown_doors_closed", p.world.unknown_doors_closed);
  r.Get("odometry/linear_scale", p.odometry.linear_scale);
  r.Get("odometry/angular_scale", p.odometry.angular_scale);
  r.Get("odometry/drift_rad_per_m", p.odometry.drift_rad_per_m, "rad/m");
  r.Get("odometry/linear_noise", p.odometry.linear_noise);
  r.Get("odometry/angular_noise", p.odometry.angular_noise);
  r.Get("odometry/angular_noise_per_m", p.odometry.angular_noise_per_m);
  r.Get("publish_octomap_markers", p.publish_octomap_markers);
  r.Get("octomap_file", p.octomap_file);
  r.Get("publish_truth_map_to_odom", p.publish_truth_map_to_odom);
  r.Get("publish_start_map_to_odom", p.publish_start_map_to_odom);
  r.Get("consumers/topics", p.consumers.topics);
  r.Get("consumers/max_lag_s", p.consumers.max_lag_s, "s");
  r.Get("consumers/max_hold_s", p.consumers.max_hold_s, "s");
  r.Get("battery_rate_hz", p.battery_rate_hz, "Hz");
  r.Get("battery/capacity_wh", p.battery.capacity_wh, "Wh");
  r.Get("battery/initial_percent", p.battery.initial_percent, "%");
  r.Get("battery/idle_power_w", p.battery.idle_power_w, "W");
  r.Get("battery/power_per_mps_w", p.battery.power_per_mps_w, "W s/m");
  r.Get("battery/power_per_rps_w", p.battery.power_per_rps_w, "W s/rad");
  r.Get("battery/full_voltage_v", p.battery.full_voltage_v, "V");
  r.Get("battery/empty_voltage_v", p.battery.empty_voltage_v, "V");
  for (const std::string& e : ValidateParameters(p)) r.Fail(e);
}

std::string FaultScheduleYaml(const ros::NodeHandle& pnh) {
  XmlRpc::XmlRpcValue faults;
  if (!pnh.getParam("faults", faults)) return "";
  return FaultScheduleYaml(faults);
}

std::string FaultScheduleYaml(const XmlRpc::XmlRpcValue& faults) {
  std::ostringstream out;
  out << "faults: ";
  Emit(faults, out);
  out << "\n";
  return out.str();
}

}  // namespace robot_sim::ros_parameters
