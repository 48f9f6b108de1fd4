// cmd_vel_arbiter's parameters from the fuzzer's bytes (tools/fuzz/parameter_fuzz.h): Read and
// the reader's Finish, as main() does (spott_ros::ReadNodeParameters). Whatever the node accepts
// must lie in the ranges its config file and arbiter.h document, make the timers'
// ros::Durations and the Arbiter the node builds.
#include <set>
#include <stdexcept>

#include "cmd_vel_arbiter/arbiter.h"
#include "cmd_vel_arbiter/ros/parameters.h"
#include "parameter_fuzz.h"

using namespace cmd_vel_arbiter;
using spott_fuzz::Expect;
using spott_fuzz::ExpectIn;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const auto vocabulary = spott_fuzz::LoadVocabulary(CONFIG_FILE);
  FuzzedDataProvider in(data, size);
  spott_ros::ParameterReader r(spott_fuzz::BuildParameters(in, vocabulary));
  NodeParameters p;
  Read(r, p);
  if (!r.Finish().empty()) return 0;  // the node stops, naming every problem

  const auto& a = p.arbiter;
  Expect(!a.sources.empty(), "no source accepted");
  std::set<std::string> names;
  std::set<int> priorities;
  for (const SourceParameters& s : a.sources) {
    Expect(!s.name.empty() && s.name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_") ==
                                  std::string::npos,
           "a source name outside [a-z0-9_]+ accepted: '" + s.name + "'");
    Expect(names.insert(s.name).second, "a source given twice");
    Expect(priorities.insert(s.priority).second, "two sources of one priority accepted");
    ExpectIn("sources/" + s.name + "/timeout_s", s.timeout_s, "(0, 60]");
  }
  ExpectIn("limits/max_linear_mps", a.max_linear_mps, "(0, inf)");
  ExpectIn("limits/max_angular_rps", a.max_angular_rps, "(0, inf)");
  ExpectIn("update_rate_hz", p.update_rate_hz, "[0.01, 1000]");
  if (p.status_rate_hz != 0) ExpectIn("status_rate_hz", p.status_rate_hz, "[0.01, 100]");
  ExpectIn("clearance/max_age_s", p.clearance_max_age_s, "(0, 60]");
  ExpectIn("clearance/deceleration_mps2", p.clearance.deceleration_mps2, "(0, 100]");
  ExpectIn("clearance/latency_s", p.clearance.latency_s, "[0, 5]");
  ExpectIn("clearance/stop_margin_m", p.clearance.stop_margin_m, "[0, 2]");
  ExpectIn("clearance/corridor_margin_m", p.clearance.corridor_margin_m, "[0, 1]");
  ExpectIn("clearance/footprint_radius_m", p.clearance.footprint_radius_m, "[0, 10]");
  spott_fuzz::ExpectRosDuration("the update timer's 1 / update_rate_hz", 1.0 / p.update_rate_hz);
  if (p.status_rate_hz > 0) {
    spott_fuzz::ExpectRosDuration("the status timer's 1 / status_rate_hz", 1.0 / p.status_rate_hz);
  }
  try {
    Arbiter arbiter(a);
  } catch (const std::exception& e) {
    Expect(false, std::string("the node accepted parameters its core refuses: ") + e.what());
  }
  return 0;
}
