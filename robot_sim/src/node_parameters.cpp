#include "robot_sim/node_parameters.h"

namespace robot_sim {

std::vector<std::string> ValidateParameters(const SimNodeParameters& p) {
  std::vector<std::string> e;
  if (p.world_file.empty()) e.push_back("world_file is required");
  if (p.robot.empty() || p.robot.find_first_of("/. ") != std::string::npos) {
    e.push_back("robot must be a robot name (nomad200, b21, b12, hilare), got '" + p.robot + "'");
  }
  if (p.seed < 0) e.push_back("seed must be >= 0");
  if (!(p.physics_rate_hz >= 10 && p.physics_rate_hz <= 10000)) {
    e.push_back("physics_rate_hz must be in [10, 10000]");
  }
  // A rate below 0.01 Hz would be published every lround(physics_rate_hz / rate) steps, beyond
  // what a long holds for a tiny rate (then on every step).
  auto rate = [&](double r, const char* name) {
    if (!(r >= 0.01 && r <= p.physics_rate_hz)) {
      e.push_back(std::string(name) + " must be in [0.01, physics_rate_hz]");
    }
  };
  rate(p.sensor_rate_hz, "sensor_rate_hz");
  rate(p.laser_rate_hz, "laser_rate_hz");
  rate(p.odom_rate_hz, "odom_rate_hz");
  rate(p.profile_rate_hz, "profile_rate_hz");
  rate(p.battery_rate_hz, "battery_rate_hz");
  // The loop sleeps until step * dt / real_time_factor of wall time (a ros::WallDuration, at most
  // 2^31 s): below 0.01 a simulated day or less would not fit.
  if (!(p.real_time_factor == 0 || (p.real_time_factor >= 0.01 && p.real_time_factor <= 1e4))) {
    e.push_back("real_time_factor must be 0 (as fast as possible) or in [0.01, 10000]");
  }
  if (!(p.cmd_vel_timeout_s >= 0 && p.cmd_vel_timeout_s < 1e6)) {
    e.push_back("cmd_vel_timeout_s must be in [0, 1e6)");
  }
  for (const std::string* f : {&p.map_frame, &p.odom_frame, &p.base_frame}) {
    if (f->empty()) e.push_back("frames must not be empty (map_frame, odom_frame, base_frame)");
  }
  if (p.publish_truth_map_to_odom && p.publish_start_map_to_odom) {
    e.push_back("publish_truth_map_to_odom and publish_start_map_to_odom: at most one of them");
  }
  for (const std::string& w : ValidateParameters(p.world)) e.push_back(w);
  for (const std::string& w : ValidateParameters(p.consumers)) e.push_back(w);
  for (const std::string& w : ValidateParameters(p.odometry)) e.push_back(w);
  for (const std::string& w : ValidateParameters(p.battery)) e.push_back(w);
  return e;
}

}  // namespace robot_sim
