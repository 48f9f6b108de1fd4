#include "spott_harmonic_planner/ros/conversions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "../test_maps.h"

namespace spott_harmonic_planner {
namespace {

PotentialField SolvedRow() {
  // 5 x 3 window, goal at (1, 1): p = 1, 4/15, 1/15 along the row (see potential_field_test).
  FieldOptions o;
  o.tolerance = 1e-12;
  PotentialField f(o);
  f.SetOccupancy(testing_maps::EmptyRaster(5, 3, 0.5));
  EXPECT_TRUE(f.SetGoalPoint(Vec2(0.75, 0.75)));
  f.ColdStart();
  f.Solve(1000);
  return f;
}

TEST(Conversions, PotentialImageScalesDecadesOfGoalProbability) {
  const PotentialField f = SolvedRow();
  const auto g = ros_conversions::ToPotentialImage(f, "map", ros::Time(3.0));
  EXPECT_EQ(g.header.frame_id, "map");
  EXPECT_EQ(g.info.width, 5u);
  EXPECT_EQ(g.info.height, 3u);
  EXPECT_FLOAT_EQ(g.info.resolution, 0.5f);
  EXPECT_EQ(g.data[5 + 1], 0);  // goal
  EXPECT_EQ(g.data[0], 100);    // border ring
  // -log10(4/15) = 0.574 decades of 12: 1 + round(98 * 0.0478) = 6; -log10(1/15) = 1.176: 11.
  EXPECT_EQ(g.data[5 + 2], 6);
  EXPECT_EQ(g.data[5 + 3], 11);
}

TEST(Conversions, ContoursCrossBetweenCellsAtTheRightLevel) {
  const PotentialField f = SolvedRow();
  const auto m = ros_conversions::ToContours(f, "map", ros::Time(0));
  ASSERT_FALSE(m.points.empty());
  EXPECT_EQ(m.points.size() % 2, 0u);
  // The level log10 p = -1 lies between cells 2 (p = 4/15) and 3 (p = 1/15) of the row, i.e.
  // between x = 1.25 and 1.75 m; every crossing is somewhere in the window.
  bool found = false;
  for (const auto& p : m.points) {
    EXPECT_GE(p.x, 0.0);
    EXPECT_LE(p.x, 2.5);
    if (std::abs(p.y - 0.75) < 1e-9 && p.x > 1.25 && p.x < 1.75) found = true;
  }
  EXPECT_TRUE(found);
}

TEST(Conversions, PathKeepsPointsInOrder) {
  PotentialField::Path path;
  path.points = {Vec2(0, 0), Vec2(1, 0.5), Vec2(2, 1)};
  const auto msg = ros_conversions::ToPath(path, "map", ros::Time(1.0));
  ASSERT_EQ(msg.poses.size(), 3u);
  EXPECT_DOUBLE_EQ(msg.poses[1].pose.position.x, 1.0);
  EXPECT_DOUBLE_EQ(msg.poses[2].pose.position.y, 1.0);
  EXPECT_EQ(msg.poses[0].header.frame_id, "map");
}

TEST(Conversions, NavigateGoalBiasKindsAreReadAndBadOnesRefusedByField) {
  spott_msgs::NavigateGoal g;
  g.target.header.frame_id = "map";
  g.ignore_heading = true;
  g.direction_bias = std::nan("");
  std::string error;
  auto r = ros_conversions::FromGoal(g, "map", 0.2, 0.1, &error);
  ASSERT_TRUE(r) << error;
  EXPECT_EQ(r->bias.kind, DirectionBias::Kind::kHeading);
  EXPECT_FALSE(r->bias.heading);  // NaN: no bias, as before bias_kind existed
  g.bias_kind = spott_msgs::NavigateGoal::BIAS_AROUND;
  g.bias_point.x = 2.0;
  g.bias_sense = 1.0;
  r = ros_conversions::FromGoal(g, "map", 0.2, 0.1, &error);
  ASSERT_TRUE(r) << error;
  EXPECT_EQ(r->bias.kind, DirectionBias::Kind::kAround);
  EXPECT_DOUBLE_EQ(r->bias.point.x(), 2.0);
  g.bias_sense = 0.5;
  EXPECT_FALSE(ros_conversions::FromGoal(g, "map", 0.2, 0.1, &error));
  EXPECT_NE(error.find("bias_sense"), std::string::npos) << error;
  g.bias_kind = spott_msgs::NavigateGoal::BIAS_VIA;
  g.bias_radius = -1.0;
  EXPECT_FALSE(ros_conversions::FromGoal(g, "map", 0.2, 0.1, &error));
  EXPECT_NE(error.find("bias_radius"), std::string::npos) << error;
  g.bias_kind = 9;
  EXPECT_FALSE(ros_conversions::FromGoal(g, "map", 0.2, 0.1, &error));
  EXPECT_NE(error.find("bias_kind"), std::string::npos) << error;
}

// Issue 21: each of these drove the robot or ended without moving before it was refused.
TEST(Conversions, NavigateGoalsThatAreNoGoalAreRefusedByField) {
  spott_msgs::NavigateGoal g;
  g.target.header.frame_id = "map";
  g.target.pose.position.x = 1.0;
  g.target.pose.orientation.w = 1.0;
  std::string error;
  ASSERT_TRUE(ros_conversions::FromGoal(g, "map", 0.2, 0.1, &error)) << error;
  g.position_tolerance = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(ros_conversions::FromGoal(g, "map", 0.2, 0.1, &error));
  EXPECT_NE(error.find("position_tolerance"), std::string::npos) << error;
  g.position_tolerance = 1e6;  // finite, but every pose of the building is within it
  EXPECT_FALSE(ros_conversions::FromGoal(g, "map", 0.2, 0.1, &error));
  EXPECT_NE(error.find("position_tolerance"), std::string::npos) << error;
  g.position_tolerance = ros_conversions::kMaxPositionToleranceM;
  EXPECT_TRUE(ros_conversions::FromGoal(g, "map", 0.2, 0.1, &error)) << error;
  g.position_tolerance = 0.0;
  g.target.pose.orientation.z = std::nan("");  // the heading counts: no yaw in it
  EXPECT_FALSE(ros_conversions::FromGoal(g, "map", 0.2, 0.1, &error));
  EXPECT_NE(error.find("orientation"), std::string::npos) << error;
  g.ignore_heading = true;  // the heading does not count: the quaternion is not read
  EXPECT_TRUE(ros_conversions::FromGoal(g, "map", 0.2, 0.1, &error)) << error;
  g.target.pose.position.y = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(ros_conversions::FromGoal(g, "map", 0.2, 0.1, &error));
  EXPECT_NE(error.find("position"), std::string::npos) << error;
}

}  // namespace
}  // namespace spott_harmonic_planner
