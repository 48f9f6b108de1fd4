// End to end on hilare_room: the global planner, the harmonic planner and the simulator together
// bring the robot to three places without touching anything, judged on the ground truth; the
// last leg goes around the room's east wall, out through the door and up the corridor.
#include <gtest/gtest.h>
#include <ros/ros.h>

#include "demo_navigation.h"
#include "spott_map/world_loader.h"

namespace {

TEST(Navigation, TheStackDrivesTheRobotToPlacesWithoutContact) {
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  std::string world_file;
  ASSERT_TRUE(pnh.getParam("world_file", world_file));
  const spott_map::WorldLoadResult world = spott_map::LoadWorldFile(world_file);
  ASSERT_TRUE(world.ok()) << spott_map::FormatErrors(world.errors);
  const spott_launch::NavigationReport report = spott_launch::RunNavigation(
      nh, *world.world, {"wall_follow_start", "zone_exit", "corridor_north"},
      /*leg_timeout_s=*/120.0,
      /*connect_timeout_s=*/30.0, /*goal_tolerance_m=*/0.25);
  ASSERT_TRUE(report.ran) << report.skipped;
  ASSERT_EQ(report.legs.size(), 3u);
  // As the crow flies: start (0.8, 5.2) -> wall_follow_start (6.0, 2.5) -> zone_exit (3.6, 3.2);
  // to corridor_north (9.25, 7.0) the wall forces the way through the door at (8, 1.2): at
  // least |(3.6, 3.2) - (8, 1.2)| + |(8, 1.2) - (9.25, 7.0)| = 4.83 + 5.93 m.
  const double shortest[3] = {5.86, 2.50, 10.76};
  for (std::size_t i = 0; i < 3; ++i) {
    const spott_launch::NavigationLeg& leg = report.legs[i];
    SCOPED_TRACE(leg.goal);
    EXPECT_TRUE(leg.reached) << leg.outcome;
    EXPECT_LT(leg.final_error_m, 0.25);  // the asked tolerance, on the ground truth
    EXPECT_EQ(leg.bumper_hits, 0);
    EXPECT_GT(leg.min_wall_distance_m, 0.2285);  // the Nomad 200's radius: no contact
    EXPECT_GT(leg.path_length_m, shortest[i] - 0.3);
    // Harmonic paths keep clear of walls and round corners: longer than the shortest, not much.
    EXPECT_LT(leg.path_length_m, 1.75 * shortest[i]);
  }
  EXPECT_EQ(report.legs[0].global_path, "room");
  EXPECT_EQ(report.legs[2].global_path, "room -> door_room -> corridor");
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "navigation_rostest");
  return RUN_ALL_TESTS();
}
