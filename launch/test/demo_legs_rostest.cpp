// Every leg of a world's demo on the whole stack (see demo_legs.test), judged on the
// simulator's ground truth, with the robot the world was built for.
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <spott_msgs/PotentialFieldStatus.h>

#include "demo_navigation.h"
#include "spott_map/world_loader.h"
#include "spott_ros/robot_geometry.h"
#include "spott_ros/testing/node_process.h"

namespace {

TEST(DemoLegs, EveryLegIsReachedOnGroundTruthWithoutContactAndWithTheRobotsOwnPadding) {
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  std::string world_file;
  // The world's demo legs: task commands for the TR+ controller on /task (`tasks`), or places
  // sent with Navigate (`goals`) when a world's demo has no tasks.
  std::vector<std::string> goals, tasks;
  double leg_timeout_s = 240.0, tolerance_m = 0.25;
  ASSERT_TRUE(pnh.getParam("world_file", world_file));
  pnh.getParam("tasks", tasks);
  pnh.getParam("goals", goals);
  ASSERT_TRUE(!tasks.empty() || !goals.empty()) << "the demo config has neither tasks nor goals";
  pnh.getParam("leg_timeout_s", leg_timeout_s);
  pnh.getParam("goal_tolerance_m", tolerance_m);
  const spott_map::WorldLoadResult world = spott_map::LoadWorldFile(world_file);
  ASSERT_TRUE(world.ok()) << spott_map::FormatErrors(world.errors);

  // The planner pads for this robot: its radius from the robot description plus the
  // localization error.
  std::string error;
  const auto radius =
      spott_ros::FootprintRadiusFromParameter(nh, "robot_description", "base_link", &error);
  ASSERT_TRUE(radius) << error;
  spott_ros::testing::Latest<spott_msgs::PotentialFieldStatus> status(nh,
                                                                      "harmonic_planner/status");
  ASSERT_TRUE(status.WaitFor([](const auto& s) { return s.robot_radius > 0; }, 60.0));
  EXPECT_DOUBLE_EQ(status.msg()->robot_radius, *radius);
  double error_m = 0.0;
  ASSERT_TRUE(nh.getParam("/harmonic_planner/window/max_localization_error_m", error_m));
  EXPECT_NEAR(status.msg()->padding, *radius + error_m, 1e-9);

  const bool by_task = !tasks.empty();
  const spott_launch::NavigationReport report =
      by_task ? spott_launch::RunTasks(nh, *world.world, tasks, leg_timeout_s,
                                       /*connect_timeout_s=*/60.0, tolerance_m)
              : spott_launch::RunNavigation(nh, *world.world, goals, leg_timeout_s,
                                            /*connect_timeout_s=*/60.0, tolerance_m);
  ASSERT_TRUE(report.ran) << report.skipped;
  ASSERT_EQ(report.legs.size(), by_task ? tasks.size() : goals.size());
  for (const spott_launch::NavigationLeg& leg : report.legs) {
    SCOPED_TRACE(by_task ? leg.task : leg.goal);
    // A task leg is reached in its goal region or within the tolerance of the controller's goal
    // point (RunTasks); a Navigate leg within the tolerance of the place.
    EXPECT_TRUE(leg.reached) << leg.outcome;
    if (!by_task) {
      EXPECT_LE(leg.final_error_m, tolerance_m);
    }
    EXPECT_EQ(leg.bumper_hits, 0);
    EXPECT_GT(leg.min_wall_distance_m, *radius) << "the body touched a wall or an object";
  }
  std::cout << spott_launch::FormatNavigation(report) << std::flush;
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "demo_legs_rostest");
  return RUN_ALL_TESTS();
}
