// sensed_map_localization_node's parameters from the fuzzer's bytes (tools/fuzz/parameter_fuzz.h):
// ReadParameters and the reader's Finish, as the node does. Whatever the node accepts must lie in
// the ranges its config file and sensed_map_tracker.h document, and make a SensedMapTracker.
#include <cmath>

#include "markov_localization/ros/sensed_map_parameters.h"
#include "parameter_fuzz.h"
#include "spott_ros/parameter_reader.h"

using namespace markov_localization;
using spott_fuzz::Expect;
using spott_fuzz::ExpectIn;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const auto vocabulary = spott_fuzz::LoadVocabulary(
      CONFIG_FILE, {{"world_file", "spott_worlds/worlds/cim_office.yaml"}},
      {"initial_pose", "last_map_to_odom"}, {"1 2 0.5", "0 0 0", "1 nan 0", "1e400 0 0"});
  FuzzedDataProvider in(data, size);
  spott_ros::ParameterReader r(spott_fuzz::BuildParameters(in, vocabulary));
  SensedMapNodeParameters p;
  ReadParameters(r, p);
  if (!r.Finish().empty()) return 0;  // the node stops, naming every problem

  ExpectIn("transform_tolerance_s", p.transform_tolerance_s, "[0, 1]");
  spott_fuzz::ExpectRosDuration("transform_tolerance_s", p.transform_tolerance_s);
  ExpectIn("odometry_max_lag_s", p.odometry_max_lag_s, "(0, 5]");
  Expect(!p.map_frame.empty() && !p.odom_frame.empty() && p.map_frame != p.odom_frame,
         "map_frame and odom_frame not two names");
  Expect(!p.ring_topic.empty() && !p.features_topic.empty() && !p.profile_topic.empty(),
         "an empty topic name accepted");
  Expect(p.profile_min_height_m < p.profile_max_height_m, "an empty profile height band accepted");
  for (const auto* pose : {&p.initial_pose, &p.last_map_to_odom}) {
    if (*pose) {
      spott_fuzz::ExpectFinite("a pose's x", (*pose)->x);
      spott_fuzz::ExpectFinite("a pose's y", (*pose)->y);
      spott_fuzz::ExpectFinite("a pose's yaw", (*pose)->yaw);
    }
  }
  const SensedMapTrackerParameters& t = p.tracker;
  ExpectIn("period_s", t.period_s, "(0, inf)");
  ExpectIn("window_s", t.window_s, "(0, inf)");
  ExpectIn("max_range_m", t.max_range_m, "(0, inf)");
  ExpectIn("gate_m", t.gate_m, "(0, inf)");
  ExpectIn("huber_m", t.huber_m, "(0, inf)");
  ExpectIn("max_correction_deg (rad)", t.max_correction_rad, "(0, inf)");
  Expect(t.iterations >= 1 && t.iterations <= 100, "iterations outside [1, 100]");
  Expect(t.min_echoes >= 3, "min_echoes < 3");
  const WallLatticeParameters& w = t.wall_lattice;
  spott_fuzz::ExpectFinite("wall_lattice/axis_deg (rad)", w.axis_rad);
  Expect(w.gate_rad > 0.0 && w.gate_rad < M_PI / 4.0, "wall_lattice/gate_deg outside (0, 45)");
  ExpectIn("wall_lattice/agree_deg (rad)", w.agree_rad, "(0, inf)");
  ExpectIn("wall_lattice/min_length_m", w.min_length_m, "(0, inf)");
  ExpectIn("wall_lattice/max_rms_m", w.max_rms_m, "(0, inf)");
  ExpectIn("wall_lattice/break_m", w.break_m, "(0, inf)");
  Expect(w.min_points >= 3, "wall_lattice/min_points < 3");
  SensedMapTracker tracker(t, spott_map::Pose2{});  // throws (and the fuzzer stops) if refused
  return 0;
}
