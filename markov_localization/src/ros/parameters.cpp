#include "markov_localization/ros/parameters.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <ros/param.h>

namespace markov_localization {
namespace {

// Reads parameters by name, remembers every name it knows and says which have the wrong type.
class Reader {
 public:
  Reader(const ros::NodeHandle& pnh, std::vector<std::string>& errors)
      : pnh_(pnh), errors_(errors) {}

  template <typename T>
  void Get(const std::string& name, T& value, const char* type) {
    known_.insert(name);
    if (!pnh_.hasParam(name)) return;
    T read{};
    if (pnh_.getParam(name, read)) {
      value = read;
    } else {
      errors_.push_back("~" + name + " must be " + type);
    }
  }
  void Double(const std::string& name, double& v) { Get(name, v, "a number"); }
  void Int(const std::string& name, int& v) { Get(name, v, "an integer"); }
  void Bool(const std::string& name, bool& v) { Get(name, v, "true or false"); }
  void String(const std::string& name, std::string& v) { Get(name, v, "a string"); }
  void Degrees(const std::string& name, double& radians) {
    double deg = radians * 180.0 / M_PI;
    Double(name, deg);
    radians = deg * M_PI / 180.0;
  }

  /// Every parameter under the private namespace that no Get asked for.
  void CheckUnknown() {
    std::vector<std::string> names;
    if (!ros::param::getParamNames(names)) return;
    const std::string prefix = pnh_.getNamespace() + "/";
    for (const auto& full : names) {
      if (full.compare(0, prefix.size(), prefix) != 0) continue;
      const std::string name = full.substr(prefix.size());
      if (!known_.count(name)) errors_.push_back("~" + name + " is not a parameter of this node");
    }
  }

