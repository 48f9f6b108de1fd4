#include "robot_sim/ros/parameters.h"

#include <set>
#include <sstream>

#include <ros/param.h>

namespace robot_sim::ros_parameters {

namespace {

template <typename T>
void Get(const ros::NodeHandle& pnh, const std::string& name, T& value,
         std::vector<std::string>& errors, std::set<std::string>& known) {
  known.insert(name);
  if (!pnh.hasParam(name)) return;
  if (!pnh.getParam(name, value)) errors.push_back(name + " has the wrong type");
}

void GetDouble(const ros::NodeHandle& pnh, const std::string& name, double& value,
               std::vector<std::string>& errors, std::set<std::string>& known) {
  known.insert(name);
  if (!pnh.hasParam(name)) return;
  XmlRpc::XmlRpcValue v;
  pnh.getParam(name, v);
  if (v.getType() == XmlRpc::XmlRpcValue::TypeDouble) {
    value = static_cast<double>(v);
  } else if (v.getType() == XmlRpc::XmlRpcValue::TypeInt) {
    value = static_cast<int>(v);
  } else {
    errors.push_back(name + " must be a number");
  }
}

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

std::vector<std::string> Read(const ros::NodeHandle& pnh, SimNodeParameters& p) {
  std::vector<std::string> errors;
  std::set<std::string> known = {"faults", "robot_description"};
  Get(pnh, "world_file", p.world_file, errors, known);
  Get(pnh, "robot", p.robot, errors, known);
  Get(pnh, "robot_file", p.robot_file, errors, known);
  Get(pnh, "urdf_file", p.urdf_file, errors, known);
  Get(pnh, "start_pose", p.start_pose, errors, known);
  Get(pnh, "seed", p.seed, errors, known);
  GetDouble(pnh, "physics_rate_hz", p.physics_rate_hz, errors, known);
  GetDouble(pnh, "sensor_rate_hz", p.sensor_rate_hz, errors, known);
  GetDouble(pnh, "laser_rate_hz", p.laser_rate_hz, errors, known);
  GetDouble(pnh, "odom_rate_hz", p.odom_rate_hz, errors, known);
  GetDouble(pnh, "profile_rate_hz", p.profile_rate_hz, errors, known);
  GetDouble(pnh, "real_time_factor", p.real_time_factor, errors, known);
  GetDouble(pnh, "cmd_vel_timeout_s", p.cmd_vel_timeout_s, errors, known);
  Get(pnh, "map_frame", p.map_frame, errors, known);
  Get(pnh, "odom_frame", p.odom_frame, errors, known);
  Get(pnh, "base_frame", p.base_frame, errors, known);
  GetDouble(pnh, "wall_height_m", p.world.wall_height_m, errors, known);
  GetDouble(pnh, "door_leaf_thickness_m", p.world.door_leaf_thickness_m, errors, known);
  GetDouble(pnh, "octomap_resolution_m", p.world.octomap_resolution_m, errors, known);
  Get(pnh, "unknown_doors_closed", p.world.unknown_doors_closed, errors, known);
  GetDouble(pnh, "odometry/linear_scale", p.odometry.linear_scale, errors, known);
  GetDouble(pnh, "odometry/angular_scale", p.odometry.angular_scale, errors, known);
  GetDouble(pnh, "odometry/drift_rad_per_m", p.odometry.drift_rad_per_m, errors, known);
  GetDouble(pnh, "odometry/linear_noise", p.odometry.linear_noise, errors, known);
  GetDouble(pnh, "odometry/angular_noise", p.odometry.angular_noise, errors, known);
  GetDouble(pnh, "odometry/angular_noise_per_m", p.odometry.angular_noise_per_m, errors, known);
  Get(pnh, "publish_octomap_markers", p.publish_octomap_markers, errors, known);
  Get(pnh, "octomap_file", p.octomap_file, errors, known);
  Get(pnh, "publish_truth_map_to_odom", p.publish_truth_map_to_odom, errors, known);
  // Unknown names under the node's namespace: most likely typos.
  std::vector<std::string> names;
  ros::param::getParamNames(names);
  const std::string prefix = pnh.getNamespace() + "/";
  for (const std::string& full : names) {
    if (full.rfind(prefix, 0) != 0) continue;
    const std::string name = full.substr(prefix.size());
    if (!known.count(name)) errors.push_back("unknown parameter '" + name + "'");
  }
  for (const std::string& e : ValidateParameters(p)) errors.push_back(e);
  return errors;
}

std::string FaultScheduleYaml(const ros::NodeHandle& pnh) {
  XmlRpc::XmlRpcValue faults;
  if (!pnh.getParam("faults", faults)) return "";
  std::ostringstream out;
  out << "faults: ";
  Emit(faults, out);
  out << "\n";
  return out.str();
}

}  // namespace robot_sim::ros_parameters
