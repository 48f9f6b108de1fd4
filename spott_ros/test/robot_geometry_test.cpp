#include "spott_ros/robot_geometry.h"

#include <cmath>

#include <gtest/gtest.h>

namespace spott_ros {
namespace {

std::string Robot(const std::string& collision) {
  return "<robot name='r'><link name='base_link'>" + collision +
         "</link><link name='other'/><joint name='j' type='fixed'><parent link='base_link'/>"
         "<child link='other'/></joint></robot>";
}

TEST(RobotGeometry, CylinderGivesItsRadius) {
  std::string error;
  const auto r = FootprintRadiusFromUrdf(
      Robot("<collision><geometry><cylinder radius='0.2625' length='1'/></geometry></collision>"),
      "base_link", &error);
  ASSERT_TRUE(r) << error;
  EXPECT_DOUBLE_EQ(*r, 0.2625);
}

TEST(RobotGeometry, BoxGivesItsHalfDiagonalPlusOffset) {
  std::string error;
  const auto r = FootprintRadiusFromUrdf(
      Robot("<collision><origin xyz='0.1 0 0'/><geometry><box size='0.6 0.8 1'/></geometry>"
            "</collision>"),
      "base_link", &error);
  ASSERT_TRUE(r) << error;
  EXPECT_NEAR(*r, 0.5 + 0.1, 1e-12);
}

TEST(RobotGeometry, MissingLinkOrGeometryIsAnError) {
  std::string error;
  EXPECT_FALSE(FootprintRadiusFromUrdf(Robot(""), "base_link", &error));
  EXPECT_NE(error.find("no <collision>"), std::string::npos) << error;
  EXPECT_FALSE(FootprintRadiusFromUrdf(Robot(""), "chassis", &error));
  EXPECT_NE(error.find("no link 'chassis'"), std::string::npos) << error;
  EXPECT_FALSE(FootprintRadiusFromUrdf("<robot", "base_link", &error));
}

}  // namespace
}  // namespace spott_ros
