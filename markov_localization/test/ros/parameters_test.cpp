// The node's parameters read from an XmlRpc tree (what the parameter server gives the reader):
// the regressions of markov_localization_parameters_fuzz.
#include <gtest/gtest.h>

#include "markov_localization/ros/parameters.h"

namespace markov_localization {
namespace {

std::vector<std::string> Read(const XmlRpc::XmlRpcValue& values, NodeParameters* p) {
  spott_ros::ParameterReader r(values);
  ReadParameters(r, *p);
  return r.Finish();
}

TEST(Parameters, TheShippedDefaultsAreAccepted) {
  NodeParameters p;
  EXPECT_TRUE(Read(XmlRpc::XmlRpcValue(), &p).empty());
}

// Found by markov_localization_parameters_fuzz: map/resolution_m 1e-300 was accepted, and the
// map model counts a building's cells in an int (undefined far beyond it).
TEST(Parameters, AMapCellTooFineForAnyBuildingIsRefused) {
  for (double res : {1e-300, 1e-6, 0.009}) {
    XmlRpc::XmlRpcValue v;
    v["map"]["resolution_m"] = res;
    NodeParameters p;
    const auto errors = Read(v, &p);
    ASSERT_EQ(errors.size(), 1u) << res;
    EXPECT_NE(errors[0].find("~map/resolution_m"), std::string::npos) << errors[0];
  }
  XmlRpc::XmlRpcValue v;
  v["map"]["resolution_m"] = 0.01;
  NodeParameters p;
  EXPECT_TRUE(Read(v, &p).empty());
  EXPECT_EQ(p.map.resolution_m, 0.01);
}

}  // namespace
}  // namespace markov_localization
