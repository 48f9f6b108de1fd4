// The parameters of spott_tr_plus's two nodes from the fuzzer's bytes
// (tools/fuzz/parameter_fuzz.h), the first byte choosing the node: tr_plus_node (ReadParameters
// and Finish, as spott_ros::ReadNodeParameters) or tr_plus_controller (ReadParameters, the
// robot's radius, the core's ValidateParameters and Finish, as its main()). Whatever a node
// accepts must lie in the ranges its config file and the core's headers document and make the
// controller's tick timer.
#include <stdexcept>

#include "parameter_fuzz.h"
#include "spott_tr_plus/ros/parameters.h"

using spott_fuzz::Expect;
using spott_fuzz::ExpectIn;

namespace {

void ExpectInterpretation(const std::string& section,
                          const spott_tr_plus::TaskInterpretationParameters& t) {
  ExpectIn(section + "at_distance_m", t.at_distance_m, "(0, inf)");
  ExpectIn(section + "against_distance_m", t.against_distance_m, "(0, inf)");
  ExpectIn(section + "near_distance_m", t.near_distance_m, "(0, inf)");
  ExpectIn(section + "far_distance_m", t.far_distance_m, "(0, inf)");
  Expect(t.near_distance_m < t.far_distance_m, section + "near_distance_m >= far_distance_m");
  ExpectIn(section + "beyond_distance_m", t.beyond_distance_m, "(0, inf)");
  ExpectIn(section + "goal_tolerance_m", t.goal_tolerance_m, "(0, inf)");
  for (double d : {t.default_door_width_m, t.default_chair_radius_m, t.default_desk_length_m,
                   t.default_desk_width_m}) {
    spott_fuzz::ExpectFinite(section + "default_*", d);
  }
  ExpectIn(section + "slow_fraction", t.slow_fraction, "(0, 1]");
  ExpectIn(section + "normal_fraction", t.normal_fraction, "(0, 1]");
  ExpectIn(section + "quick_fraction", t.quick_fraction, "(0, 1]");
  Expect(t.slow_fraction < t.normal_fraction && t.normal_fraction < t.quick_fraction,
         section + "fractions not slow < normal < quick");
  ExpectIn(section + "free_space_resolution_m", t.free_space_resolution_m, "(0, 0.5]");
}

void Node(FuzzedDataProvider& in) {
  static const auto vocabulary = spott_fuzz::LoadVocabulary(
      NODE_CONFIG_FILE, {{"program_file", "programs/spott_navigation.tr"}});
  spott_ros::ParameterReader r(spott_fuzz::BuildParameters(in, vocabulary));
  spott_tr_plus::NodeParameters p;
  spott_tr_plus::ReadParameters(r, p);
  if (!r.Finish().empty()) return;  // the node stops, naming every problem
  Expect(!p.program_file.empty(), "an empty program_file accepted");
  Expect(p.max_call_depth >= 1, "max_call_depth < 1 accepted");
  ExpectInterpretation("task/", p.task);
}

void Controller(FuzzedDataProvider& in) {
  static const auto vocabulary = spott_fuzz::LoadVocabulary(
      CONTROLLER_CONFIG_FILE, {{"program_file", "programs/spott_navigation.tr"}});
  const double radius = in.ConsumeFloatingPointInRange(0.0, 1.0);  // the robot description's
  spott_ros::ParameterReader r(spott_fuzz::BuildParameters(in, vocabulary));
  spott_tr_plus::controller::NodeParameters p;
  spott_tr_plus::controller::ReadParameters(r, p);
  p.controller.robot_radius_m = radius;
  for (const auto& v : spott_tr_plus::controller::ValidateParameters(p.controller)) r.Fail(v);
  if (!r.Finish().empty()) return;  // the node stops, naming every problem

  Expect(!p.program_file.empty() && !p.frame_id.empty() && !p.base_frame.empty(),
         "an empty program_file or frame accepted");
  ExpectIn("tick_rate_hz", p.tick_rate_hz, "[0.01, 200]");
  spott_fuzz::ExpectRosDuration("the tick timer's 1 / tick_rate_hz", 1.0 / p.tick_rate_hz);
  ExpectIn("ptu/sweep_period_s", p.ptu.sweep_period_s, "(0, inf)");
  ExpectIn("ptu/door_watch_m", p.ptu.door_watch_m, "[0, inf)");
  ExpectIn("ptu/max_pan_rad", p.ptu.max_pan_rad, "(0, 3.15)");
  for (double d : {p.ptu.sweep_rad, p.ptu.hallway_pan_rad, p.ptu_min_height_m, p.ptu_max_height_m,
                   p.marker_height_m}) {
    spott_fuzz::ExpectFinite("ptu/* or marker_height_m", d);
  }
  Expect(p.pan_joints.size() == p.tilt_joints.size(), "ptu joints of different counts");
  const auto& c = p.controller;
  ExpectIn("max_localization_error_m", c.max_localization_error_m, "[0, inf)");
  ExpectIn("drive/max_linear_mps", c.max_linear_mps, "(0, inf)");
  ExpectIn("drive/max_angular_rps", c.max_angular_rps, "(0, inf)");
  Expect(c.max_call_depth >= 1, "max_call_depth < 1 accepted");
  const auto& m = c.mapping;
  ExpectIn("mapping/cell_m", m.cell_m, "[0.02, 0.5]");
  ExpectIn("mapping/sonar_max_range_m", m.sonar_max_range_m, "(0, inf)");
  spott_fuzz::ExpectFinite("mapping/sonar_min_margin_m", m.sonar_min_margin_m);
  spott_fuzz::ExpectFinite("mapping/range_finder_max_range_m", m.range_finder_max_range_m);
  Expect(m.sonar_hit_score >= 1 && m.range_finder_hit_score >= 1 && m.miss_score >= 0 &&
             m.confirm_score >= 1,
         "mapping/*_score out of range accepted");
  Expect(m.max_score >= m.confirm_score, "mapping/max_score below confirm_score accepted");
  spott_fuzz::ExpectFinite("mapping/known_tolerance_m", m.known_tolerance_m);
  ExpectIn("mapping/door_zone_m", m.door_zone_m, "(0, inf)");
  spott_fuzz::ExpectFinite("mapping/segment_residual_m", m.segment_residual_m);
  ExpectIn("mapping/cluster_gap_m", m.cluster_gap_m, "(0, inf)");
  ExpectIn("mapping/echo_cluster_gap_m", m.echo_cluster_gap_m, "(0, inf)");
  const auto& ss = c.sonar_scan;
  ExpectIn("sonar_scan/period_s", ss.period_s, "[0, inf)");
  ExpectIn("sonar_scan/steps", ss.steps, "[2, 64]");
  ExpectIn("sonar_scan/step_rad", ss.step_rad, "(0, 0.79]");
  Expect(ss.settle_rad > 0 && ss.settle_rad < ss.step_rad / 2,
         "sonar_scan/settle_rad out of (0, step_rad / 2) accepted");
  ExpectIn("sonar_scan/step_timeout_s", ss.step_timeout_s, "(0, inf)");
  ExpectIn("mapping/echo_tolerance_m", m.echo_fit.tolerance_base_m, "(0, inf)");
  ExpectIn("mapping/echo_tolerance_per_m", m.echo_fit.tolerance_per_m, "[0, inf)");
  ExpectIn("mapping/sonar_max_incidence_rad", m.echo_fit.max_incidence_rad, "[0, 1.58)");
  ExpectIn("mapping/echo_max_direction_error_rad", m.echo_fit.max_direction_error_rad, "(0, 1)");
  ExpectIn("mapping/echoes_per_cell", m.echoes_per_cell, "[1, 64]");
  const auto& d = c.doors;
  spott_fuzz::ExpectFinite("doors/range_m", d.range_m);
  ExpectIn("doors/end_margin_m", d.end_margin_m, "[0, inf)");
  spott_fuzz::ExpectFinite("doors/pose_error_m", d.pose_error_m);
  ExpectIn("doors/match_m", d.match_m, "(0, inf)");
  ExpectIn("doors/beyond_m", d.beyond_m, "(0, inf)");
  spott_fuzz::ExpectFinite("doors/normal_angle_rad", d.normal_angle_rad);
  ExpectIn("doors/profile_normal_angle_rad", d.profile_normal_angle_rad, "[0, 1.58)");
  Expect(d.votes >= 1 && d.max_votes >= d.votes, "doors/votes or max_votes out of range");
  const auto& x = c.reflex;
  ExpectIn("reflex/speed_mps", x.speed_mps, "(0, inf)");
  ExpectIn("reflex/turn_rps", x.turn_rps, "(0, inf)");
  ExpectIn("reflex/align_rad", x.align_rad, "(0, pi/2)");
  ExpectIn("reflex/timeout_s", x.timeout_s, "(0, inf)");
  spott_fuzz::ExpectFinite("reflex/infrared_close_m", x.infrared_close_m);
  spott_fuzz::ExpectFinite("reflex/known_tolerance_m", x.known_tolerance_m);
  const auto& t = c.teleop;
  ExpectIn("teleop/stop_distance_m", t.stop_distance_m, "(0, inf)");
  ExpectIn("teleop/lookahead_m", t.lookahead_m, "(0, inf)");
  ExpectIn("teleop/clearance_m", t.clearance_m, "[0, inf)");
  ExpectIn("teleop/max_deviation_rad", t.max_deviation_rad, "[0, pi/2]");
  ExpectIn("teleop/heading_gain_per_s", t.heading_gain_per_s, "(0, inf)");
  ExpectIn("teleop/blocked_timeout_s", t.blocked_timeout_s, "(0, inf)");
  const auto& l = c.localization;
  ExpectIn("localization/period_s", l.period_s, "(0, inf)");
  ExpectIn("localization/distance_m", l.distance_m, "(0, inf)");
  ExpectIn("localization/place_radius_m", l.place_radius_m, "[0, inf)");
  ExpectIn("localization/max_age_s", l.max_age_s, "(0, inf)");
  ExpectIn("localization/jump_m", l.jump_m, "(0, inf)");
  ExpectIn("localization/jump_rad", l.jump_rad, "(0, inf)");
  ExpectIn("localization/retract_s", l.retract_s, "[0, inf)");
  ExpectIn("localization/settle_s", l.settle_s, "[0, inf)");
  ExpectIn("localization/keep_radius_m", l.keep_radius_m, "[0, 10]");
  const auto& k = c.tasks;
  ExpectIn("tasks/goal_tolerance_m", k.goal_tolerance_m, "(0, inf)");
  Expect(k.navigate_retries >= 0, "tasks/navigate_retries < 0 accepted");
  ExpectIn("tasks/retry_delay_s", k.retry_delay_s, "[0, inf)");
  ExpectIn("tasks/localized_wait_s", k.localized_wait_s, "(0, inf)");
  ExpectIn("tasks/stop_speed_mps", k.stop_speed_mps, "(0, inf)");
  ExpectIn("tasks/stop_timeout_s", k.stop_timeout_s, "(0, inf)");
  ExpectIn("tasks/pose_timeout_s", k.pose_timeout_s, "(0, inf)");
  ExpectIn("tasks/search_turn_rps", k.search_turn_rps, "(0, inf)");
  ExpectIn("tasks/obstacle_ahead_m", k.obstacle_ahead_m, "(0, inf)");
  ExpectIn("tasks/feedback_period_s", k.feedback_period_s, "(0, inf)");
  ExpectInterpretation("task/", c.interpretation);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzedDataProvider in(data, size);
  if (in.ConsumeBool()) {
    Controller(in);
  } else {
    Node(in);
  }
  return 0;
}
