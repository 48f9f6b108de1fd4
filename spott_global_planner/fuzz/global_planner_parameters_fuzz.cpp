// The global planner node's parameters from the fuzzer's bytes (tools/fuzz/parameter_fuzz.h):
// ReadParameters, the passage padding from the robot's radius, ValidateCore and the reader's
// Finish, as main() does. Whatever the node accepts must lie in the ranges its config file and
// headers document, make the timer's ros::Duration, and place a window and analyse a room's
// passages (what the node does with every graph) without undefined behaviour.
#include <cmath>
#include <stdexcept>

#include "parameter_fuzz.h"
#include "spott_global_planner/passage_blocking.h"
#include "spott_global_planner/planning_session.h"
#include "spott_global_planner/ros/parameters.h"
#include "spott_global_planner/window_tracker.h"

using namespace spott_global_planner;
using spott_fuzz::Expect;
using spott_fuzz::ExpectIn;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const auto vocabulary = spott_fuzz::LoadVocabulary(CONFIG_FILE, {}, {}, {"astar"});
  FuzzedDataProvider in(data, size);
  const double radius = in.ConsumeFloatingPointInRange(0.0, 1.0);  // the robot description's
  spott_ros::ParameterReader r(spott_fuzz::BuildParameters(in, vocabulary));
  ros_parameters::NodeParameters p;
  ros_parameters::ReadParameters(r, p);
  p.core.passage.padding_m = radius + p.max_localization_error_m;
  ros_parameters::ValidateCore(r, p);
  if (!r.Finish().empty()) return 0;  // the node stops, naming every problem

  Expect(!p.frame_id.empty() && !p.robot_frame.empty(), "an empty frame accepted");
  ExpectIn("update_rate_hz", p.update_rate_hz, "[0.01, 100]");
  spott_fuzz::ExpectRosDuration("the update timer's 1 / update_rate_hz", 1.0 / p.update_rate_hz);
  ExpectIn("passage/max_localization_error_m", p.max_localization_error_m, "[0, inf)");
  const auto& w = p.core.window;
  ExpectIn("window/window_size_m", w.window_size_m, "(0, inf)");
  ExpectIn("window/resolution_m", w.resolution_m, "(0, inf)");
  Expect(w.resolution_m <= w.window_size_m, "window/resolution_m > window_size_m accepted");
  ExpectIn("window/recentre_margin_m", w.recentre_margin_m, "[0, inf)");
  Expect(w.recentre_margin_m < 0.5 * w.window_size_m,
         "window/recentre_margin_m >= window_size_m / 2 accepted");
  ExpectIn("window/max_window_size_m", w.max_window_size_m, "(0, inf)");
  Expect(w.max_window_size_m >= w.window_size_m, "window/max_window_size_m < window_size_m");
  // At most 8192 cells across, the local planner's limit (WindowAround counts them in an int).
  Expect(w.max_window_size_m / w.resolution_m <= 8192.5,
         "a window of more than 8192 cells across accepted (max_window_size_m / resolution_m)");
  const auto& s = p.core.passage;
  ExpectIn("passage/resolution_m", s.resolution_m, "(0, inf)");
  ExpectIn("the passage padding", s.padding_m, "[0, inf)");
  ExpectIn("passage/door_depth_m", s.door_depth_m, "(0, inf)");
  Expect(s.max_cells >= 1, "passage/max_cells < 1 accepted");

  try {
    PlanningSession session(p.core);  // what the node builds at start
    WindowTracker tracker(w);
    tracker.Update(spott_map::Vec2(1.0, 1.0), nullptr);
    // A 2 m x 2 m room (no doors, no features), as every graph's rooms are analysed; only when
    // that is cheap (or refused for its size), to keep the fuzzer fast.
    const double cells = std::pow(2.0 / s.resolution_m + 3.0, 2.0);
    if (cells <= 2e5 || cells > s.max_cells) {
      spott_map::Room room;
      room.id = "r";
      room.polygon = {{0.0, 0.0}, {2.0, 0.0}, {2.0, 2.0}, {0.0, 2.0}};
      AnalysePassages(room, {}, {}, s);
    }
  } catch (const std::exception& e) {
    Expect(false, std::string("the node accepted parameters its core refuses: ") + e.what());
  }
  return 0;
}
