// The global_planner node's parameters, read from its private namespace as one XmlRpc struct
// (what `ros::NodeHandle("~").getParam("", value)` returns) so that the checks run without a
// ROS master in tests.
#pragma once

#include <string>
#include <vector>

#include <xmlrpcpp/XmlRpcValue.h>

#include "spott_global_planner/planning_session.h"

namespace spott_global_planner::ros_parameters {

struct NodeParameters {
  std::string frame_id = "map";           ///< frame of the graph, goals and outputs
  std::string robot_frame = "base_link";  ///< pose = tf frame_id -> robot_frame
  double update_rate_hz = 5.0;            ///< (0, 100]
  bool follow_local_window = true;        ///< use the window received on local_window
  GlobalPlannerParameters core;
};

/// Fills `p` from the private namespace `params` (a struct; missing names keep their defaults)
/// and returns every violation, each naming its parameter ("~window/window_size_m must be > 0
/// (got -1)"): wrong types, values out of range, and names that are no parameter of the node.
std::vector<std::string> ReadParameters(XmlRpc::XmlRpcValue& params, NodeParameters& p);

}  // namespace spott_global_planner::ros_parameters
