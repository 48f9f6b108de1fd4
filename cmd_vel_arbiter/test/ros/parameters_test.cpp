// The node's parameters read from an XmlRpc tree (what the parameter server gives the reader):
// the regressions of cmd_vel_arbiter_parameters_fuzz.
#include <gtest/gtest.h>

#include "cmd_vel_arbiter/ros/parameters.h"

namespace cmd_vel_arbiter {
namespace {

using Strings = std::vector<std::string>;

XmlRpc::XmlRpcValue OneSource() {
  XmlRpc::XmlRpcValue v;
  v["sources"]["planner"]["priority"] = 10;
  v["sources"]["planner"]["timeout_s"] = 0.5;
  return v;
}

Strings ReadTree(const XmlRpc::XmlRpcValue& values, NodeParameters* p) {
  spott_ros::ParameterReader r(values);
  Read(r, *p);
  return r.Finish();
}

TEST(NodeParameters, OneSourceIsEnough) {
  NodeParameters p;
  EXPECT_EQ(ReadTree(OneSource(), &p), Strings{});
  ASSERT_EQ(p.arbiter.sources.size(), 1u);
  EXPECT_EQ(p.arbiter.sources[0].name, "planner");
}

// Found by cmd_vel_arbiter_parameters_fuzz: update_rate_hz 5e-324 (and status_rate_hz 1e-300)
// were accepted, and the timers' ros::Duration(1 / rate) throws beyond 2^31 s: the node died.
TEST(NodeParameters, RatesWhosePeriodNoDurationHoldsAreRefused) {
  for (const char* key : {"update_rate_hz", "status_rate_hz"}) {
    for (double hz : {5e-324, 1e-300, 0.0099}) {
      XmlRpc::XmlRpcValue v = OneSource();
      v[key] = hz;
      NodeParameters p;
      const Strings e = ReadTree(v, &p);
      ASSERT_EQ(e.size(), 1u) << key << " " << hz;
      EXPECT_EQ(e[0].rfind(std::string("~") + key + " must be ", 0), 0u) << e[0];
    }
  }
  XmlRpc::XmlRpcValue v = OneSource();
  v["status_rate_hz"] = 0.0;  // on change only
  v["update_rate_hz"] = 0.01;
  NodeParameters p;
  EXPECT_EQ(ReadTree(v, &p), Strings{});
}

TEST(NodeParameters, ClearanceTopicsAreAListOfDistinctNames) {
  NodeParameters p;
  EXPECT_EQ(ReadTree(OneSource(), &p), Strings{});
  EXPECT_EQ(p.clearance_topics, (Strings{"sonar", "infrared"}));
  EXPECT_EQ(p.clearance_scan_topics, (Strings{"scan"}));
  const auto with = [](const Strings& rings, const Strings& scans) {
    XmlRpc::XmlRpcValue v = OneSource();
    v["clearance"]["topics"].setSize(static_cast<int>(rings.size()));
    for (std::size_t i = 0; i < rings.size(); ++i) v["clearance"]["topics"][i] = rings[i];
    v["clearance"]["scan_topics"].setSize(static_cast<int>(scans.size()));
    for (std::size_t i = 0; i < scans.size(); ++i) v["clearance"]["scan_topics"][i] = scans[i];
    NodeParameters q;
    return ReadTree(v, &q);
  };
  for (const Strings& bad : {Strings{"sonar", ""}, Strings{"sonar", "sonar"}, Strings{"scan"}}) {
    const Strings e = with(bad, {"scan"});
    ASSERT_EQ(e.size(), 1u) << bad.back();
    EXPECT_NE(e[0].find("clearance/"), std::string::npos) << e[0];
    EXPECT_NE(e[0].find(bad.back().empty() ? "empty" : "twice"), std::string::npos) << e[0];
  }
  EXPECT_EQ(with({}, {"scan"}), Strings{});   // a laser alone caps
  EXPECT_EQ(with({"sonar"}, {}), Strings{});  // a ring alone too
  const Strings none = with({}, {});          // nothing to cap by while enabled
  ASSERT_EQ(none.size(), 1u);
  EXPECT_NE(none[0].find("at least one topic"), std::string::npos) << none[0];
  // The old single key is refused by name (unknown keys stop the node).
  XmlRpc::XmlRpcValue v = OneSource();
  v["clearance"]["topic"] = "sonar";
  NodeParameters q;
  const Strings e = ReadTree(v, &q);
  ASSERT_EQ(e.size(), 1u);
  EXPECT_NE(e[0].find("clearance/topic"), std::string::npos) << e[0];
}

}  // namespace
}  // namespace cmd_vel_arbiter