 private:
  const ros::NodeHandle& pnh_;
  std::vector<std::string>& errors_;
  std::set<std::string> known_;
};

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

std::vector<std::string> ReadParameters(const ros::NodeHandle& pnh, NodeParameters& p) {
  std::vector<std::string> v;
  Reader r(pnh, v);
  r.String("world_file", p.world_file);
  r.String("ring_topic", p.ring_topic);
  r.String("map_frame", p.map_frame);
  r.String("odom_frame", p.odom_frame);
  r.Double("transform_tolerance_s", p.transform_tolerance_s);
  r.Bool("start_uniform", p.start_uniform);
  r.Bool("initial_pose_from_world", p.initial_pose_from_world);
  r.Double("initial_sigma_xy_m", p.initial_sigma_xy_m);
  r.Degrees("initial_sigma_theta_deg", p.initial_sigma_theta_rad);
  r.Double("belief_rate_hz", p.belief_rate_hz);

  r.Double("map/resolution_m", p.map.resolution_m);
  r.Double("map/state_clearance_m", p.map.state_clearance_m);
  r.Double("map/door_thickness_m", p.map.door_thickness_m);
  r.Int("map/ray_cast_subdivision", p.map.ray_cast_subdivision);

  r.Degrees("grid/angular_resolution_deg", p.grid.angular_resolution_rad);
  r.Bool("grid/selective_update", p.grid.selective_update);
  r.Double("grid/threshold_fraction", p.grid.threshold_fraction);
  r.Double("grid/floor_fraction", p.grid.floor_fraction);
  auto& lost = p.grid.lost;
  r.Bool("lost/enabled", lost.enabled);
  r.Double("lost/fast_rate", lost.fast_rate);
  r.Double("lost/slow_rate", lost.slow_rate);
  r.Double("lost/lost_ratio", lost.lost_ratio);
  r.Double("lost/scan_lost_ratio", lost.scan_lost_ratio);
  r.Double("lost/certainty_drop_ratio", lost.certainty_drop_ratio);
  r.Int("lost/hold_scans", lost.hold_scans);
  r.Double("lost/relocalization_mass", lost.relocalization_mass);
  auto& m = p.grid.motion;
  r.Double("motion/sigma_xy_per_m", m.sigma_xy_per_m);
  r.Double("motion/sigma_xy_per_rad", m.sigma_xy_per_rad);
  r.Double("motion/sigma_theta_per_m", m.sigma_theta_per_m);
  r.Double("motion/sigma_theta_per_rad", m.sigma_theta_per_rad);

  auto& s = p.sensor;
  r.Int("sensor/beams", p.beams);
  r.Bool("sensor/ring_geometry", p.ring_geometry);
  r.Double("sensor/sensor_offset_m", s.sensor_offset_m);
  // The Polaroid sonar's 6.5 m (capped by the ring's own max_range): at 5 m the corner echoes
  // and far walls that told room A from room B after a kidnap were cut off.
  s.max_range_m = 6.5;
  r.Double("sensor/max_range_m", s.max_range_m);
  // Sonar physics (node defaults: the ring's cone, 0.35 rad); see sensor_model.h.
  s.beam_width_rad = -1.0;
  s.critical_angle_rad = 0.35;
  r.Double("sensor/beam_width_rad", s.beam_width_rad);
  r.Double("sensor/critical_angle_rad", s.critical_angle_rad);
  r.Double("sensor/range_bin_m", s.range_bin_m);
  r.Double("sensor/sigma_hit_m", s.sigma_hit_m);
  r.Double("sensor/lambda_short_per_m", s.lambda_short_per_m);
  r.Double("sensor/z_hit", s.z_hit);
  r.Double("sensor/z_short", s.z_short);
  r.Double("sensor/z_max", s.z_max);
  r.Double("sensor/z_rand", s.z_rand);

  r.Double("certainty/mode_radius_m", p.certainty.mode_radius_m);
  r.Degrees("certainty/mode_radius_deg", p.certainty.mode_radius_rad);
  r.Double("certainty/threshold", p.certainty.threshold);
  r.Double("modes/uniform_factor", p.modes.uniform_factor);
  r.Double("modes/max_fraction", p.modes.max_fraction);
  r.Int("modes/max_modes", p.modes.max_modes);

  auto& a = p.active;
  r.Double("active/window_m", a.window_m);
  r.Double("active/target_spacing_m", a.target_spacing_m);
  r.Double("active/alpha", a.alpha);
  r.Double("active/travel_cost_per_m", a.travel_cost_per_m);
  r.Double("active/occupied_cost", a.occupied_cost);
  r.Double("active/max_target_occupancy", a.max_target_occupancy);
  r.Int("active/max_modes", a.max_modes);

  auto& run = p.run;
  r.Double("active_run/random_motion_m", run.random_motion_m);
  r.Double("active_run/rewander_m", run.rewander_m);
  r.Double("active_run/min_target_distance_m", run.min_target_distance_m);
  r.Int("active_run/max_navigation_failures", run.max_navigation_failures);
  r.Double("active_run/estimate_jump_m", run.estimate_jump_m);
  r.Degrees("active_run/estimate_jump_deg", run.estimate_jump_rad);
  r.Double("active_run/target_timeout_s", run.target_timeout_s);
  r.Double("active_run/confirm_s", run.confirm_s);
  r.Double("active_run/position_tolerance_m", p.position_tolerance_m);
  r.Double("active_run/target_clearance_m", p.target_clearance_m);
  r.Double("active_run/target_search_m", p.target_search_m);
  r.String("active_run/navigate_action", p.navigate_action);
  r.String("active_run/global_goal_topic", p.global_goal_topic);
  r.String("active_run/cmd_vel_topic", p.cmd_vel_topic);
  r.Int("active_run/seed", p.seed);

  r.Double("estimate/switch_ratio", p.sticky.switch_ratio);
  r.Double("estimate/match_radius_m", p.sticky.match_radius_m);
  r.Degrees("estimate/match_deg", p.sticky.match_rad);

  auto& w = p.wander;
  r.Double("wander/max_speed_mps", w.max_speed_mps);
  r.Double("wander/max_turn_rps", w.max_turn_rps);
  r.Double("wander/heading_gain", w.heading_gain);
  r.Double("wander/stop_distance_m", w.stop_distance_m);
  r.Double("wander/slow_distance_m", w.slow_distance_m);
  r.Double("wander/side_distance_m", w.side_distance_m);
  r.Double("wander/free_range_m", w.free_range_m);
  r.Degrees("wander/front_half_angle_deg", w.front_half_angle_rad);
  r.Int("wander/stall_steps", w.stall_steps);
  r.CheckUnknown();

  if (p.world_file.empty()) v.push_back("~world_file must name a world file");
  if (p.ring_topic.empty()) v.push_back("~ring_topic must not be empty");
  if (p.map_frame.empty() || p.odom_frame.empty() || p.map_frame == p.odom_frame)
    v.push_back("~map_frame and ~odom_frame must be two non-empty frame names");
  if (!(p.transform_tolerance_s >= 0.0 && p.transform_tolerance_s <= 10.0))
    v.push_back("~transform_tolerance_s must be in [0, 10] s");
  if (!(p.initial_sigma_xy_m > 0.0)) v.push_back("~initial_sigma_xy_m must be > 0 m");
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
  return v;
}

}  // namespace markov_localization
