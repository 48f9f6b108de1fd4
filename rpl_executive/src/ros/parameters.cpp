#include "parameters.h"

#include "spott_ros/parameter_reader.h"

namespace rpl_executive::ros_parameters {

namespace {

void Prefixed(spott_ros::ParameterReader& r, const std::string& section,
              const std::vector<std::string>& violations) {
  for (const std::string& v : violations) r.Fail(section + v);
}

}  // namespace

std::vector<std::string> ValidateParameters(const NodeParameters& p) {
  std::vector<std::string> e;
  if (p.pose_source != "odometry" && p.pose_source != "localization")
    e.push_back("nc/pose_source: must be odometry or localization, got '" + p.pose_source + "'");
  for (const std::string* f :
       {&p.map_frame, &p.base_frame, &p.odom_frame, &p.arbiter, &p.wheels_source,
        &p.navigate_action, &p.active_localize_action, &p.global_localization_service,
        &p.enable_sonar_service, &p.planner_cmd_topic, &p.wander_cmd_topic, &p.sonar_topic,
        &p.laser_topic, &p.battery_topic}) {
    if (f->empty()) e.push_back("frame, topic, action and service names must not be empty");
  }
  // The state timer's period 1 / state_rate_hz must make a ros::Duration (at most 2^31 s).
  if (!(p.state_rate_hz == 0 || (p.state_rate_hz >= 0.01 && p.state_rate_hz <= 100)))
    e.push_back("state_rate_hz: must be 0 (on change only) or in [0.01, 100] Hz");
  if (!(p.ended_threads_kept >= 0 && p.ended_threads_kept <= 1000))
    e.push_back("ended_threads_kept: must be in [0, 1000]");
  if (!(p.service_timeout_s > 0 && p.service_timeout_s <= 60))
    e.push_back("service_timeout_s: must be in (0, 60] s");
  if (!(p.tracking_status_timeout_s > 0 && p.tracking_status_timeout_s <= 600))
    e.push_back("rpl/tracking_status_timeout_s: must be in (0, 600] s");
  if (!(p.control_rate_hz >= 1 && p.control_rate_hz <= 1000))
    e.push_back("nc/control_rate_hz: must be in [1, 1000] Hz");
  for (double v : {p.travel.office_max_linear_mps, p.travel.hallway_max_linear_mps,
                   p.travel.doorway_max_linear_mps, p.travel.office_max_angular_rps,
                   p.travel.hallway_max_angular_rps, p.travel.doorway_max_angular_rps}) {
    if (!(v >= 0 && v <= 10)) {
      e.push_back("rpl/travel_modes/*: speed limits must be in [0, 10] (0 = the robot's own)");
      break;
    }
  }
  return e;
}

void Read(spott_ros::ParameterReader& r, NodeParameters& p) {
  r.Get("map_frame", p.map_frame);
  r.Get("base_frame", p.base_frame);
  r.Get("odom_frame", p.odom_frame);
  r.Get("arbiter", p.arbiter);
  r.Get("wheels_source", p.wheels_source);
  r.Get("state_rate_hz", p.state_rate_hz, "Hz");
  r.Get("ended_threads_kept", p.ended_threads_kept);
  r.Get("service_timeout_s", p.service_timeout_s, "s");

  // RPL
  r.Get("rpl/max_instructions_per_step", p.rpl.max_instructions_per_step);
  r.Get("rpl/max_call_depth", p.rpl.max_call_depth);
  r.Get("rpl/event_log_capacity", p.rpl.event_log_capacity);
  r.Get("rpl/max_live_tasks", p.rpl.max_live_tasks);
  Prefixed(r, "rpl/", rpl::ValidateParameters(p.rpl));
  auto& nav = p.navigation;
  r.Get("rpl/navigation/goal_tolerance_m", nav.goal_tolerance_m, "m");
  r.Get("rpl/navigation/target_tolerance_m", nav.target_tolerance_m, "m");
  r.Get("rpl/navigation/door_approach_m", nav.plan.door_approach_m, "m");
  r.Get("rpl/navigation/doorway_depth_m", nav.plan.doorway_depth_m, "m");
  r.Get("rpl/navigation/doorway_margin_m", nav.plan.doorway_margin_m, "m");
  r.Get("rpl/navigation/office_pass_penalty_m", nav.plan.office_pass_penalty_m, "m");
  r.Get("rpl/navigation/min_target_spacing_m", nav.plan.min_target_spacing_m, "m");
  Prefixed(r, "rpl/navigation/", rpl::office::ValidateParameters(nav));
  auto& al = p.active_localization;
  r.Get("rpl/active_localization/uniform_start", al.uniform_start);
  r.Get("rpl/active_localization/certainty_threshold", al.certainty_threshold);
  r.Get("rpl/active_localization/timeout_s", al.timeout_s, "s");
  Prefixed(r, "rpl/active_localization/", rpl::office::ValidateParameters(al));
  r.Get("rpl/travel_modes/office_max_linear_mps", p.travel.office_max_linear_mps, "m/s");
  r.Get("rpl/travel_modes/hallway_max_linear_mps", p.travel.hallway_max_linear_mps, "m/s");
  r.Get("rpl/travel_modes/doorway_max_linear_mps", p.travel.doorway_max_linear_mps, "m/s");
  r.Get("rpl/travel_modes/office_max_angular_rps", p.travel.office_max_angular_rps, "rad/s");
  r.Get("rpl/travel_modes/hallway_max_angular_rps", p.travel.hallway_max_angular_rps, "rad/s");
  r.Get("rpl/travel_modes/doorway_max_angular_rps", p.travel.doorway_max_angular_rps, "rad/s");
  r.Get("rpl/travel_modes/doorway_sonars_off", p.travel.doorway_sonars_off);
  r.Get("rpl/tracking_status_timeout_s", p.tracking_status_timeout_s, "s");
  r.Get("rpl/navigate_action", p.navigate_action);
  r.Get("rpl/active_localize_action", p.active_localize_action);
  r.Get("rpl/global_localization_service", p.global_localization_service);
  r.Get("rpl/enable_sonar_service", p.enable_sonar_service);
  r.Get("rpl/planner_cmd_topic", p.planner_cmd_topic);
  r.Get("rpl/wander_cmd_topic", p.wander_cmd_topic);

  // Noreils-Chatila
  r.Get("nc/interruption_report_timeout_s", p.nc.interruption_report_timeout_s, "s");
  int capacity = static_cast<int>(p.nc.message_capacity);
  r.Get("nc/message_capacity", capacity);
  r.Require(capacity >= 0, "nc/message_capacity", ">= 0", capacity);
  p.nc.message_capacity = static_cast<size_t>(std::max(0, capacity));
  Prefixed(r, "nc/", noreils_chatila::ValidateParameters(p.nc));
  auto& s = p.surveillance;
  r.Get("nc/part_validity_s", s.part_validity_s, "s");
  r.Get("nc/laser_front_half_angle_rad", s.laser_front_half_angle_rad, "rad");
  auto& sonar = s.sonar;
  r.Get("nc/sonar/min_sensors", sonar.min_sensors);
  r.Get("nc/sonar/max_rms_m", sonar.max_rms_m, "m");
  r.Get("nc/sonar/max_range_m", sonar.max_range_m, "m");
  r.Get("nc/sonar/search_margin_rad", sonar.search_margin_rad, "rad");
  r.Get("nc/sonar/rho_tolerance_m", sonar.rho_tolerance_m, "m");
  r.Get("nc/sonar/theta_tolerance_rad", sonar.theta_tolerance_rad, "rad");
  Prefixed(r, "nc/", noreils_chatila::ValidateParameters(s));
  auto& ob = p.on_board;
  ob.sonar = sonar;
  auto& pi = ob.pilot;
  r.Get("nc/pilot/default_speed_mps", pi.default_speed_mps, "m/s");
  r.Get("nc/pilot/max_speed_mps", pi.max_speed_mps, "m/s");
  r.Get("nc/pilot/max_angular_rps", pi.max_angular_rps, "rad/s");
  r.Get("nc/pilot/lookahead_m", pi.lookahead_m, "m");
  r.Get("nc/pilot/k_x", pi.k_x, "1/s");
  r.Get("nc/pilot/k_y", pi.k_y, "1/m^2");
  r.Get("nc/pilot/k_theta", pi.k_theta, "1/m");
  r.Get("nc/pilot/goal_tolerance_m", pi.goal_tolerance_m, "m");
  r.Get("nc/pilot/heading_tolerance_rad", pi.heading_tolerance_rad, "rad");
  r.Get("nc/pilot/turn_in_place_rad", pi.turn_in_place_rad, "rad");
  r.Get("nc/pilot/k_turn", pi.k_turn, "1/s");
  r.Get("nc/pilot/slow_down_distance_m", pi.slow_down_distance_m, "m");
  r.Get("nc/pilot/corner_distance_max_m", pi.smoothing.corner_distance_max_m, "m");
  r.Get("nc/pilot/sample_step_m", pi.smoothing.sample_step_m, "m");
  r.Get("nc/pilot/max_deflection_rad", pi.smoothing.max_deflection_rad, "rad");
  auto& wf = ob.wall_following;
  r.Get("nc/wall_following/speed_mps", wf.speed_mps, "m/s");
  r.Get("nc/wall_following/k_distance", wf.k_distance, "rad/s/m");
  r.Get("nc/wall_following/k_heading", wf.k_heading, "1/s");
  r.Get("nc/wall_following/max_angular_rps", wf.max_angular_rps, "rad/s");
  r.Get("nc/wall_following/front_distance_m", wf.front_distance_m, "m");
  r.Get("nc/wall_following/side_window_rad", wf.side_window_rad, "rad");
  r.Get("nc/wall_following/insufficient_data_limit", wf.insufficient_data_limit);
  auto& oa = ob.obstacle_avoidance;
  r.Get("nc/obstacle_avoidance/speed_mps", oa.speed_mps, "m/s");
  r.Get("nc/obstacle_avoidance/detect_distance_m", oa.detect_distance_m, "m");
  r.Get("nc/obstacle_avoidance/stop_distance_m", oa.stop_distance_m, "m");
  r.Get("nc/obstacle_avoidance/front_half_angle_rad", oa.front_half_angle_rad, "rad");
  r.Get("nc/obstacle_avoidance/max_angular_rps", oa.max_angular_rps, "rad/s");
  r.Get("nc/obstacle_avoidance/insufficient_data_limit", oa.insufficient_data_limit);
  r.Get("nc/obstacle_avoidance/robot_radius_m", oa.robot_radius_m, "m");
  r.Get("nc/obstacle_avoidance/way_clearance_m", oa.way_clearance_m, "m");
  r.Get("nc/obstacle_avoidance/way_check_distance_m", oa.way_check_distance_m, "m");
  r.Get("nc/obstacle_avoidance/max_travel_m", oa.max_travel_m, "m");
  r.Get("nc/obstacle_avoidance/goal_turn_gain", oa.goal_turn_gain, "1/s");
  r.Get("nc/obstacle_avoidance/forget_margin_m", oa.forget_margin_m, "m");
  Prefixed(r, "nc/", noreils_chatila::ValidateParameters(ob));
  r.Get("nc/control_rate_hz", p.control_rate_hz, "Hz");
  r.Get("nc/pose_source", p.pose_source);
  r.Get("nc/o_surveillances", p.o_surveillances);
  r.Get("nc/sonar_topic", p.sonar_topic);
  r.Get("nc/laser_topic", p.laser_topic);
  r.Get("nc/battery_topic", p.battery_topic);

  for (const std::string& e : ValidateParameters(p)) r.Fail(e);
}

}  // namespace rpl_executive::ros_parameters
