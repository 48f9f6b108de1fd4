// The harmonic planner node's parameters from the fuzzer's bytes (tools/fuzz/parameter_fuzz.h):
// ReadParameters, the robot's radius as the node sets it, the core's ValidateParameters and the
// reader's Finish, as main() does. Whatever the node accepts must lie in the ranges its config
// file and headers document, make the timer's ros::Duration and the cores the node builds.
#include <cmath>
#include <stdexcept>

#include "parameter_fuzz.h"
#include "spott_harmonic_planner/contact_memory.h"
#include "spott_harmonic_planner/local_planner.h"
#include "spott_harmonic_planner/navigate_session.h"
#include "spott_harmonic_planner/ros/parameters.h"

using namespace spott_harmonic_planner;
using spott_fuzz::Expect;
using spott_fuzz::ExpectIn;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const auto vocabulary = spott_fuzz::LoadVocabulary(
      CONFIG_FILE, {}, {},
      {"sor_red_black", "adi", "multigrid", "multigrid_cg", "nine_point", "absolute"});
  FuzzedDataProvider in(data, size);
  // The robot description's footprint radius (spott_ros::FootprintRadiusFromParameter).
  const double radius = in.ConsumeFloatingPointInRange(0.0, 1.0);
  spott_ros::ParameterReader r(spott_fuzz::BuildParameters(in, vocabulary));
  NodeParameters p;
  ReadParameters(r, p);
  p.planner.window.robot_radius_m = radius;
  for (const auto& v : ValidateParameters(p.planner)) r.Fail(v);
  if (!r.Finish().empty()) return 0;  // the node stops, naming every problem

  ExpectIn("cycle_rate_hz", p.cycle_rate_hz, "[0.01, 1000]");
  spott_fuzz::ExpectRosDuration("the cycle timer's 1 / cycle_rate_hz", 1.0 / p.cycle_rate_hz);
  Expect(p.visualization_every >= 1, "visualization_every < 1 accepted");
  Expect(!p.frame_id.empty() && !p.base_frame.empty(), "an empty frame accepted");
  ExpectIn("navigate/heading_tolerance_rad", p.heading_tolerance_rad, "(0, pi]");
  ExpectIn("navigate/contact_memory_s", p.contact_memory_s, "(0, inf)");
  ExpectIn("navigate/contact_size_m", p.contact_size_m, "(0, 1]");

  const auto& w = p.planner.window;
  ExpectIn("window/window_size_m", w.window_size_m, "(0, inf)");
  ExpectIn("window/resolution_m", w.resolution_m, "(0, inf)");
  Expect(w.resolution_m <= w.window_size_m, "window/resolution_m > window_size_m accepted");
  Expect(w.cells() >= 1 && w.cells() <= 8192, "a window of more than 8192 cells across accepted");
  ExpectIn("window/max_localization_error_m", w.max_localization_error_m, "[0, inf)");
  ExpectIn("window/recentre_margin_m", w.recentre_margin_m, "[0, inf)");
  Expect(w.recentre_margin_m < 0.5 * w.window_size_m,
         "window/recentre_margin_m >= window_size_m / 2 accepted");
  ExpectIn("window/door_thickness_m", w.door_thickness_m, "[0, inf)");
  spott_fuzz::ExpectFinite("the padding (radius + max_localization_error_m)", w.padding_m());

  const auto& f = p.planner.field;
  Expect(f.solver.omega == 0.0 || (f.solver.omega > 0.0 && f.solver.omega < 2.0),
         "solver/omega outside 0 or (0, 2) accepted");
  ExpectIn("solver/tolerance", f.tolerance, "(0, 1)");
  Expect(p.planner.sweeps_per_cycle >= 1 && p.planner.sweeps_per_cycle <= 10000,
         "solver/sweeps_per_cycle outside [1, 10000] accepted");
  Expect(f.norm == ResidualNorm::kRelative, "solver/residual_norm absolute accepted (refused)");

  const auto& s = p.planner.steering;
  ExpectIn("steering/max_linear_mps", s.max_linear_mps, "(0, 5]");
  ExpectIn("steering/max_angular_rps", s.max_angular_rps, "(0, 10]");
  ExpectIn("steering/slowly_fraction", s.slowly_fraction, "(0, 1]");
  ExpectIn("steering/normal_fraction", s.normal_fraction, "(0, 1]");
  ExpectIn("steering/quickly_fraction", s.quickly_fraction, "(0, 1]");
  ExpectIn("steering/heading_gain_per_s", s.heading_gain, "(0, inf)");
  ExpectIn("steering/max_bias_deviation_rad", s.max_bias_deviation_rad, "[0, pi/2)");
  ExpectIn("steering/bias_reverse_fade_rad", s.bias_reverse_fade_rad, "[0, pi/2]");
  ExpectIn("steering/bias_clearance_m", s.bias_clearance_m, "(0, 10]");
  ExpectIn("steering/slow_clearance_m", s.slow_clearance_m, "(0, inf)");
  ExpectIn("steering/goal_slowdown_m", s.goal_slowdown_m, "(0, inf)");
  ExpectIn("steering/escape_radius_m", s.escape_radius_m, "[0, inf)");

  ExpectIn("navigate/goal_tolerance_m", p.planner.goal_tolerance_m, "(0, inf)");
  ExpectIn("navigate/border_goal_half_width_m", p.planner.border_goal_half_width_m, "(0, inf)");
  const auto& n = p.navigate;
  ExpectIn("navigate/planning_timeout_s", n.planning_timeout_s, "(0, 600]");
  Expect(n.unreachable_cycles >= 1, "navigate/unreachable_cycles < 1 accepted");
  ExpectIn("navigate/backoff_distance_m", n.backoff_distance_m, "(0, 2]");
  ExpectIn("navigate/backoff_speed_mps", n.backoff_speed_mps, "(0, 1]");
  ExpectIn("navigate/arrival_stall_s", n.arrival_stall_s, "(0, inf)");
  ExpectIn("navigate/planner_patience_s", n.planner_patience_s, "[0, 600]");
  ExpectIn("navigate/settle_timeout_s", n.settle_timeout_s, "[0, 60]");
  Expect(n.max_settle_drive_ons >= 0, "navigate/max_settle_drive_ons < 0 accepted");
  ExpectIn("navigate/settle_max_offset_m", n.settle_max_offset_m, "(0, 100]");
  ExpectIn("navigate/lost_timeout_s", n.lost_timeout_s, "[0, 600]");

  // The cores the node builds at start: what the reader accepted, they must take.
  try {
    LocalPlanner planner(p.planner);
    NavigateSession session(p.navigate, 0.0);
    ContactMemory contacts(p.contact_memory_s, p.contact_size_m);
  } catch (const std::exception& e) {
    Expect(false, std::string("the node accepted parameters its core refuses: ") + e.what());
  }
  return 0;
}
