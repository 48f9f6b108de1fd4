// The CI's short version of the Fig. 18 campaign (fig18.test): one seeded case, a fresh stack
// with the robot at the case's start, GO with the CAD map, judged on the ground truth. The full
// campaign (20 seeds) is launch/scripts/fig18_campaign.sh; its table is in spott_tr_plus's README.
#include <gtest/gtest.h>

#include "fig18_campaign.h"
#include "spott_map/world_loader.h"

namespace {

TEST(Fig18, GoWithTheCadMapArrives) {
  ros::NodeHandle nh, pnh("~");
  int seed = 1;
  std::string world_file;
  pnh.getParam("seed", seed);
  ASSERT_TRUE(pnh.getParam("world_file", world_file));
  const auto loaded = spott_map::LoadWorldFile(world_file);
  ASSERT_TRUE(loaded.ok());
  const auto c = spott_launch::Fig18CaseFor(*loaded.world, seed);
  ASSERT_FALSE(c.command.empty());
  double x = 0, y = 0;
  ASSERT_TRUE(pnh.getParam("start_x", x));
  ASSERT_TRUE(pnh.getParam("start_y", y));
  ASSERT_NEAR(c.start.x, x, 0.01) << "fig18.test's start_pose is not seed " << seed << "'s";
  ASSERT_NEAR(c.start.y, y, 0.01);
  const auto run = spott_launch::RunFig18Case(nh, c, 200.0, 0.35);
  EXPECT_TRUE(run.arrived) << spott_launch::Fig18Line(run);
  std::cout << "fig18: " << spott_launch::Fig18Line(run) << std::endl;
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "fig18_rostest");
  return RUN_ALL_TESTS();
}
