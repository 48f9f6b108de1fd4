#include "spott_tr_plus/ros/parameters.h"

#include <utility>

namespace spott_tr_plus {

void ReadParameters(spott_ros::ParameterReader& r, NodeParameters& p) {
  r.Get("program_file", p.program_file);
  r.Get("main", p.main);
  r.Get("max_call_depth", p.max_call_depth);
  TaskInterpretationParameters& t = p.task;
  const std::pair<const char*, double*> distances[] = {
      {"task/at_distance_m", &t.at_distance_m},
      {"task/against_distance_m", &t.against_distance_m},
      {"task/near_distance_m", &t.near_distance_m},
      {"task/far_distance_m", &t.far_distance_m},
      {"task/beyond_distance_m", &t.beyond_distance_m},
      {"task/goal_tolerance_m", &t.goal_tolerance_m},
      {"task/default_door_width_m", &t.default_door_width_m},
      {"task/default_chair_radius_m", &t.default_chair_radius_m},
      {"task/default_desk_length_m", &t.default_desk_length_m},
      {"task/default_desk_width_m", &t.default_desk_width_m}};
  for (const auto& [name, field] : distances) r.Get(name, *field, "m");
  r.Get("task/slow_fraction", t.slow_fraction);
  r.Get("task/normal_fraction", t.normal_fraction);
  r.Get("task/quick_fraction", t.quick_fraction);
  if (p.program_file.empty()) r.Fail("program_file is required (a .tr file)");
  r.Require(p.max_call_depth >= 1, "max_call_depth", ">= 1", p.max_call_depth);
  for (const std::string& v : ValidateParameters(t)) r.Fail("task/" + v);
}

}  // namespace spott_tr_plus

