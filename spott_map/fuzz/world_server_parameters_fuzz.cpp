// world_server's parameters from the fuzzer's bytes (tools/fuzz/parameter_fuzz.h): ReadParameters
// and the reader's Finish, as main() does (spott_ros::ReadNodeParameters). Whatever the node
// accepts must lie in the ranges its config file documents. (The published map's size is capped
// by the node itself: a resolution too fine for the world is coarsened.)
#include "parameter_fuzz.h"
#include "spott_map/ros/world_server_parameters.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const auto vocabulary = spott_fuzz::LoadVocabulary(
      CONFIG_FILE, {{"world_file", "spott_worlds/worlds/cim_office.yaml"}});
  FuzzedDataProvider in(data, size);
  spott_ros::ParameterReader r(spott_fuzz::BuildParameters(in, vocabulary));
  spott_map::WorldServerParameters p;
  spott_map::ReadParameters(r, p);
  if (!r.Finish().empty()) return 0;  // the node stops, naming every problem
  spott_fuzz::Expect(!p.world_file.empty() && !p.frame_id.empty(), "an empty name accepted");
  spott_fuzz::ExpectIn("map_resolution_m", p.map_resolution_m, "(0, 10]");
  spott_fuzz::ExpectIn("feature_tolerance_m", p.feature_tolerance_m, "(0, inf)");
  return 0;
}
