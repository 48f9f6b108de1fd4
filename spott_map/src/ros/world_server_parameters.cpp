#include "spott_map/ros/world_server_parameters.h"

namespace spott_map {

void ReadParameters(spott_ros::ParameterReader& r, WorldServerParameters& p) {
  r.Get("world_file", p.world_file);
  r.Get("frame_id", p.frame_id);
  r.Get("map_resolution_m", p.map_resolution_m, "m");
  r.Get("feature_tolerance_m", p.feature_tolerance_m, "m");
  r.Get("a_priori_map", p.a_priori_map);
  if (p.world_file.empty()) r.Fail("world_file is required (path to a world YAML)");
  if (p.frame_id.empty()) r.Fail("frame_id must not be empty");
  r.Require(p.map_resolution_m > 0.0 && p.map_resolution_m <= 10.0, "map_resolution_m",
            "in (0, 10]", p.map_resolution_m);
  r.Require(p.feature_tolerance_m > 0.0, "feature_tolerance_m", "> 0", p.feature_tolerance_m);
}

}  // namespace spott_map
