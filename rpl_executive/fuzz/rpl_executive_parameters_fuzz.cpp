// rpl_executive's parameters from the fuzzer's bytes (tools/fuzz/parameter_fuzz.h): Read and the
// reader's Finish, as main() does (spott_ros::ReadNodeParameters). Whatever the node accepts must
// lie in the ranges its config file and the cores' headers document, make the ros::Durations of
// its timers and waits, build the RPL executive, and let HILARE's pilot smooth a path.
#include <cmath>
#include <stdexcept>

#include "../src/ros/parameters.h"
#include "parameter_fuzz.h"
#include "rpl_executive/noreils_chatila/path_smoothing.h"
#include "rpl_executive/rpl/executive.h"
#include "spott_ros/parameter_reader.h"

using namespace rpl_executive;
using spott_fuzz::Expect;
using spott_fuzz::ExpectIn;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const auto vocabulary =
      spott_fuzz::LoadVocabulary(CONFIG_FILE, {}, {}, {"odometry", "localization"});
  FuzzedDataProvider in(data, size);
  spott_ros::ParameterReader r(spott_fuzz::BuildParameters(in, vocabulary));
  ros_parameters::NodeParameters p;
  ros_parameters::Read(r, p);
  if (!r.Finish().empty()) return 0;  // the node stops, naming every problem

  if (p.state_rate_hz != 0) {
    ExpectIn("state_rate_hz", p.state_rate_hz, "[0.01, 100]");
    spott_fuzz::ExpectRosDuration("the state timer's 1 / state_rate_hz", 1.0 / p.state_rate_hz);
  }
  Expect(p.ended_threads_kept >= 0 && p.ended_threads_kept <= 1000, "ended_threads_kept");
  ExpectIn("service_timeout_s", p.service_timeout_s, "(0, 60]");
  spott_fuzz::ExpectRosDuration("waitForExistence(service_timeout_s)", p.service_timeout_s);
  ExpectIn("rpl/tracking_status_timeout_s", p.tracking_status_timeout_s, "(0, 600]");
  ExpectIn("nc/control_rate_hz", p.control_rate_hz, "[1, 1000]");
  spott_fuzz::ExpectRosDuration("the control timer's 1 / control_rate_hz", 1.0 / p.control_rate_hz);
  Expect(p.pose_source == "odometry" || p.pose_source == "localization", "nc/pose_source");

  const auto& x = p.rpl;
  Expect(x.max_instructions_per_step >= 1 && x.max_instructions_per_step <= 1000000000,
         "rpl/max_instructions_per_step outside [1, 1e9]");
  Expect(x.max_call_depth >= 1 && x.max_call_depth <= 100000, "rpl/max_call_depth");
  Expect(x.event_log_capacity >= 0 && x.event_log_capacity <= 10000000, "rpl/event_log_capacity");
  Expect(x.max_live_tasks >= 1 && x.max_live_tasks <= 100000000, "rpl/max_live_tasks");
  const auto& nav = p.navigation;
  ExpectIn("rpl/navigation/goal_tolerance_m", nav.goal_tolerance_m, "(0, 5]");
  ExpectIn("rpl/navigation/target_tolerance_m", nav.target_tolerance_m, "(0, 5]");
  ExpectIn("rpl/navigation/door_approach_m", nav.plan.door_approach_m, "(0, 5]");
  ExpectIn("rpl/navigation/doorway_depth_m", nav.plan.doorway_depth_m, "(0, 5]");
  ExpectIn("rpl/navigation/doorway_margin_m", nav.plan.doorway_margin_m, "[0, 2]");
  ExpectIn("rpl/navigation/office_pass_penalty_m", nav.plan.office_pass_penalty_m, "[0, 1e6]");
  ExpectIn("rpl/navigation/min_target_spacing_m", nav.plan.min_target_spacing_m, "[0, 5]");
  const auto& al = p.active_localization;
  ExpectIn("rpl/active_localization/certainty_threshold", al.certainty_threshold, "(0, 1)");
  ExpectIn("rpl/active_localization/timeout_s", al.timeout_s, "[0, 1e5]");
  for (const auto& [name, v] :
       {std::pair<const char*, double>{"office_max_linear_mps", p.travel.office_max_linear_mps},
        {"hallway_max_linear_mps", p.travel.hallway_max_linear_mps},
        {"doorway_max_linear_mps", p.travel.doorway_max_linear_mps},
        {"office_max_angular_rps", p.travel.office_max_angular_rps},
        {"hallway_max_angular_rps", p.travel.hallway_max_angular_rps},
        {"doorway_max_angular_rps", p.travel.doorway_max_angular_rps}}) {
    ExpectIn(std::string("rpl/travel_modes/") + name, v, "[0, 10]");
  }

  ExpectIn("nc/interruption_report_timeout_s", p.nc.interruption_report_timeout_s, "(0, inf)");
  const auto& s = p.surveillance;
  ExpectIn("nc/part_validity_s", s.part_validity_s, "(0, inf)");
  ExpectIn("nc/laser_front_half_angle_rad", s.laser_front_half_angle_rad, "(0, pi]");
  const auto& on_board = p.on_board;
  for (const auto* sonar : {&s.sonar, &on_board.sonar}) {
    Expect(sonar->min_sensors >= 2 && sonar->min_sensors <= 16, "nc/sonar/min_sensors");
    ExpectIn("nc/sonar/max_rms_m", sonar->max_rms_m, "(0, 1]");
    ExpectIn("nc/sonar/max_range_m", sonar->max_range_m, "(0, inf)");
    ExpectIn("nc/sonar/search_margin_rad", sonar->search_margin_rad, "[0, pi/2)");
    ExpectIn("nc/sonar/rho_tolerance_m", sonar->rho_tolerance_m, "(0, inf)");
    ExpectIn("nc/sonar/theta_tolerance_rad", sonar->theta_tolerance_rad, "(0, pi)");
  }
  const auto& pi = p.on_board.pilot;
  ExpectIn("nc/pilot/max_speed_mps", pi.max_speed_mps, "(0, inf)");
  ExpectIn("nc/pilot/default_speed_mps", pi.default_speed_mps, "(0, inf)");
  Expect(pi.default_speed_mps <= pi.max_speed_mps, "nc/pilot/default_speed_mps > max_speed_mps");
  ExpectIn("nc/pilot/max_angular_rps", pi.max_angular_rps, "(0, inf)");
  ExpectIn("nc/pilot/lookahead_m", pi.lookahead_m, "[0, inf)");
  ExpectIn("nc/pilot/k_x", pi.k_x, "(0, inf)");
  ExpectIn("nc/pilot/k_y", pi.k_y, "(0, inf)");
  ExpectIn("nc/pilot/k_theta", pi.k_theta, "(0, inf)");
  ExpectIn("nc/pilot/goal_tolerance_m", pi.goal_tolerance_m, "(0, inf)");
  ExpectIn("nc/pilot/heading_tolerance_rad", pi.heading_tolerance_rad, "(0, pi)");
  ExpectIn("nc/pilot/turn_in_place_rad", pi.turn_in_place_rad, "(0, pi]");
  ExpectIn("nc/pilot/k_turn", pi.k_turn, "(0, inf)");
  ExpectIn("nc/pilot/slow_down_distance_m", pi.slow_down_distance_m, "[0, inf)");
  ExpectIn("nc/pilot/corner_distance_max_m", pi.smoothing.corner_distance_max_m, "(0, inf)");
  ExpectIn("nc/pilot/sample_step_m", pi.smoothing.sample_step_m, "[0.001, 1]");
  ExpectIn("nc/pilot/max_deflection_rad", pi.smoothing.max_deflection_rad, "(0, pi)");
  const auto& wf = p.on_board.wall_following;
  ExpectIn("nc/wall_following/speed_mps", wf.speed_mps, "(0, inf)");
  ExpectIn("nc/wall_following/k_distance", wf.k_distance, "(0, inf)");
  ExpectIn("nc/wall_following/k_heading", wf.k_heading, "(0, inf)");
  ExpectIn("nc/wall_following/max_angular_rps", wf.max_angular_rps, "(0, inf)");
  ExpectIn("nc/wall_following/front_distance_m", wf.front_distance_m, "(0, inf)");
  ExpectIn("nc/wall_following/side_window_rad", wf.side_window_rad, "(0, pi]");
  Expect(wf.insufficient_data_limit >= 1, "nc/wall_following/insufficient_data_limit < 1");
  const auto& oa = p.on_board.obstacle_avoidance;
  ExpectIn("nc/obstacle_avoidance/speed_mps", oa.speed_mps, "(0, inf)");
  ExpectIn("nc/obstacle_avoidance/stop_distance_m", oa.stop_distance_m, "[0, inf)");
  ExpectIn("nc/obstacle_avoidance/detect_distance_m", oa.detect_distance_m, "(0, inf)");
  Expect(oa.detect_distance_m > oa.stop_distance_m, "detect_distance_m <= stop_distance_m");
  ExpectIn("nc/obstacle_avoidance/front_half_angle_rad", oa.front_half_angle_rad, "(0, pi]");
  ExpectIn("nc/obstacle_avoidance/max_angular_rps", oa.max_angular_rps, "(0, inf)");
  Expect(oa.insufficient_data_limit >= 1, "nc/obstacle_avoidance/insufficient_data_limit < 1");
  ExpectIn("nc/obstacle_avoidance/robot_radius_m", oa.robot_radius_m, "[0, inf)");
  ExpectIn("nc/obstacle_avoidance/way_clearance_m", oa.way_clearance_m, "[0, inf)");
  ExpectIn("nc/obstacle_avoidance/way_check_distance_m", oa.way_check_distance_m, "(0, inf)");
  ExpectIn("nc/obstacle_avoidance/max_travel_m", oa.max_travel_m, "(0, inf)");
  ExpectIn("nc/obstacle_avoidance/goal_turn_gain", oa.goal_turn_gain, "(0, inf)");
  ExpectIn("nc/obstacle_avoidance/forget_margin_m", oa.forget_margin_m, "[0, inf)");

  try {
    rpl::Executive executive(p.rpl);  // what RplBinding builds
    // The pilot smooths every path it is given: a 2 m corner here.
    noreils_chatila::SmoothBrokenLine({{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}}, pi.smoothing);
  } catch (const std::exception& e) {
    Expect(false, std::string("the node accepted parameters its core refuses: ") + e.what());
  }
  return 0;
}
