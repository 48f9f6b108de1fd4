// tr_plus_controller's parameters are read through spott_ros's reader: an unknown key (a typo)
// stops the node, naming the key; a value out of range is named with its section.
#include <gtest/gtest.h>
#include <ros/package.h>
#include <ros/ros.h>

#include "spott_ros/testing/node_process.h"

namespace {

std::string ProgramFile() {
  std::string path;
  ros::NodeHandle("~").getParam("program_file", path);
  return path;
}

TEST(TrPlusControllerParameters, AnUnknownKeyStopsTheNodeNamingIt) {
  const auto run = spott_ros::testing::RunNode(
      EXECUTABLE, "_program_file:=" + ProgramFile() + " _mapping/cel_m:=0.1 __name:=probe_unknown");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("mapping/cel_m"), std::string::npos) << run.output;
}

TEST(TrPlusControllerParameters, AValueOutOfRangeIsNamedWithItsSection) {
  const auto run = spott_ros::testing::RunNode(
      EXECUTABLE,
      "_program_file:=" + ProgramFile() + " _teleop/stop_distance_m:=-1 __name:=probe_range");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("teleop/stop_distance_m"), std::string::npos) << run.output;
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "tr_plus_controller_params_rostest");
  return RUN_ALL_TESTS();
}
