// The main demo on cim_office against the real world_server: the report's facts are the
// world's, and closing doors through the service changes what is reachable.
#include <algorithm>

#include <gtest/gtest.h>
#include <ros/ros.h>

#include "demo_report.h"

namespace {

bool Contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

TEST(Demo, ReportsTheCimOfficeWorldAndDoorClosures) {
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  std::string world_file;
  ASSERT_TRUE(pnh.getParam("world_file", world_file));
  spott_launch::DemoOptions options;
  options.world_file = world_file;
  options.doors_to_close = {"d_lab_w", "d_lab_e", "hall_join"};
  const auto r = spott_launch::RunDemo(nh, options);
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_EQ(r.world, "cim_office");
  EXPECT_EQ(r.rooms, 12);
  EXPECT_EQ(r.hallways, 2);
  EXPECT_EQ(r.doors_closed, 2);  // d_102 and d_202_lab
  EXPECT_EQ(r.openings, 1);
  EXPECT_EQ(r.start_room, "hall_w");
  // office_102's only door is closed; everything else is reachable from the hallway.
  EXPECT_EQ(r.reachable.size(), 11u);
  ASSERT_EQ(r.unreachable.size(), 1u);
  EXPECT_EQ(r.unreachable[0], "office_102 (behind closed d_102)");
  ASSERT_EQ(r.door_experiments.size(), 3u);
  // Closing the lab's west door leaves its east door.
  EXPECT_TRUE(r.door_experiments[0].accepted);
  EXPECT_TRUE(r.door_experiments[0].newly_unreachable.empty());
  // Closing the east door too still leaves the way through office_201 and the meeting room.
  EXPECT_TRUE(r.door_experiments[1].accepted);
  EXPECT_TRUE(r.door_experiments[1].newly_unreachable.empty());
  // An opening cannot be closed.
  EXPECT_FALSE(r.door_experiments[2].accepted);
  EXPECT_NE(r.door_experiments[2].message.find("opening"), std::string::npos);
  // The local window is SPOTT's 35 x 35 with the robot and walls in it.
  ASSERT_EQ(r.local_window.size(), 35u);
  const std::string all = [&] {
    std::string s;
    for (const auto& row : r.local_window) s += row;
    return s;
  }();
  EXPECT_EQ(std::count(all.begin(), all.end(), 'R'), 1);
  EXPECT_GT(std::count(all.begin(), all.end(), '#'), 35);
  EXPECT_TRUE(Contains(r.reachable, "lab"));
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "demo_rostest");
  return RUN_ALL_TESTS();
}
