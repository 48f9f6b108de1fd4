// The node's parameter checks, on XmlRpc structs as the parameter server hands them over.
#include "spott_global_planner/ros/parameters.h"

#include <gtest/gtest.h>

namespace spott_global_planner::ros_parameters {
namespace {

using XmlRpc::XmlRpcValue;
using Strings = std::vector<std::string>;

Strings Read(const XmlRpcValue& v, NodeParameters& p) {
  spott_ros::ParameterReader r(v);
  ReadParameters(r, p);
  p.core.passage.padding_m = 0.2 + p.max_localization_error_m;
  ValidateCore(r, p);
  return r.Finish();
}

TEST(NodeParameters, NothingSetKeepsTheDefaults) {
  NodeParameters p;
  EXPECT_TRUE(Read(XmlRpcValue{}, p).empty());
  EXPECT_EQ(p.frame_id, "map");
  EXPECT_DOUBLE_EQ(p.core.window.window_size_m, 7.0);
}

TEST(NodeParameters, NestedValuesAreRead) {
  XmlRpcValue v;
  v["algorithm"] = "astar";
  v["update_rate_hz"] = 10;  // an int is a number
  v["window"]["window_size_m"] = 9.0;
  v["window"]["fit_node"] = true;
  v["passage"]["max_cells"] = 1000;
  NodeParameters p;
  EXPECT_EQ(Read(v, p), Strings{});
  EXPECT_EQ(p.core.algorithm, SearchAlgorithm::kAStar);
  EXPECT_DOUBLE_EQ(p.update_rate_hz, 10.0);
  EXPECT_DOUBLE_EQ(p.core.window.window_size_m, 9.0);
  EXPECT_TRUE(p.core.window.fit_node);
  EXPECT_EQ(p.core.passage.max_cells, 1000);
}

// Found by global_planner_parameters_fuzz: 1e-300 Hz was accepted, and the update timer's
// ros::Duration(1 / update_rate_hz) throws beyond 2^31 s.
TEST(NodeParameters, ARateWhosePeriodNoDurationHoldsIsRefused) {
  for (double hz : {1e-300, 4.9e-324, 0.0099}) {
    XmlRpcValue v;
    v["update_rate_hz"] = hz;
    NodeParameters p;
    const Strings e = Read(v, p);
    ASSERT_EQ(e.size(), 1u) << hz;
    EXPECT_EQ(e[0].rfind("~update_rate_hz must be in [0.01, 100]", 0), 0u) << e[0];
  }
  XmlRpcValue v;
  v["update_rate_hz"] = 0.01;
  NodeParameters p;
  EXPECT_EQ(Read(v, p), Strings{});
}

// Found by global_planner_parameters_fuzz: a 7 m window of 1e-300 m cells was accepted, and
// WindowAround rounds the cells into an int (std::lround beyond a long: an unspecified window).
TEST(NodeParameters, AWindowOfMoreCellsThanTheLocalPlannerTakesIsRefused) {
  XmlRpcValue v;
  v["window"]["resolution_m"] = 1e-300;
  NodeParameters p;
  const Strings e = Read(v, p);
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].rfind("~window/max_window_size_m must be at most 8192 cells", 0), 0u) << e[0];
  XmlRpcValue fine;
  fine["window"]["resolution_m"] = 30.0 / 8192;  // max_window_size_m 30 m: 8192 cells
  EXPECT_EQ(Read(fine, p), Strings{});
}

TEST(NodeParameters, EveryViolationNamesItsParameter) {
  XmlRpcValue v;
  v["algorithm"] = "bfs";
  v["update_rate_hz"] = 0.0;
  v["frame_id"] = 3;
  v["window"]["window_size_m"] = -1.0;
  v["window"]["fit_node"] = "yes";
  v["window"]["size"] = 5.0;  // a typo of window_size_m
  v["passage"]["max_localization_error_m"] = -0.5;
  NodeParameters p;
  EXPECT_EQ(Read(v, p), (Strings{"~frame_id must be a string, not an integer",
                                 "~algorithm must be dijkstra or astar (got 'bfs')",
                                 "~window/fit_node must be true or false, not a string",
                                 "~update_rate_hz must be in [0.01, 100] (got 0)",
                                 "~passage/max_localization_error_m must be >= 0 (got -0.5)",
                                 "~window/window_size_m must be > 0 (got -1)",
                                 "~window/size is not a parameter of this node"}));
}

}  // namespace
}  // namespace spott_global_planner::ros_parameters