namespace spott_tr_plus::controller {

void ReadParameters(spott_ros::ParameterReader& r, NodeParameters& p) {
  r.Get("program_file", p.program_file);
  r.Get("main", p.main);
  r.Get("frame_id", p.frame_id);
  r.Get("odom_frame", p.odom_frame);
  r.Get("base_frame", p.base_frame);
  r.Get("robot_description", p.robot_description);
  r.Get("navigate_action", p.navigate_action);
  r.Get("active_localize_action", p.active_localize_action);
  r.Get("arbiter", p.arbiter);
  r.Get("tick_rate_hz", p.tick_rate_hz, "Hz");
  r.Get("assume_localized", p.assume_localized);
  r.Get("ptu/pan_joints", p.pan_joints);
  r.Get("ptu/tilt_joints", p.tilt_joints);
  r.Get("ptu/sweep_rad", p.ptu.sweep_rad, "rad");
  r.Get("ptu/sweep_period_s", p.ptu.sweep_period_s, "s");
  r.Get("ptu/hallway_pan_rad", p.ptu.hallway_pan_rad, "rad");
  r.Get("ptu/door_watch_m", p.ptu.door_watch_m, "m");
  r.Get("ptu/max_pan_rad", p.ptu.max_pan_rad, "rad");
  r.Get("ptu/head_height_m", p.ptu.head_height_m, "m");
  r.Get("ptu/max_tilt_rad", p.ptu.max_tilt_rad, "rad");
  r.Get("ptu/min_height_m", p.ptu_min_height_m, "m");
  r.Get("ptu/max_height_m", p.ptu_max_height_m, "m");
  r.Get("marker_height_m", p.marker_height_m, "m");
  ControllerParameters& c = p.controller;
  int seed = static_cast<int>(c.seed);
  r.Get("seed", seed);
  c.seed = static_cast<unsigned>(seed);
  r.Get("max_call_depth", c.max_call_depth);
  r.Get("subroutines_off", c.subroutines_off);
  r.Get("max_localization_error_m", c.max_localization_error_m, "m");
  r.Get("drive/max_linear_mps", c.max_linear_mps, "m/s");
  r.Get("drive/max_angular_rps", c.max_angular_rps, "rad/s");
  auto& m = c.mapping;
  r.Get("mapping/cell_m", m.cell_m, "m");
  r.Get("mapping/sonar_max_range_m", m.sonar_max_range_m, "m");
  r.Get("mapping/sonar_min_margin_m", m.sonar_min_margin_m, "m");
  r.Get("mapping/range_finder_max_range_m", m.range_finder_max_range_m, "m");
  r.Get("mapping/sonar_hit_score", m.sonar_hit_score);
  r.Get("mapping/range_finder_hit_score", m.range_finder_hit_score);
  r.Get("mapping/miss_score", m.miss_score);
  r.Get("mapping/confirm_score", m.confirm_score);
  r.Get("mapping/max_score", m.max_score);
  r.Get("mapping/known_tolerance_m", m.known_tolerance_m, "m");
  r.Get("mapping/near_miss_m", m.near_miss_m, "m");
  r.Get("mapping/near_miss_points", m.near_miss_points);
  r.Get("mapping/door_zone_m", m.door_zone_m, "m");
  r.Get("mapping/segment_residual_m", m.segment_residual_m, "m");
  r.Get("mapping/cluster_gap_m", m.cluster_gap_m, "m");
  r.Get("mapping/echo_cluster_gap_m", m.echo_cluster_gap_m, "m");
  r.Get("mapping/mapless_extent_m", m.mapless_extent_m, "m");
  r.Get("mapping/echo_tolerance_m", m.echo_fit.tolerance_base_m, "m");
  r.Get("mapping/echo_tolerance_per_m", m.echo_fit.tolerance_per_m);
  r.Get("mapping/sonar_max_incidence_rad", m.echo_fit.max_incidence_rad, "rad");
  r.Get("mapping/echo_max_direction_error_rad", m.echo_fit.max_direction_error_rad, "rad");
  r.Get("mapping/echoes_per_cell", m.echoes_per_cell);
  auto& ss = c.sonar_scan;
  r.Get("sonar_scan/period_s", ss.period_s, "s");
  r.Get("sonar_scan/steps", ss.steps);
  r.Get("sonar_scan/step_rad", ss.step_rad, "rad");
  r.Get("sonar_scan/settle_rad", ss.settle_rad, "rad");
  r.Get("sonar_scan/step_timeout_s", ss.step_timeout_s, "s");
  auto& d = c.doors;
  r.Get("doors/range_m", d.range_m, "m");
  r.Get("doors/end_margin_m", d.end_margin_m, "m");
  r.Get("doors/pose_error_m", d.pose_error_m, "m");
  r.Get("doors/match_m", d.match_m, "m");
  r.Get("doors/beyond_m", d.beyond_m, "m");
  r.Get("doors/normal_angle_rad", d.normal_angle_rad, "rad");
  r.Get("doors/profile_normal_angle_rad", d.profile_normal_angle_rad, "rad");
  r.Get("doors/votes", d.votes);
  r.Get("doors/max_votes", d.max_votes);
  r.Get("doors/sonar_with_profiles", d.sonar_with_profiles);
  auto& g = c.recognition;
  r.Get("recognition/cell_m", g.cell_m, "m");
  r.Get("recognition/cluster_gap_m", g.cluster_gap_m, "m");
  r.Get("recognition/known_tolerance_m", g.known_tolerance_m, "m");
  r.Get("recognition/floor_m", g.floor_m, "m");
  r.Get("recognition/max_range_m", g.max_range_m, "m");
  r.Get("recognition/top_jump_m", g.top_jump_m, "m");
  r.Get("recognition/top_flat_m", g.top_flat_m, "m");
  r.Get("recognition/top_join_m", g.top_join_m, "m");
  r.Get("recognition/min_points", g.min_points);
  r.Get("recognition/min_vertical_points", g.min_vertical_points);
  r.Get("recognition/min_cell_hits", g.min_cell_hits);
  r.Get("recognition/vertical_block_m", g.vertical_block_m, "m");
  r.Get("recognition/min_views", g.min_views);
  r.Get("recognition/growth_m", g.growth_m, "m");
  r.Get("recognition/stable_views", g.stable_views);
  r.Get("recognition/quiet_profiles", g.quiet_profiles);
  r.Get("recognition/circle_residual_m", g.circle_residual_m, "m");
  r.Get("recognition/min_arc_rad", g.min_arc_rad, "rad");
  r.Get("recognition/max_extent_m", g.max_extent_m, "m");
  r.Get("recognition/wall_depth_m", g.wall_depth_m, "m");
  r.Get("recognition/look_views", g.look_views);
  r.Get("recognition/look_below_top_m", g.look_below_top_m, "m");
  auto& x = c.reflex;
  r.Get("reflex/speed_mps", x.speed_mps, "m/s");
  r.Get("reflex/turn_rps", x.turn_rps, "rad/s");
  r.Get("reflex/align_rad", x.align_rad, "rad");
  r.Get("reflex/timeout_s", x.timeout_s, "s");
  r.Get("reflex/infrared_close_m", x.infrared_close_m, "m");
  r.Get("reflex/known_tolerance_m", x.known_tolerance_m, "m");
  r.Get("reflex/repeat_s", x.repeat_s, "s");
  auto& t = c.teleop;
  r.Get("teleop/stop_distance_m", t.stop_distance_m, "m");
  r.Get("teleop/lookahead_m", t.lookahead_m, "m");
  r.Get("teleop/clearance_m", t.clearance_m, "m");
  r.Get("teleop/max_deviation_rad", t.max_deviation_rad, "rad");
  r.Get("teleop/heading_gain_per_s", t.heading_gain_per_s, "1/s");
  r.Get("teleop/blocked_timeout_s", t.blocked_timeout_s, "s");
  auto& l = c.localization;
  r.Get("localization/period_s", l.period_s, "s");
  r.Get("localization/distance_m", l.distance_m, "m");
  r.Get("localization/place_radius_m", l.place_radius_m, "m");
  r.Get("localization/max_age_s", l.max_age_s, "s");
  r.Get("localization/jump_m", l.jump_m, "m");
  r.Get("localization/jump_rad", l.jump_rad, "rad");
  r.Get("localization/retract_s", l.retract_s, "s");
  r.Get("localization/keep_radius_m", l.keep_radius_m, "m");
  r.Get("localization/settle_s", l.settle_s, "s");
  auto& k = c.tasks;
  r.Get("tasks/goal_tolerance_m", k.goal_tolerance_m, "m");
  r.Get("tasks/navigate_retries", k.navigate_retries);
  r.Get("tasks/retry_delay_s", k.retry_delay_s, "s");
  r.Get("tasks/clear_radius_m", k.clear_radius_m, "m");
  r.Get("tasks/arrival_margin_m", k.arrival_margin_m, "m");
  r.Get("tasks/localized_wait_s", k.localized_wait_s, "s");
  r.Get("tasks/active_localizations", k.active_localizations);
  r.Get("tasks/active_localize_timeout_s", k.active_localize_timeout_s, "s");
  r.Get("tasks/stop_speed_mps", k.stop_speed_mps, "m/s");
  r.Get("tasks/stop_timeout_s", k.stop_timeout_s, "s");
  r.Get("tasks/pose_timeout_s", k.pose_timeout_s, "s");
  r.Get("tasks/search_turn_rps", k.search_turn_rps, "rad/s");
  r.Get("tasks/obstacle_ahead_m", k.obstacle_ahead_m, "m");
  r.Get("tasks/feedback_period_s", k.feedback_period_s, "s");
  auto& i = c.interpretation;
  r.Get("task/at_distance_m", i.at_distance_m, "m");
  r.Get("task/against_distance_m", i.against_distance_m, "m");
  r.Get("task/near_distance_m", i.near_distance_m, "m");
  r.Get("task/far_distance_m", i.far_distance_m, "m");
  r.Get("task/beyond_distance_m", i.beyond_distance_m, "m");
  r.Get("task/goal_tolerance_m", i.goal_tolerance_m, "m");
  r.Get("task/default_door_width_m", i.default_door_width_m, "m");
  r.Get("task/default_chair_radius_m", i.default_chair_radius_m, "m");
  r.Get("task/default_desk_length_m", i.default_desk_length_m, "m");
  r.Get("task/default_desk_width_m", i.default_desk_width_m, "m");
  r.Get("task/slow_fraction", i.slow_fraction);
  r.Get("task/normal_fraction", i.normal_fraction);
  r.Get("task/quick_fraction", i.quick_fraction);
  r.Get("task/free_space_resolution_m", i.free_space_resolution_m, "m");
  if (p.program_file.empty()) r.Fail("program_file is required (a .tr file)");
  if (p.frame_id.empty() || p.base_frame.empty()) r.Fail("frame_id and base_frame must be set");
  // The tick timer's period 1 / tick_rate_hz must make a ros::Duration (at most 2^31 s).
  r.Require(p.tick_rate_hz >= 0.01 && p.tick_rate_hz <= 200, "tick_rate_hz", "in [0.01, 200]",
            p.tick_rate_hz);
  for (const std::string& v : ValidateParameters(p.ptu)) r.Fail("ptu/" + v);
  if (p.pan_joints.size() != p.tilt_joints.size())
    r.Fail("ptu/pan_joints and ptu/tilt_joints must have as many names");
}

}  // namespace spott_tr_plus::controller
