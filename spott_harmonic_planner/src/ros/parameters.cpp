#include "spott_harmonic_planner/ros/parameters.h"

#include <cmath>

namespace spott_harmonic_planner {

void ReadParameters(spott_ros::ParameterReader& r, NodeParameters& p) {
  r.Get("frame_id", p.frame_id);
  r.Get("odom_frame", p.odom_frame);
  r.Get("base_frame", p.base_frame);
  r.Get("robot_description", p.robot_description);
  r.Get("cycle_rate_hz", p.cycle_rate_hz, "Hz");
  r.Get("visualization_every", p.visualization_every);

  auto& w = p.planner.window;
  r.Get("window/window_size_m", w.window_size_m, "m");
  r.Get("window/resolution_m", w.resolution_m, "m");
  r.Get("window/max_localization_error_m", w.max_localization_error_m, "m");
  r.Get("window/recentre_margin_m", w.recentre_margin_m, "m");
  r.Get("window/door_thickness_m", w.door_thickness_m, "m");

  std::string solver = "multigrid_cg", stencil = "five_point", norm = "relative";
  auto& f = p.planner.field;
  r.Get("solver/kind", solver);
  r.Get("solver/stencil", stencil);
  r.Get("solver/residual_norm", norm);
  r.Get("solver/omega", f.solver.omega);
  r.Get("solver/tolerance", f.tolerance);
  r.Get("solver/start_fraction", f.start_fraction);
  r.Get("solver/sweeps_per_cycle", p.planner.sweeps_per_cycle);
  if (const auto k = ParseSolverKind(solver)) {
    f.solver.kind = *k;
  } else {
    r.Fail("solver/kind must be sor_red_black, adi, multigrid or multigrid_cg (got '" + solver +
           "')");
  }
  if (const auto s = ParseStencil(stencil)) {
    f.solver.stencil = *s;
  } else {
    r.Fail("solver/stencil must be five_point or nine_point (got '" + stencil + "')");
  }
  if (norm == "absolute" || norm == "relative") {
    f.norm = norm == "absolute" ? ResidualNorm::kAbsolute : ResidualNorm::kRelative;
  } else {
    r.Fail("solver/residual_norm must be absolute or relative (got '" + norm + "')");
  }

  auto& n = p.navigate;
  r.Get("navigate/goal_tolerance_m", p.planner.goal_tolerance_m, "m");
  r.Get("navigate/heading_tolerance_rad", p.heading_tolerance_rad, "rad");
  r.Get("navigate/border_goal_half_width_m", p.planner.border_goal_half_width_m, "m");
  r.Get("navigate/unreachable_cycles", n.unreachable_cycles);
  r.Get("navigate/planning_timeout_s", n.planning_timeout_s, "s");
  r.Get("navigate/use_global_planner", n.use_global_planner);
  // Without the global planner there is no map beyond the window to route by: explore.
  p.planner.explore_when_cut_off = !n.use_global_planner;
  r.Get("navigate/backoff_distance_m", n.backoff_distance_m, "m");
  r.Get("navigate/backoff_speed_mps", n.backoff_speed_mps, "m/s");
  r.Get("navigate/arrival_stall_s", n.arrival_stall_s, "s");
  r.Get("navigate/planner_patience_s", n.planner_patience_s, "s");
  r.Get("navigate/settle_timeout_s", n.settle_timeout_s, "s");
  r.Get("navigate/max_settle_drive_ons", n.max_settle_drive_ons);
  r.Get("navigate/settle_max_offset_m", n.settle_max_offset_m, "m");
  r.Get("navigate/localization_topic", p.localization_topic);
  r.Get("navigate/lost_timeout_s", n.lost_timeout_s, "s");
  r.Get("navigate/progress_radius_m", n.progress_radius_m, "m");
  r.Get("navigate/progress_timeout_s", n.progress_timeout_s, "s");
  r.Get("navigate/localization_status_topic", p.localization_status_topic);
  r.Get("navigate/contact_memory_s", p.contact_memory_s, "s");
  r.Get("navigate/contact_size_m", p.contact_size_m, "m");
  r.Get("navigate/bumper_backoff", p.bumper_backoff);

  auto& s = p.planner.steering;
  r.Get("steering/max_linear_mps", s.max_linear_mps, "m/s");
  r.Get("steering/max_angular_rps", s.max_angular_rps, "rad/s");
  r.Get("steering/slowly_fraction", s.slowly_fraction);
  r.Get("steering/normal_fraction", s.normal_fraction);
  r.Get("steering/quickly_fraction", s.quickly_fraction);
  r.Get("steering/heading_gain_per_s", s.heading_gain, "1/s");
  r.Get("steering/max_bias_deviation_rad", s.max_bias_deviation_rad, "rad");
  r.Get("steering/bias_reverse_fade_rad", s.bias_reverse_fade_rad, "rad");
  r.Get("steering/bias_clearance_m", s.bias_clearance_m, "m");
  r.Get("steering/slow_clearance_m", s.slow_clearance_m, "m");
  r.Get("steering/escape_radius_m", s.escape_radius_m, "m");
  r.Get("steering/escape_speed_fraction", s.escape_speed_fraction);
  r.Get("steering/goal_slowdown_m", s.goal_slowdown_m, "m");

  r.Require(p.heading_tolerance_rad > 0.0 && p.heading_tolerance_rad <= M_PI,
            "navigate/heading_tolerance_rad", "in (0, pi]", p.heading_tolerance_rad);
  // The timer's period 1 / cycle_rate_hz must make a ros::Duration (at most 2^31 s).
  r.Require(p.cycle_rate_hz >= 0.01 && p.cycle_rate_hz <= 1000.0, "cycle_rate_hz",
            "in [0.01, 1000]", p.cycle_rate_hz);
  r.Require(p.visualization_every >= 1, "visualization_every", ">= 1", p.visualization_every);
  r.Require(p.contact_memory_s > 0.0, "navigate/contact_memory_s", "> 0", p.contact_memory_s);
  r.Require(p.contact_size_m > 0.0 && p.contact_size_m <= 1.0, "navigate/contact_size_m",
            "in (0, 1]", p.contact_size_m);
  if (p.frame_id.empty() || p.base_frame.empty())
    r.Fail("frame_id and base_frame must not be empty");
  for (const auto& e : ValidateParameters(p.navigate)) r.Fail(e);
}

}  // namespace spott_harmonic_planner
