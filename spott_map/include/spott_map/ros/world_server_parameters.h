// world_server's parameters (config/world_server.yaml), read through spott_ros's reader: wrong
// types, values out of range and unknown keys stop the node, each named.
#pragma once

#include <string>

#include "spott_ros/parameter_reader.h"

namespace spott_map {

struct WorldServerParameters {
  std::string world_file;  ///< Required.
  std::string frame_id = "map";
  double map_resolution_m = 0.05;    ///< (0, 10]
  double feature_tolerance_m = 0.1;  ///< > 0: sensed features this close are "already there".
  /// false: the map database starts empty (no walls, rooms or doors; the places, zones and paths
  /// of tasks are still served): the robot knows only what its sensors add (SPOTT's Experiment 1).
  bool a_priori_map = true;
};

/// Fills `p` (missing keys keep their defaults) and records every violation in `r` by its key.
void ReadParameters(spott_ros::ParameterReader& r, WorldServerParameters& p);

}  // namespace spott_map
