// rpl_executive refuses a parameter it does not know, and a value out of range, naming each,
// and exits with status 1 (spott_ros::ParameterReader); with its own defaults it starts.
#include <gtest/gtest.h>
#include <ros/ros.h>

#include "spott_ros/testing/node_process.h"

namespace {

using spott_ros::testing::RunNode;

TEST(RplExecutiveParameters, AnUnknownKeyStopsTheNodeByName) {
  const auto run =
      RunNode(NODE_EXE, "__name:=probe_unknown _bad_key:=1 _rpl/navigation/goal_tolerance_mm:=0.3");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("~bad_key"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("~rpl/navigation/goal_tolerance_mm"), std::string::npos) << run.output;
}

TEST(RplExecutiveParameters, ValuesOutOfRangeAreAllNamedAtOnce) {
  const auto run = RunNode(NODE_EXE,
                           "__name:=probe_range _rpl/navigation/goal_tolerance_m:=-1 "
                           "_nc/control_rate_hz:=0 _nc/pilot/max_speed_mps:=-0.4");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("goal_tolerance_m"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("control_rate_hz"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("max_speed_mps"), std::string::npos) << run.output;
}

TEST(RplExecutiveParameters, AValueOfTheWrongTypeIsNamed) {
  const auto run = RunNode(NODE_EXE, "__name:=probe_type _nc/control_rate_hz:=fast");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("nc/control_rate_hz"), std::string::npos) << run.output;
}

TEST(RplExecutiveParameters, AnUnknownPoseSourceIsNamed) {
  const auto run = RunNode(NODE_EXE, "__name:=probe_source _nc/pose_source:=gps");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("nc/pose_source: must be odometry or localization, got 'gps'"),
            std::string::npos)
      << run.output;
}

TEST(RplExecutiveParameters, WithItsDefaultsTheNodeRunsUntilStopped) {
  // No key set: the defaults are valid; the node keeps running (killed by the timeout: -1).
  const auto run = RunNode(NODE_EXE, "__name:=probe_defaults", 5.0);
  EXPECT_EQ(run.exit_code, -1) << run.output;
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "rpl_executive_parameters_rostest");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
