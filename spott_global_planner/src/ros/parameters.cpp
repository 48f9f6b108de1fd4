#include "spott_global_planner/ros/parameters.h"

namespace spott_global_planner::ros_parameters {

void ReadParameters(spott_ros::ParameterReader& r, NodeParameters& p) {
  r.Get("frame_id", p.frame_id);
  r.Get("odom_frame", p.odom_frame);
  r.Get("robot_frame", p.robot_frame);
  r.Get("robot_description", p.robot_description);
  r.Get("update_rate_hz", p.update_rate_hz, "Hz");
  r.Get("follow_local_window", p.follow_local_window);
  std::string algorithm = ToString(p.core.algorithm);
  r.Get("algorithm", algorithm);
  if (const auto a = ParseSearchAlgorithm(algorithm)) {
    p.core.algorithm = *a;
  } else {
    r.Fail("algorithm must be dijkstra or astar (got '" + algorithm + "')");
  }
  WindowParameters& w = p.core.window;
  r.Get("window/window_size_m", w.window_size_m, "m");
  r.Get("window/resolution_m", w.resolution_m, "m");
  r.Get("window/recentre_margin_m", w.recentre_margin_m, "m");
  r.Get("window/fit_node", w.fit_node);
  r.Get("window/max_window_size_m", w.max_window_size_m, "m");
  r.Get("detect_blocked_passages", p.core.detect_blocked_passages);
  PassageParameters& s = p.core.passage;
  r.Get("passage/resolution_m", s.resolution_m, "m");
  r.Get("passage/max_localization_error_m", p.max_localization_error_m, "m");
  r.Get("passage/door_depth_m", s.door_depth_m, "m");
  r.Get("passage/max_cells", s.max_cells);
  if (p.frame_id.empty()) r.Fail("frame_id must not be empty");
  if (p.robot_frame.empty()) r.Fail("robot_frame must not be empty");
  // The timer's period 1 / update_rate_hz must make a ros::Duration (at most 2^31 s).
  r.Require(p.update_rate_hz >= 0.01 && p.update_rate_hz <= 100.0, "update_rate_hz",
            "in [0.01, 100]", p.update_rate_hz);
  r.Require(p.max_localization_error_m >= 0.0, "passage/max_localization_error_m", ">= 0",
            p.max_localization_error_m);
}

void ValidateCore(spott_ros::ParameterReader& r, const NodeParameters& p) {
  for (const std::string& s : ValidateParameters(p.core)) {
    // The padding is the robot's radius plus passage/max_localization_error_m, checked above.
    if (s.rfind("passage/padding_m", 0) != 0) r.Fail(s);
  }
}

}  // namespace spott_global_planner::ros_parameters
