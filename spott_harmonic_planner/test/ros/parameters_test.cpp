// The node's parameters read from an XmlRpc tree (what the parameter server gives the reader), as
// main() reads them: the regressions of harmonic_planner_parameters_fuzz.
#include <gtest/gtest.h>

#include "spott_harmonic_planner/ros/parameters.h"

namespace spott_harmonic_planner {
namespace {

using Strings = std::vector<std::string>;

Strings Read(const XmlRpc::XmlRpcValue& values, NodeParameters* p) {
  spott_ros::ParameterReader r(values);
  ReadParameters(r, *p);
  p->planner.window.robot_radius_m = 0.25;  // from the robot description
  for (const auto& v : ValidateParameters(p->planner)) r.Fail(v);
  return r.Finish();
}

TEST(NodeParameters, NothingSetKeepsTheDefaults) {
  NodeParameters p;
  EXPECT_EQ(Read(XmlRpc::XmlRpcValue(), &p), Strings{});
}

// Found by harmonic_planner_parameters_fuzz: 5e-324 Hz was accepted, and the cycle timer's
// ros::Duration(1 / cycle_rate_hz) throws beyond 2^31 s.
TEST(NodeParameters, ACycleRateWhosePeriodNoDurationHoldsIsRefused) {
  for (double hz : {5e-324, 1e-300, 0.0099}) {
    XmlRpc::XmlRpcValue v;
    v["cycle_rate_hz"] = hz;
    NodeParameters p;
    const Strings e = Read(v, &p);
    ASSERT_EQ(e.size(), 1u) << hz;
    EXPECT_EQ(e[0].rfind("~cycle_rate_hz must be in [0.01, 1000]", 0), 0u) << e[0];
  }
}

// Found by harmonic_planner_parameters_fuzz: window/resolution_m 2e-322 m was accepted (the
// 8192-cell limit was checked on the cell count after it wrapped around an int).
TEST(NodeParameters, AWindowOfTooManyCellsIsRefused) {
  XmlRpc::XmlRpcValue v;
  v["window"]["resolution_m"] = 2e-322;
  NodeParameters p;
  const Strings e = Read(v, &p);
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].rfind("~window/window_size_m must be at most 8192 cells", 0), 0u) << e[0];
}

}  // namespace
}  // namespace spott_harmonic_planner
