// The move_base adapter's parameters from the fuzzer's bytes (tools/fuzz/parameter_fuzz.h): Read
// and the reader's Finish, as main() does (spott_ros::ReadNodeParameters). Whatever the node
// accepts must lie in the documented ranges and make the ros::Duration of its wait for the
// Navigate server.
#include "parameter_fuzz.h"
#include "spott_move_base/parameters.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const auto vocabulary = spott_fuzz::LoadVocabulary(CONFIG_FILE);
  FuzzedDataProvider in(data, size);
  spott_ros::ParameterReader r(spott_fuzz::BuildParameters(in, vocabulary));
  spott_move_base::NodeParameters p;
  spott_move_base::Read(r, p);
  if (!r.Finish().empty()) return 0;  // the node stops, naming every problem
  spott_fuzz::Expect(!p.navigate_action.empty(), "an empty navigate_action accepted");
  spott_fuzz::ExpectIn("server_timeout_s", p.server_timeout_s, "(0, 3600]");
  spott_fuzz::ExpectRosDuration("waitForServer(server_timeout_s)", p.server_timeout_s);
  return 0;
}
