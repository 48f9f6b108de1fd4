#include "markov_localization/ros/sensed_map_parameters.h"

#include <utility>

#include "markov_localization/ros/parameters.h"
#include "spott_ros/parameter_reader.h"

namespace markov_localization {

void ReadParameters(spott_ros::ParameterReader& r, SensedMapNodeParameters& p) {
  r.Get("world_file", p.world_file);
  GetPoseText(r, "initial_pose", p.initial_pose);
  GetPoseText(r, "last_map_to_odom", p.last_map_to_odom);
  r.Get("map_frame", p.map_frame);
  r.Get("odom_frame", p.odom_frame);
  r.Get("ring_topic", p.ring_topic);
  r.Get("features_topic", p.features_topic);
  r.Get("profile_topic", p.profile_topic);
  r.Get("profile_min_height_m", p.profile_min_height_m, "m");
  r.Get("profile_max_height_m", p.profile_max_height_m, "m");
  r.Require(p.profile_min_height_m < p.profile_max_height_m, "profile_max_height_m",
            "above profile_min_height_m", p.profile_max_height_m);
  r.Get("segment_sensors", p.segment_sensors);
  r.Get("transform_tolerance_s", p.transform_tolerance_s, "s");
  r.Require(p.transform_tolerance_s >= 0.0 && p.transform_tolerance_s <= 1.0,
            "transform_tolerance_s", "in [0, 1]", p.transform_tolerance_s);
  r.Get("odometry_max_lag_s", p.odometry_max_lag_s, "s");
  r.Require(p.odometry_max_lag_s > 0.0 && p.odometry_max_lag_s <= 5.0, "odometry_max_lag_s",
            "in (0, 5]", p.odometry_max_lag_s);
  const std::pair<const char*, const std::string*> names[] = {{"map_frame", &p.map_frame},
                                                              {"odom_frame", &p.odom_frame},
                                                              {"ring_topic", &p.ring_topic},
                                                              {"features_topic", &p.features_topic},
                                                              {"profile_topic", &p.profile_topic}};
  for (const auto& [key, value] : names) {
    if (value->empty()) r.Fail(std::string("~") + key + " must not be empty");
  }
  if (!p.map_frame.empty() && p.map_frame == p.odom_frame)
    r.Fail("~odom_frame must differ from ~map_frame (both '" + p.map_frame + "')");
  SensedMapTrackerParameters& t = p.tracker;
  r.Get("period_s", t.period_s, "s");
  r.Get("window_s", t.window_s, "s");
  r.Get("max_range_m", t.max_range_m, "m");
  r.Get("min_segment_length_m", t.min_segment_length_m, "m");
  r.Get("extend_m", t.extend_m, "m");
  r.GetDegrees("max_incidence_deg", t.max_incidence_rad);
  r.Get("gate_m", t.gate_m, "m");
  r.Get("huber_m", t.huber_m, "m");
  r.Get("iterations", t.iterations);
  r.Get("min_echoes", t.min_echoes);
  r.Get("min_information", t.min_information);
  r.Get("correct_heading", t.correct_heading);
  r.Get("max_correction_m", t.max_correction_m, "m");
  r.GetDegrees("max_correction_deg", t.max_correction_rad);
  WallLatticeParameters& w = t.wall_lattice;
  r.Get("wall_lattice/enabled", w.enabled);
  r.Get("wall_lattice/period_s", w.period_s, "s");
  r.Get("wall_lattice/window_s", w.window_s, "s");
  r.GetDegrees("wall_lattice/axis_deg", w.axis_rad);
  r.GetDegrees("wall_lattice/gate_deg", w.gate_rad);
  r.GetDegrees("wall_lattice/agree_deg", w.agree_rad);
  r.Get("wall_lattice/min_length_m", w.min_length_m, "m");
  r.Get("wall_lattice/min_points", w.min_points);
  r.Get("wall_lattice/max_rms_m", w.max_rms_m, "m");
  r.Get("wall_lattice/break_m", w.break_m, "m");
  r.Get("wall_lattice/min_total_m", w.min_total_m, "m");
  for (std::string e : ValidateParameters(t)) {
    for (const char* name : {"max_incidence_rad", "max_correction_rad", "wall_lattice/axis_rad",
                             "wall_lattice/gate_rad", "wall_lattice/agree_rad"}) {
      const std::string n = name;
      if (e.rfind(n, 0) == 0) e = n.substr(0, n.size() - 3) + "deg" + e.substr(n.size());
    }
    r.Fail("~" + e);
  }
}

std::vector<std::string> ReadParameters(const ros::NodeHandle& pnh, SensedMapNodeParameters& p) {
  spott_ros::ParameterReader r = spott_ros::ParameterReader::FromNode(pnh);
  ReadParameters(r, p);
  return r.Finish();
}

}  // namespace markov_localization
