#include "spott_harmonic_planner/ros/parameters.h"

#include <cmath>

namespace spott_harmonic_planner {

std::vector<std::string> ReadParameters(const ros::NodeHandle& pnh, NodeParameters& p) {
  std::vector<std::string> v;
  auto& w = p.planner.window;
  pnh.param("window_size", w.window_size_m, w.window_size_m);
  pnh.param("resolution", w.resolution_m, w.resolution_m);
  pnh.param("robot_radius", w.robot_radius_m, w.robot_radius_m);
  pnh.param("max_localization_error", w.max_localization_error_m, w.max_localization_error_m);
  pnh.param("recentre_margin", w.recentre_margin_m, w.recentre_margin_m);
  std::string solver = "multigrid_cg", stencil = "five_point", norm = "relative";
  pnh.param<std::string>("solver", solver, solver);
  pnh.param<std::string>("stencil", stencil, stencil);
  pnh.param<std::string>("residual_norm", norm, norm);
  if (const auto k = ParseSolverKind(solver)) {
    p.planner.field.solver.kind = *k;
  } else {
    v.push_back("~solver must be sor_red_black, adi, multigrid or multigrid_cg (got '" + solver +
                "')");
  }
  if (const auto s = ParseStencil(stencil)) {
    p.planner.field.solver.stencil = *s;
  } else {
    v.push_back("~stencil must be five_point or nine_point (got '" + stencil + "')");
  }
  if (norm == "absolute" || norm == "relative") {
    p.planner.field.norm = norm == "absolute" ? ResidualNorm::kAbsolute : ResidualNorm::kRelative;
  } else {
    v.push_back("~residual_norm must be absolute or relative (got '" + norm + "')");
  }
  pnh.param("omega", p.planner.field.solver.omega, p.planner.field.solver.omega);
  pnh.param("tolerance", p.planner.field.tolerance, p.planner.field.tolerance);
  pnh.param("sweeps_per_cycle", p.planner.sweeps_per_cycle, p.planner.sweeps_per_cycle);
  pnh.param("goal_tolerance", p.planner.goal_tolerance_m, p.planner.goal_tolerance_m);
  pnh.param("border_goal_half_width", p.planner.border_goal_half_width_m,
            p.planner.border_goal_half_width_m);
  auto& s = p.planner.steering;
  pnh.param("max_linear", s.max_linear_mps, s.max_linear_mps);
  pnh.param("max_angular", s.max_angular_rps, s.max_angular_rps);
  pnh.param("slowly_fraction", s.slowly_fraction, s.slowly_fraction);
  pnh.param("normal_fraction", s.normal_fraction, s.normal_fraction);
  pnh.param("quickly_fraction", s.quickly_fraction, s.quickly_fraction);
  pnh.param("heading_gain", s.heading_gain, s.heading_gain);
  pnh.param("max_bias_deviation", s.max_bias_deviation_rad, s.max_bias_deviation_rad);
  pnh.param("slow_clearance", s.slow_clearance_m, s.slow_clearance_m);
  pnh.param("escape_radius", s.escape_radius_m, s.escape_radius_m);
  pnh.param("goal_slowdown", s.goal_slowdown_m, s.goal_slowdown_m);
  pnh.param<std::string>("frame_id", p.frame_id, p.frame_id);
  pnh.param<std::string>("base_frame", p.base_frame, p.base_frame);
  pnh.param("cycle_rate", p.cycle_rate_hz, p.cycle_rate_hz);
  pnh.param("visualization_every", p.visualization_every, p.visualization_every);
  pnh.param("unreachable_cycles", p.unreachable_cycles, p.unreachable_cycles);
  pnh.param("heading_tolerance", p.heading_tolerance_rad, p.heading_tolerance_rad);
  if (!(p.heading_tolerance_rad > 0.0 && p.heading_tolerance_rad <= M_PI)) {
    v.push_back("~heading_tolerance must be in (0, pi] rad (got " +
                std::to_string(p.heading_tolerance_rad) + ")");
  }
  for (const auto& e : ValidateParameters(p.planner)) v.push_back("~" + e);
  if (!(p.cycle_rate_hz > 0.0 && p.cycle_rate_hz <= 1000.0)) {
    v.push_back("~cycle_rate must be in (0, 1000] Hz (got " + std::to_string(p.cycle_rate_hz) +
                ")");
  }
  if (p.visualization_every < 1) v.push_back("~visualization_every must be >= 1");
  if (p.unreachable_cycles < 1) v.push_back("~unreachable_cycles must be >= 1");
  if (p.frame_id.empty() || p.base_frame.empty())
    v.push_back("~frame_id and ~base_frame must not be empty");
  return v;
}

}  // namespace spott_harmonic_planner
