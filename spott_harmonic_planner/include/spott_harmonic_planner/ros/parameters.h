// The node's parameters: read from the parameter server and validated by name (tested by the
// rostest, which has a master).
#pragma once

#include <ros/node_handle.h>

#include <string>
#include <vector>

#include "spott_harmonic_planner/local_planner.h"

namespace spott_harmonic_planner {

struct NodeParameters {
  PlannerParameters planner;
  std::string frame_id = "map";
  std::string base_frame = "base_link";
  double cycle_rate_hz = 20.0;         ///< (0, 1000]
  int visualization_every = 5;         ///< Cycles between potential/contour/path messages, >= 1.
  int unreachable_cycles = 40;         ///< Cycles without a usable answer before aborting, >= 1.
  double heading_tolerance_rad = 0.1;  ///< Default final heading tolerance (rad), (0, pi].
};

/// Reads every parameter of config/harmonic_planner.yaml from `pnh` (defaults where unset) and
/// returns every violation, each naming its parameter ("~resolution must be ...").
std::vector<std::string> ReadParameters(const ros::NodeHandle& pnh, NodeParameters& p);

}  // namespace spott_harmonic_planner
