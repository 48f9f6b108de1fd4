#include "markov_localization/ros/parameters.h"

#include <algorithm>
#include <cmath>

#include "spott_map/pose_text.h"
#include "spott_ros/parameter_reader.h"

namespace markov_localization {
namespace {

// The core's messages name struct fields; the node's names are the YAML keys.
void AddCore(std::vector<std::string>& errors, const std::vector<std::string>& core,
             const std::string& section) {
  for (std::string e : core) {
    std::string prefix = section;
    if (e.rfind("motion.", 0) == 0) {
      e = e.substr(7);
      prefix = "motion";
    } else if (e.rfind("lost.", 0) == 0) {
      e = e.substr(5);
      prefix = "lost";
    }
    if (e.rfind("angular_resolution_rad", 0) == 0)
      e = "angular_resolution_deg" + e.substr(22) + " (in degrees: 360 / it an integer)";
    for (const char* name : {"mode_radius_rad", "estimate_jump_rad", "front_half_angle_rad"}) {
      const std::string n = name;
      if (e.rfind(n, 0) == 0)
        e = n.substr(0, n.size() - 3) + "deg" + e.substr(n.size()) + " (given in degrees)";
    }
    errors.push_back("~" + prefix + "/" + e);
  }
}

}  // namespace

void GetPoseText(spott_ros::ParameterReader& r, const std::string& key,
                 std::optional<spott_map::Pose2>& pose) {
  std::string text;
  r.Get(key, text);
  if (text.empty()) return;
  std::string why;
  pose = spott_map::ParsePoseText(text, &why);
  if (!pose) r.Fail("~" + key + ": " + why);
}

void ReadParameters(spott_ros::ParameterReader& r, NodeParameters& p) {
  std::vector<std::string> v;  // this node's own checks, handed to the reader at the end
  r.Get("world_file", p.world_file);
  r.Get("map_file", p.map_file);
  r.Get("use_map_topic", p.use_map_topic);
  r.Get("map_topic", p.map_topic);
  r.Get("map_updates_topic", p.map_updates_topic);
  r.Get("map_update_features", p.map_update_features);
  r.Get("sonar_enabled", p.sonar_enabled);
  r.Get("ring_topic", p.ring_topic);
  r.Get("sonar_off_max_s", p.sonar_off_max_s);
  auto& g = p.gate;
  r.Get("gate/update_min_d_m", g.update_min_d_m);
  r.GetDegrees("gate/update_min_a_deg", g.update_min_a_rad);
  r.Get("gate/standing_interval_s", g.standing_interval_s);
  r.Get("gate/join_s", g.join_s, "s");
  // A single-ray model's keys below `section` (the laser's, the profiles').
  const auto get_ray_model = [&](const std::string& section, SensorModelParameters& m) {
    r.Get(section + "/max_range_m", m.max_range_m, "m");
    r.Get(section + "/range_bin_m", m.range_bin_m, "m");
    r.Get(section + "/sigma_hit_m", m.sigma_hit_m, "m");
    r.Get(section + "/lambda_short_per_m", m.lambda_short_per_m, "1/m");
    r.Get(section + "/z_hit", m.z_hit);
    r.Get(section + "/z_short", m.z_short);
    r.Get(section + "/z_max", m.z_max);
    r.Get(section + "/z_rand", m.z_rand);
  };
  auto& l = p.laser;
  l.model.max_range_m = 25.0;
  l.model.critical_angle_rad = M_PI / 2;  // a laser scatters off every surface
  r.Get("laser/enabled", l.enabled);
  r.Get("laser/topic", l.topic);
  r.Get("laser/max_beams", l.max_beams);
  r.Get("laser/base_frame", l.base_frame);
  get_ray_model("laser", l.model);
  auto& f = p.profile;
  f.model.max_range_m = 4.0;
  f.model.critical_angle_rad = M_PI / 2;  // a light stripe scatters off every surface
  r.Get("profile/enabled", f.enabled);
  r.Get("profile/topic", f.topic);
  r.Get("profile/base_frame", f.base_frame);
  r.Get("profile/min_height_m", f.min_height_m, "m");
  r.Get("profile/max_height_m", f.max_height_m, "m");
  get_ray_model("profile", f.model);
  r.Get("estimate/refine", p.refine.enabled);
  r.Get("estimate/refine_sigma_scale", p.refine.sigma_scale);
  r.Get("estimate/refine_max_offset_cells", p.refine.max_offset_cells);
  r.Get("map_frame", p.map_frame);
  r.Get("odom_frame", p.odom_frame);
  r.Get("transform_tolerance_s", p.transform_tolerance_s);
  r.Get("odometry_max_lag_s", p.odometry_max_lag_s);
  r.Get("start_uniform", p.start_uniform);
  r.Get("initial_pose_from_world", p.initial_pose_from_world);
  GetPoseText(r, "initial_pose", p.initial_pose);
  GetPoseText(r, "last_map_to_odom", p.last_map_to_odom);
  GetPoseText(r, "last_odom", p.last_odom);
  r.Get("last_sigma_xy_m", p.last_sigma_xy_m, "m");
  r.GetDegrees("last_sigma_theta_deg", p.last_sigma_theta_rad);
  r.Get("save_pose_period_s", p.save_pose_period_s, "s");
  r.Require(p.save_pose_period_s >= 0.0 && p.save_pose_period_s <= 60.0, "save_pose_period_s",
            "in [0, 60]", p.save_pose_period_s);
  r.Get("initial_sigma_xy_m", p.initial_sigma_xy_m);
  r.GetDegrees("initial_sigma_theta_deg", p.initial_sigma_theta_rad);
  r.Get("belief_rate_hz", p.belief_rate_hz);

  r.Get("map/resolution_m", p.map.resolution_m);
  r.Get("map/state_clearance_m", p.map.state_clearance_m);
  r.Get("map/door_thickness_m", p.map.door_thickness_m);
  r.Get("map/ray_cast_subdivision", p.map.ray_cast_subdivision);
  r.Get("map/occupied_threshold", p.map.occupied_threshold);
  r.Get("map/free_threshold", p.map.free_threshold);

  r.GetDegrees("grid/angular_resolution_deg", p.grid.angular_resolution_rad);
  r.Get("grid/selective_update", p.grid.selective_update);
  r.Get("grid/threshold_fraction", p.grid.threshold_fraction);
  r.Get("grid/floor_fraction", p.grid.floor_fraction);
  r.Get("grid/distance_filter", p.grid.distance_filter);
  r.Get("grid/distance_filter_probability", p.grid.distance_filter_probability);
  r.Get("grid/distance_filter_sigmas", p.grid.distance_filter_sigmas);
  r.Get("grid/distance_filter_max_parts", p.grid.distance_filter_max_parts);
  r.Get("grid/distance_filter_max_fraction", p.grid.distance_filter_max_fraction);
  r.Get("grid/distance_filter_confirm_ratio", p.grid.distance_filter_confirm_ratio);
  auto& lost = p.grid.lost;
  r.Get("lost/enabled", lost.enabled);
  r.Get("lost/surprise", lost.surprise);
  r.Get("lost/fast_rate", lost.fast_rate);
  r.Get("lost/slow_rate", lost.slow_rate);
  r.Get("lost/lost_ratio", lost.lost_ratio);
  r.Get("lost/scan_lost_ratio", lost.scan_lost_ratio);
  r.Get("lost/judge_without_short_beams", lost.judge_without_short_beams);
  r.Get("lost/without_short_lost_ratio", lost.without_short_lost_ratio);
  r.Get("lost/short_beams_min_others", lost.short_beams_min_others);
  r.Get("lost/certainty_drop_ratio", lost.certainty_drop_ratio);
  r.Get("lost/hold_scans", lost.hold_scans);
  r.Get("lost/relocalization_mass", lost.relocalization_mass);
  auto& m = p.grid.motion;
  r.Get("motion/sigma_xy_per_m", m.sigma_xy_per_m);
  r.Get("motion/sigma_xy_per_rad", m.sigma_xy_per_rad);
  r.Get("motion/sigma_theta_per_m", m.sigma_theta_per_m);
  r.Get("motion/sigma_theta_per_rad", m.sigma_theta_per_rad);

  auto& s = p.sensor;
  r.Get("sensor/beams", p.beams);
  r.Get("sensor/ring_geometry", p.ring_geometry);
  r.Get("sensor/sensor_offset_m", s.sensor_offset_m);
  // The Polaroid sonar's 6.5 m (capped by the ring's own max_range): at 5 m the corner echoes
  // and far walls that told room A from room B after a kidnap were cut off.
  s.max_range_m = 6.5;
  r.Get("sensor/max_range_m", s.max_range_m);
  // Sonar physics (node defaults: the ring's cone, 0.35 rad); see sensor_model.h.
  s.beam_width_rad = -1.0;
  s.critical_angle_rad = 0.35;
  r.Get("sensor/beam_width_rad", s.beam_width_rad);
  r.Get("sensor/critical_angle_rad", s.critical_angle_rad);
  r.Get("sensor/range_bin_m", s.range_bin_m);
  r.Get("sensor/sigma_hit_m", s.sigma_hit_m);
  r.Get("sensor/lambda_short_per_m", s.lambda_short_per_m);
  r.Get("sensor/z_hit", s.z_hit);
  r.Get("sensor/z_short", s.z_short);
  r.Get("sensor/z_max", s.z_max);
  r.Get("sensor/z_rand", s.z_rand);

  r.Get("certainty/mode_radius_m", p.certainty.mode_radius_m);
  r.GetDegrees("certainty/mode_radius_deg", p.certainty.mode_radius_rad);
  r.Get("certainty/threshold", p.certainty.threshold);
  r.Get("modes/uniform_factor", p.modes.uniform_factor);
  r.Get("modes/max_fraction", p.modes.max_fraction);
  r.Get("modes/max_modes", p.modes.max_modes);

  auto& a = p.active;
  r.Get("active/window_m", a.window_m);
  r.Get("active/target_spacing_m", a.target_spacing_m);
  r.Get("active/alpha", a.alpha);
  r.Get("active/travel_cost_per_m", a.travel_cost_per_m);
  r.Get("active/occupied_cost", a.occupied_cost);
  r.Get("active/max_target_occupancy", a.max_target_occupancy);
  r.Get("active/max_modes", a.max_modes);

  auto& run = p.run;
  r.Get("active_run/random_motion_m", run.random_motion_m);
  r.Get("active_run/rewander_m", run.rewander_m);
  r.Get("active_run/min_target_distance_m", run.min_target_distance_m);
  r.Get("active_run/max_navigation_failures", run.max_navigation_failures);
  r.Get("active_run/estimate_jump_m", run.estimate_jump_m);
  r.GetDegrees("active_run/estimate_jump_deg", run.estimate_jump_rad);
  r.Get("active_run/target_timeout_s", run.target_timeout_s);
  r.Get("active_run/confirm_s", run.confirm_s);
  r.Get("active_run/position_tolerance_m", p.position_tolerance_m);
  r.Get("active_run/target_clearance_m", p.target_clearance_m);
  r.Get("active_run/target_search_m", p.target_search_m);
  r.Get("active_run/navigate_action", p.navigate_action);
  r.Get("active_run/cmd_vel_topic", p.cmd_vel_topic);
  r.Get("active_run/seed", p.seed);

  r.Get("estimate/switch_ratio", p.sticky.switch_ratio);
  r.Get("estimate/match_radius_m", p.sticky.match_radius_m);
  r.GetDegrees("estimate/match_deg", p.sticky.match_rad);

  auto& w = p.wander;
  r.Get("wander/max_speed_mps", w.max_speed_mps);
  r.Get("wander/max_turn_rps", w.max_turn_rps);
  r.Get("wander/heading_gain", w.heading_gain);
  r.Get("wander/stop_distance_m", w.stop_distance_m);
  r.Get("wander/slow_distance_m", w.slow_distance_m);
  r.Get("wander/side_distance_m", w.side_distance_m);
  r.Get("wander/free_range_m", w.free_range_m);
  r.GetDegrees("wander/front_half_angle_deg", w.front_half_angle_rad);
  r.Get("wander/stall_steps", w.stall_steps);

  if (p.sonar_enabled && p.ring_topic.empty()) v.push_back("~ring_topic must not be empty");
  if (!(p.sonar_off_max_s > 0.0 && p.sonar_off_max_s <= 600.0))
    v.push_back("~sonar_off_max_s must be in (0, 600] s");
  if (!p.sonar_enabled && !l.enabled)
    v.push_back("~sonar_enabled and ~laser/enabled are both false: nothing to localize on");
  if (l.enabled && l.topic.empty()) v.push_back("~laser/topic must not be empty");
  if (l.enabled && l.base_frame.empty()) v.push_back("~laser/base_frame must not be empty");
  if (l.max_beams < 2 || l.max_beams > 2000) v.push_back("~laser/max_beams must be in [2, 2000]");
  if (p.use_map_topic && p.map_topic.empty()) v.push_back("~map_topic must not be empty");
  if (f.enabled && f.topic.empty()) v.push_back("~profile/topic must not be empty");
  if (f.enabled && f.base_frame.empty()) v.push_back("~profile/base_frame must not be empty");
  r.Require(std::isfinite(f.min_height_m) && std::isfinite(f.max_height_m) &&
                f.min_height_m < f.max_height_m && f.max_height_m <= 10.0,
            "profile/min_height_m", "below profile/max_height_m (<= 10 m)", f.min_height_m);
  {
    SensorModelParameters fm = f.model;
    fm.beam_angles_rad = {0.0};
    for (const auto& e : ValidateParameters(fm)) v.push_back("~profile/" + e);
  }
  for (std::string e : ValidateParameters(g)) {
    if (e.rfind("update_min_a_rad", 0) == 0)
      e = "update_min_a_deg" + e.substr(16) + " (given in degrees)";
    v.push_back("~gate/" + e);
  }
  {
    // The laser model's parameters, checked with a placeholder beam (the scan's come later).
    SensorModelParameters lm = l.model;
    lm.beam_angles_rad = {0.0};
    for (const auto& e : ValidateParameters(lm)) v.push_back("~laser/" + e);
  }
  for (const auto& e : ValidateParameters(p.refine)) {
    std::string name = e.substr(0, e.find(' '));
    const std::string rest = e.substr(name.size());
    if (name == "sigma_scale") name = "refine_sigma_scale";
    if (name == "max_offset_cells") name = "refine_max_offset_cells";
    v.push_back("~estimate/" + name + rest);
  }
  if (p.map_frame.empty() || p.odom_frame.empty() || p.map_frame == p.odom_frame)
    v.push_back("~map_frame and ~odom_frame must be two non-empty frame names");
  if (!(p.transform_tolerance_s >= 0.0 && p.transform_tolerance_s <= 10.0))
    v.push_back("~transform_tolerance_s must be in [0, 10] s");
  if (!(p.odometry_max_lag_s > 0.0 && p.odometry_max_lag_s <= 10.0))
    v.push_back("~odometry_max_lag_s must be in (0, 10] s");
  if (!(p.initial_sigma_xy_m > 0.0)) v.push_back("~initial_sigma_xy_m must be > 0 m");
  if (!(p.last_sigma_xy_m >= 0.0 && p.last_sigma_xy_m < 1e3))
    v.push_back("~last_sigma_xy_m must be in [0, 1000) m");
  if (!(p.last_sigma_theta_rad >= 0.0 && p.last_sigma_theta_rad < 1e3))
    v.push_back("~last_sigma_theta_deg must be >= 0 and finite");
  if (!(p.initial_sigma_theta_rad > 0.0)) v.push_back("~initial_sigma_theta_deg must be > 0");
  if (!(p.belief_rate_hz > 0.0 && p.belief_rate_hz <= 100.0))
    v.push_back("~belief_rate_hz must be in (0, 100] Hz");
  if (p.beams < 1 || p.beams > 1000) v.push_back("~sensor/beams must be in [1, 1000]");
  s.beam_angles_rad = SonarRingAngles(std::clamp(p.beams, 1, 1000));

  AddCore(v, ValidateParameters(p.map), "map");
  AddCore(v, ValidateParameters(p.grid), "grid");
  // -1: the ring's field of view, known when the first ring arrives.
  const double beam_width = s.beam_width_rad;
  if (beam_width == -1.0) s.beam_width_rad = 0.0;
  AddCore(v, ValidateParameters(s), "sensor");
  s.beam_width_rad = beam_width;
  AddCore(v, ValidateParameters(p.certainty), "certainty");
  if (!(p.modes.uniform_factor > 0.0)) v.push_back("~modes/uniform_factor must be > 0");
  if (!(p.modes.max_fraction >= 0.0 && p.modes.max_fraction < 1.0))
    v.push_back("~modes/max_fraction must be in [0, 1)");
  if (p.modes.max_modes < 1) v.push_back("~modes/max_modes must be >= 1");
  AddCore(v, ValidateParameters(a), "active");
  AddCore(v, ValidateParameters(run), "active_run");
  AddCore(v, ValidateParameters(w), "wander");
  if (!(p.position_tolerance_m > 0.0))
    v.push_back("~active_run/position_tolerance_m must be > 0 m");
  if (!(p.target_clearance_m >= 0.0 && p.target_clearance_m < 2.0))
    v.push_back("~active_run/target_clearance_m must be in [0, 2) m");
  if (!(p.target_search_m >= 0.0 && p.target_search_m <= 5.0))
    v.push_back("~active_run/target_search_m must be in [0, 5] m");
  if (!(p.sticky.switch_ratio >= 1.0)) v.push_back("~estimate/switch_ratio must be >= 1");
  if (!(p.sticky.match_radius_m > 0.0)) v.push_back("~estimate/match_radius_m must be > 0 m");
  if (!(p.sticky.match_rad > 0.0)) v.push_back("~estimate/match_deg must be > 0");
  if (p.navigate_action.empty()) v.push_back("~active_run/navigate_action must not be empty");
  if (p.cmd_vel_topic.empty()) v.push_back("~active_run/cmd_vel_topic must not be empty");
  if (p.seed < 0) v.push_back("~active_run/seed must be >= 0");
  for (const std::string& e : v) r.Fail(e);
}

std::vector<std::string> ReadParameters(const ros::NodeHandle& pnh, NodeParameters& p) {
  // spott_ros::ParameterReader: typed getters, every violation and every unknown key by name.
  spott_ros::ParameterReader r = spott_ros::ParameterReader::FromNode(pnh);
  ReadParameters(r, p);
  return r.Finish();  // the violations, then every key no getter asked for
}

}  // namespace markov_localization
