// markov_localization's parameters from the fuzzer's bytes (tools/fuzz/parameter_fuzz.h):
// ReadParameters and the reader's Finish, as the node does. Whatever the node accepts must lie in
// the ranges its config file and the cores' headers document, make the ros::Durations of its
// timers, and give rasters a building fits in.
#include <cmath>

#include "markov_localization/ros/parameters.h"
#include "parameter_fuzz.h"

using namespace markov_localization;
using spott_fuzz::Expect;
using spott_fuzz::ExpectIn;

namespace {

void ExpectSensorModel(const std::string& s, const SensorModelParameters& m, bool sonar) {
  ExpectIn(s + "max_range_m", m.max_range_m, "(0, inf)");
  if (!(sonar && m.beam_width_rad == -1.0)) {  // -1: the ring's own cone, known later
    ExpectIn(s + "beam_width_rad", m.beam_width_rad, "[0, pi)");
  }
  ExpectIn(s + "critical_angle_rad", m.critical_angle_rad, "(0, pi/2]");
  ExpectIn(s + "range_bin_m", m.range_bin_m, "(0, inf)");
  Expect(m.max_range_m / m.range_bin_m <= 254.0, s + "range_bin_m gives more than 254 bins");
  ExpectIn(s + "sigma_hit_m", m.sigma_hit_m, "(0, inf)");
  ExpectIn(s + "lambda_short_per_m", m.lambda_short_per_m, "(0, inf)");
  for (double z : {m.z_hit, m.z_short, m.z_max, m.z_rand}) ExpectIn(s + "z_*", z, "[0, 1]");
  Expect(std::fabs(m.z_hit + m.z_short + m.z_max + m.z_rand - 1.0) < 1e-6,
         s + "z_hit + z_short + z_max + z_rand != 1 accepted");
  ExpectIn(s + "likelihood_exponent", m.likelihood_exponent, "(0, 1]");
  ExpectIn(s + "sensor_offset_m", m.sensor_offset_m, "[0, inf)");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const auto vocabulary = spott_fuzz::LoadVocabulary(
      CONFIG_FILE, {{"world_file", "spott_worlds/worlds/cim_office.yaml"}},
      {"map_file", "initial_pose", "last_map_to_odom"},
      {"1 2 0.5", "0 0 0", "1 nan 0", "/tmp/map.yaml"});
  FuzzedDataProvider in(data, size);
  spott_ros::ParameterReader r(spott_fuzz::BuildParameters(in, vocabulary));
  NodeParameters p;
  ReadParameters(r, p);
  if (!r.Finish().empty()) return 0;  // the node stops, naming every problem

  Expect(p.sonar_enabled || p.laser.enabled, "neither sonar nor laser accepted");
  ExpectIn("sonar_off_max_s", p.sonar_off_max_s, "(0, 600]");
  ExpectIn("transform_tolerance_s", p.transform_tolerance_s, "[0, 10]");
  spott_fuzz::ExpectRosDuration("transform_tolerance_s", p.transform_tolerance_s);
  ExpectIn("save_pose_period_s", p.save_pose_period_s, "[0, 60]");
  spott_fuzz::ExpectRosDuration("the save timer's save_pose_period_s", p.save_pose_period_s);
  ExpectIn("initial_sigma_xy_m", p.initial_sigma_xy_m, "(0, inf)");
  ExpectIn("initial_sigma_theta_deg (rad)", p.initial_sigma_theta_rad, "(0, inf)");
  ExpectIn("belief_rate_hz", p.belief_rate_hz, "(0, 100]");
  for (const auto* pose : {&p.initial_pose, &p.last_map_to_odom}) {
    if (*pose) {
      spott_fuzz::ExpectFinite("a pose's x", (*pose)->x);
      spott_fuzz::ExpectFinite("a pose's y", (*pose)->y);
      spott_fuzz::ExpectFinite("a pose's yaw", (*pose)->yaw);
    }
  }
  Expect(!p.map_frame.empty() && !p.odom_frame.empty() && p.map_frame != p.odom_frame,
         "map_frame and odom_frame not two names");

  const auto& g = p.gate;
  ExpectIn("gate/update_min_d_m", g.update_min_d_m, "[0, inf)");
  ExpectIn("gate/update_min_a_deg (rad)", g.update_min_a_rad, "[0, inf)");
  ExpectIn("gate/standing_interval_s", g.standing_interval_s, "[0, inf)");
  if (p.laser.enabled) {
    Expect(p.laser.max_beams >= 2 && p.laser.max_beams <= 2000, "laser/max_beams");
    ExpectSensorModel("laser/", p.laser.model, false);
  }
  ExpectIn("estimate/refine_max_offset_cells", p.refine.max_offset_cells, "(0, inf)");
  ExpectIn("estimate/refine_sigma_scale", p.refine.sigma_scale, "(0, 1]");
  Expect(p.refine.sweeps >= 1, "refine sweeps < 1");

  const auto& m = p.map;
  ExpectIn("map/resolution_m", m.resolution_m, "[0.01, 2]");
  // MapModel counts a building's cells in an int (static_cast<int>(ceil(size / resolution))),
  // and holds them: a 100 m x 100 m building must fit in 1e9 cells.
  Expect(std::pow(100.0 / m.resolution_m, 2.0) <= 1e9,
         "a map/resolution_m so fine that a 100 m building needs more than 1e9 cells accepted");
  ExpectIn("map/state_clearance_m", m.state_clearance_m, "[0, 2]");
  ExpectIn("map/door_thickness_m", m.door_thickness_m, "(0, 1]");
  Expect(m.ray_cast_subdivision >= 1 && m.ray_cast_subdivision <= 8, "map/ray_cast_subdivision");
  Expect(m.occupied_threshold >= 1 && m.occupied_threshold <= 100, "map/occupied_threshold");
  Expect(m.free_threshold >= 0 && m.free_threshold <= m.occupied_threshold, "map/free_threshold");

  const auto& grid = p.grid;
  const double bins = 2.0 * M_PI / grid.angular_resolution_rad;
  Expect(std::fabs(bins - std::round(bins)) < 1e-6 && bins >= 4 - 1e-9 && bins <= 3600 + 1e-9,
         "grid/angular_resolution_deg: 360 / it not an integer in [4, 3600]");
  ExpectIn("grid/threshold_fraction", grid.threshold_fraction, "(0, 1)");
  ExpectIn("grid/floor_fraction", grid.floor_fraction, "[0, 1)");
  Expect(grid.floor_fraction < grid.threshold_fraction, "grid/floor_fraction >= threshold");
  ExpectIn("grid/distance_filter_max_fraction", grid.distance_filter_max_fraction, "[0, 1]");
  ExpectIn("grid/distance_filter_confirm_ratio", grid.distance_filter_confirm_ratio, "[0, 1)");
  ExpectIn("grid/distance_filter_probability", grid.distance_filter_probability, "(0.5, 1]");
  ExpectIn("grid/distance_filter_sigmas", grid.distance_filter_sigmas, "[0, inf)");
  Expect(grid.distance_filter_max_parts >= 1, "grid/distance_filter_max_parts < 1");
  const auto& mo = grid.motion;
  for (double s :
       {mo.sigma_xy_per_m, mo.sigma_xy_per_rad, mo.sigma_theta_per_m, mo.sigma_theta_per_rad}) {
    ExpectIn("motion/sigma_*", s, "[0, inf)");
  }
  const auto& lost = grid.lost;
  ExpectIn("lost/fast_rate", lost.fast_rate, "(0, 1]");
  ExpectIn("lost/slow_rate", lost.slow_rate, "(0, 1]");
  Expect(lost.slow_rate < lost.fast_rate, "lost/slow_rate >= fast_rate");
  ExpectIn("lost/lost_ratio", lost.lost_ratio, "(0, 1)");
  ExpectIn("lost/scan_lost_ratio", lost.scan_lost_ratio, "(0, 1)");
  Expect(lost.scan_lost_ratio <= lost.lost_ratio, "lost/scan_lost_ratio > lost_ratio");
  ExpectIn("lost/certainty_drop_ratio", lost.certainty_drop_ratio, "(0, 1)");
  Expect(lost.certainty_drop_ratio >= lost.lost_ratio, "lost/certainty_drop_ratio < lost_ratio");
  Expect(lost.hold_scans >= 1, "lost/hold_scans < 1");
  ExpectIn("lost/relocalization_mass", lost.relocalization_mass, "(0, 1)");
  Expect(lost.relocalization_mass > grid.threshold_fraction,
         "lost/relocalization_mass <= grid/threshold_fraction accepted");

  Expect(p.beams >= 1 && p.beams <= 1000, "sensor/beams");
  ExpectSensorModel("sensor/", p.sensor, true);

  ExpectIn("certainty/mode_radius_m", p.certainty.mode_radius_m, "(0, inf)");
  ExpectIn("certainty/mode_radius_deg (rad)", p.certainty.mode_radius_rad, "(0, inf)");
  ExpectIn("certainty/threshold", p.certainty.threshold, "(0, 1)");
  ExpectIn("modes/uniform_factor", p.modes.uniform_factor, "(0, inf)");
  ExpectIn("modes/max_fraction", p.modes.max_fraction, "[0, 1)");
  Expect(p.modes.max_modes >= 1, "modes/max_modes < 1");

  const auto& a = p.active;
  ExpectIn("active/window_m", a.window_m, "(0, inf)");
  ExpectIn("active/target_spacing_m", a.target_spacing_m, "(0, inf)");
  ExpectIn("active/alpha", a.alpha, "[0, inf)");
  ExpectIn("active/travel_cost_per_m", a.travel_cost_per_m, "[0, inf)");
  ExpectIn("active/occupied_cost", a.occupied_cost, "(0, inf)");
  spott_fuzz::ExpectFinite("active/max_target_occupancy", a.max_target_occupancy);
  Expect(a.max_modes >= 1, "active/max_modes < 1");
  const auto& run = p.run;
  ExpectIn("active_run/random_motion_m", run.random_motion_m, "[0, inf)");
  ExpectIn("active_run/rewander_m", run.rewander_m, "(0, inf)");
  ExpectIn("active_run/min_target_distance_m", run.min_target_distance_m, "[0, inf)");
  Expect(run.max_navigation_failures >= 1, "active_run/max_navigation_failures < 1");
  ExpectIn("active_run/estimate_jump_m", run.estimate_jump_m, "(0, inf)");
  ExpectIn("active_run/estimate_jump_deg (rad)", run.estimate_jump_rad, "(0, inf)");
  ExpectIn("active_run/target_timeout_s", run.target_timeout_s, "(0, inf)");
  ExpectIn("active_run/confirm_s", run.confirm_s, "[0, inf)");
  ExpectIn("active_run/position_tolerance_m", p.position_tolerance_m, "(0, inf)");
  ExpectIn("active_run/target_clearance_m", p.target_clearance_m, "[0, 2)");
  ExpectIn("active_run/target_search_m", p.target_search_m, "[0, 5]");
  Expect(p.seed >= 0, "active_run/seed < 0");
  Expect(!p.navigate_action.empty() && !p.cmd_vel_topic.empty(), "an empty action or topic");

  ExpectIn("estimate/switch_ratio", p.sticky.switch_ratio, "[1, inf)");
  ExpectIn("estimate/match_radius_m", p.sticky.match_radius_m, "(0, inf)");
  ExpectIn("estimate/match_deg (rad)", p.sticky.match_rad, "(0, inf)");
  const auto& w = p.wander;
  ExpectIn("wander/max_speed_mps", w.max_speed_mps, "(0, inf)");
  ExpectIn("wander/max_turn_rps", w.max_turn_rps, "(0, inf)");
  ExpectIn("wander/heading_gain", w.heading_gain, "(0, inf)");
  ExpectIn("wander/stop_distance_m", w.stop_distance_m, "(0, inf)");
  Expect(w.slow_distance_m > w.stop_distance_m, "wander/slow_distance_m <= stop_distance_m");
  spott_fuzz::ExpectFinite("wander/side_distance_m", w.side_distance_m);
  ExpectIn("wander/free_range_m", w.free_range_m, "(0, inf)");
  spott_fuzz::ExpectFinite("wander/front_half_angle_deg (rad)", w.front_half_angle_rad);
  Expect(w.stall_steps >= 1, "wander/stall_steps < 1");
  return 0;
}
