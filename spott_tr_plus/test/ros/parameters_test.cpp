// The nodes' parameters read from an XmlRpc tree (what the parameter server gives the reader):
// the regressions of tr_plus_parameters_fuzz.
#include <gtest/gtest.h>

#include "spott_tr_plus/ros/parameters.h"

namespace spott_tr_plus::controller {
namespace {

using Strings = std::vector<std::string>;

Strings ReadTree(const XmlRpc::XmlRpcValue& values, NodeParameters* p) {
  spott_ros::ParameterReader r(values);
  ReadParameters(r, *p);
  p->controller.robot_radius_m = 0.2285;  // from the robot description
  for (const auto& v : ValidateParameters(p->controller)) r.Fail(v);
  return r.Finish();
}

XmlRpc::XmlRpcValue WithProgram() {
  XmlRpc::XmlRpcValue v;
  v["program_file"] = "spott_navigation.tr";
  return v;
}

TEST(ControllerParameters, AProgramFileIsEnough) {
  NodeParameters p;
  EXPECT_EQ(ReadTree(WithProgram(), &p), Strings{});
}

// Found by tr_plus_parameters_fuzz: tick_rate_hz 1e-300 was accepted, and the tick timer's
// ros::Duration(1 / tick_rate_hz) throws beyond 2^31 s.
TEST(ControllerParameters, ATickRateWhosePeriodNoDurationHoldsIsRefused) {
  for (double hz : {1e-300, 0.0099}) {
    XmlRpc::XmlRpcValue v = WithProgram();
    v["tick_rate_hz"] = hz;
    NodeParameters p;
    const Strings e = ReadTree(v, &p);
    ASSERT_EQ(e.size(), 1u) << hz;
    EXPECT_EQ(e[0].rfind("~tick_rate_hz must be in [0.01, 200]", 0), 0u) << e[0];
  }
}

}  // namespace
}  // namespace spott_tr_plus::controller
