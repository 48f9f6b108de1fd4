// Parameters of the robot_sim node (config/robot_sim.yaml documents each with its default).
#pragma once

#include <string>
#include <vector>

#include "robot_sim/battery.h"
#include "robot_sim/consumer_pacer.h"
#include "robot_sim/drive.h"
#include "robot_sim/sim_world.h"

namespace robot_sim {

struct SimNodeParameters {
  std::string world_file;          ///< spott_map world file (required).
  std::string robot = "nomad200";  ///< nomad200 | b21 | b12 | hilare
  std::string robot_file;          ///< Robot YAML; "" = <package>/config/robots/<robot>.yaml
  std::string urdf_file;           ///< URDF; "" = <package>/urdf/<robot>.urdf
  std::string start_pose;          ///< "" = the world's robot_start; else "x y yaw" (m, m, rad)
  int seed = 1;                    ///< Seeds every random draw, >= 0.
  double physics_rate_hz = 100.0;  ///< [10, 10000]
  double sensor_rate_hz = 10.0;    ///< Sonar, infrared, bumper; [0.01, physics_rate_hz]
  double laser_rate_hz = 10.0;     ///< [0.01, physics_rate_hz]
  double profile_rate_hz = 1.0;    ///< QUADRIS profiles (horizontal and vertical); [0.01, physics]
  double odom_rate_hz = 50.0;      ///< /odom, tf, ground truth, joint states; [0.01, physics]
  /// Simulated s per wall s; 0 = as fast as possible, else [0.01, 1e4].
  double real_time_factor = 1.0;
  double cmd_vel_timeout_s = 1.0;  ///< Stop without a command for this long (sim s); 0 = never
  std::string map_frame = "map";
  std::string odom_frame = "odom";
  std::string base_frame = "base_link";
  SimWorldParameters world;
  OdometryErrorModel odometry;
  bool publish_octomap_markers = true;
  /// Publish map->odom from the ground truth (demos and screenshots without localization only:
  /// off whenever a localization node publishes map->odom).
  bool publish_truth_map_to_odom = false;
  /// Publish map->odom as it was at the start, held (dead reckoning: the robot knows where it
  /// started and then only its odometry; SPOTT's Experiment 1 without a map to localize on).
  /// Not with publish_truth_map_to_odom.
  bool publish_start_map_to_odom = false;
  std::string octomap_file = "/tmp/robot_sim.bt";  ///< Where ~save_octomap writes.
  /// The stack's outputs whose lag holds the clock (consumer_pacer.h).
  PacerParameters consumers;
  /// The battery's drain model (battery.h) and how often /battery is published, [0.01, physics].
  BatteryParameters battery;
  double battery_rate_hz = 1.0;
};

/// One message per violated parameter, naming it as in the YAML file.
std::vector<std::string> ValidateParameters(const SimNodeParameters& p);

}  // namespace robot_sim
