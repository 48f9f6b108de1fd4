// The node's parameters (config/cmd_vel_arbiter.yaml), read through spott_ros's reader: wrong
// types, values out of range and unknown keys stop the node, each named.
#pragma once

#include <string>
#include <vector>

#include "cmd_vel_arbiter/arbiter.h"
#include "cmd_vel_arbiter/clearance.h"
#include "spott_ros/parameter_reader.h"

namespace cmd_vel_arbiter {

struct NodeParameters {
  ArbiterParameters arbiter;
  double update_rate_hz = 50.0;  ///< Timeout checks per second (Hz), [0.01, 1000].
  /// Status also at this rate besides every change (Hz): 0 (on change only) or [0.01, 100].
  double status_rate_hz = 2.0;
  /// The clearance bounds (clearance.h) from range rings; off: nothing caps the speed.
  bool clearance_enabled = true;
  /// spott_msgs/RangeRing topics, the tightest bound wins; a topic nobody publishes bounds
  /// nothing (the B21 and HILARE have no infrared ring).
  std::vector<std::string> clearance_topics{"sonar", "infrared"};
  /// sensor_msgs/LaserScan topics bounding alike (the B21's and HILARE's lasers); the scanner's
  /// pose from tf (clearance/base_frame <- the scan's frame), the body's radius from
  /// clearance/footprint_radius_m or the robot description.
  std::vector<std::string> clearance_scan_topics{"scan"};
  std::string base_frame = "base_link";  ///< clearance/base_frame (REP-105).
  double clearance_max_age_s = 0.5;      ///< An older ring bounds nothing (s), (0, 60].
  ClearanceParameters clearance;
};

/// The rings' topics, then the scans': the clearance inputs by index.
std::vector<std::string> ClearanceTopicNames(const NodeParameters& p);

/// Fills `p` (missing keys keep their defaults; one source per key under `sources`) and records
/// every violation in `r` by its key.
void Read(spott_ros::ParameterReader& r, NodeParameters& p);

}  // namespace cmd_vel_arbiter
