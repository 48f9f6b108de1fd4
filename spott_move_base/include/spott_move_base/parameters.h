// The node's parameters (config/move_base.yaml), read through spott_ros's reader: wrong types,
// values out of range and unknown keys stop the node, each named.
#pragma once

#include <string>

#include "spott_ros/parameter_reader.h"

namespace spott_move_base {

struct NodeParameters {
  std::string navigate_action = "harmonic_planner/navigate";
  /// Wait this long for the Navigate server per goal (s), (0, 3600].
  double server_timeout_s = 30.0;
};

/// Fills `p` (missing keys keep their defaults) and records every violation in `r` by its key.
void Read(spott_ros::ParameterReader& r, NodeParameters& p);

}  // namespace spott_move_base
