// The node's parameters read from an XmlRpc tree (what the parameter server gives the reader):
// the regressions of move_base_parameters_fuzz.
#include <gtest/gtest.h>

#include "spott_move_base/parameters.h"

namespace spott_move_base {
namespace {

std::vector<std::string> ReadTree(const XmlRpc::XmlRpcValue& values, NodeParameters* p) {
  spott_ros::ParameterReader r(values);
  Read(r, *p);
  return r.Finish();
}

// Found by move_base_parameters_fuzz: server_timeout_s 1.4e20 was accepted, and every goal's
// waitForServer(ros::Duration(server_timeout_s)) throws beyond 2^31 s: the node died on a goal.
TEST(NodeParameters, AServerTimeoutNoDurationHoldsIsRefused) {
  for (double s : {1.3835058055282164e20, 3600.5}) {
    XmlRpc::XmlRpcValue v;
    v["server_timeout_s"] = s;
    NodeParameters p;
    const auto e = ReadTree(v, &p);
    ASSERT_EQ(e.size(), 1u) << s;
    EXPECT_EQ(e[0].rfind("~server_timeout_s must be in (0, 3600]", 0), 0u) << e[0];
  }
  XmlRpc::XmlRpcValue v;
  v["server_timeout_s"] = 3600;
  NodeParameters p;
  EXPECT_TRUE(ReadTree(v, &p).empty());
  EXPECT_EQ(p.server_timeout_s, 3600.0);
}

}  // namespace
}  // namespace spott_move_base
