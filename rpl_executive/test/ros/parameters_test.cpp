// The node's parameters read from an XmlRpc tree (what the parameter server gives the reader):
// the regressions of rpl_executive_parameters_fuzz.
#include <gtest/gtest.h>

#include "parameters.h"
#include "spott_ros/parameter_reader.h"

namespace rpl_executive::ros_parameters {
namespace {

using Strings = std::vector<std::string>;

Strings ReadTree(const XmlRpc::XmlRpcValue& values, NodeParameters* p) {
  spott_ros::ParameterReader r(values);
  Read(r, *p);
  return r.Finish();
}

TEST(NodeParameters, NothingSetKeepsTheDefaults) {
  NodeParameters p;
  EXPECT_EQ(ReadTree(XmlRpc::XmlRpcValue(), &p), Strings{});
}

// Found by rpl_executive_parameters_fuzz: state_rate_hz 1e-300 was accepted, and the state
// timer's ros::Duration(1 / state_rate_hz) throws beyond 2^31 s.
TEST(NodeParameters, AStateRateWhosePeriodNoDurationHoldsIsRefused) {
  for (double hz : {1e-300, 0.0099}) {
    XmlRpc::XmlRpcValue v;
    v["state_rate_hz"] = hz;
    NodeParameters p;
    const Strings e = ReadTree(v, &p);
    ASSERT_EQ(e.size(), 1u) << hz;
    EXPECT_EQ(e[0].rfind("~state_rate_hz: must be 0 (on change only) or in [0.01, 100]", 0), 0u)
        << e[0];
  }
  XmlRpc::XmlRpcValue off;
  off["state_rate_hz"] = 0.0;
  NodeParameters p;
  EXPECT_EQ(ReadTree(off, &p), Strings{});
}

// Found by rpl_executive_parameters_fuzz: see PathSmoothing.ASampleStepTooFineToCountIsRefused.
TEST(NodeParameters, APilotSampleStepTooFineIsRefusedByItsKey) {
  XmlRpc::XmlRpcValue v;
  v["nc"]["pilot"]["sample_step_m"] = 1e-300;
  NodeParameters p;
  const Strings e = ReadTree(v, &p);
  ASSERT_EQ(e.size(), 1u);
  EXPECT_NE(e[0].find("sample_step_m"), std::string::npos) << e[0];
}

}  // namespace
}  // namespace rpl_executive::ros_parameters
