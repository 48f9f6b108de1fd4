// The node's parameters (config/cmd_vel_arbiter.yaml), read through spott_ros's reader: wrong
// types, values out of range and unknown keys stop the node, each named.
#pragma once

#include "cmd_vel_arbiter/arbiter.h"
#include "spott_ros/parameter_reader.h"

namespace cmd_vel_arbiter {

struct NodeParameters {
  ArbiterParameters arbiter;
  double update_rate_hz = 50.0;  ///< Timeout checks per second (Hz), [0.01, 1000].
  /// Status also at this rate besides every change (Hz): 0 (on change only) or [0.01, 100].
  double status_rate_hz = 2.0;
};

/// Fills `p` (missing keys keep their defaults; one source per key under `sources`) and records
/// every violation in `r` by its key.
void Read(spott_ros::ParameterReader& r, NodeParameters& p);

}  // namespace cmd_vel_arbiter
