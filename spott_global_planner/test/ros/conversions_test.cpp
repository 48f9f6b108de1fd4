// Conversions of the global planner's core types to spott_msgs and its rviz markers.
#include "spott_global_planner/ros/conversions.h"

#include <gtest/gtest.h>

#include "../test_building.h"

namespace spott_global_planner {
namespace {

using spott_map::Box;
using spott_map::Vec2;
namespace conv = ros_conversions;

TEST(Conversions, PathKeepsRoomsDoorsWaypointsAndCost) {
  GlobalPlanner planner(test::MakeTestBuilding());
  const PlanResult r = planner.Plan(Vec2(1, 1), Vec2(11, 1));
  ASSERT_TRUE(r.ok());
  const spott_msgs::GlobalPath msg = conv::ToMsg(*r.path, "map", ros::Time(5.0));
  EXPECT_EQ(msg.header.frame_id, "map");
  EXPECT_EQ(msg.header.stamp, ros::Time(5.0));
  EXPECT_EQ(msg.rooms, (std::vector<std::string>{"A", "B", "C"}));
  EXPECT_EQ(msg.doors, (std::vector<std::string>{"dAB", "dBC"}));
  ASSERT_EQ(msg.waypoints.size(), 4u);
  EXPECT_DOUBLE_EQ(msg.waypoints[1].x, 4.0);
  EXPECT_DOUBLE_EQ(msg.waypoints[2].x, 8.0);
  EXPECT_DOUBLE_EQ(msg.cost, 8.0);
}

TEST(Conversions, ProjectedGoalCarriesCaseBorderAndWindow) {
  GlobalPlanner planner(test::MakeTestBuilding());
  const PlanResult r = planner.Plan(Vec2(3, 3), Vec2(10, 2));
  ASSERT_TRUE(r.ok());
  const Box window{Vec2(1, 1), Vec2(5, 5)};
  const ProjectedGoal p =
      ProjectGoalOntoWindow(planner.graph(), *r.path, Vec2(3, 3), Vec2(10, 2), window);
  const spott_msgs::ProjectedGoal msg = conv::ToMsg(p, "map", ros::Time(1.0));
  EXPECT_EQ(msg.projection_case, spott_msgs::ProjectedGoal::CASE_GENERAL);
  EXPECT_TRUE(msg.on_border);
  EXPECT_EQ(msg.edge_id, "dBC");
  EXPECT_EQ(msg.node_id, "B");
  EXPECT_DOUBLE_EQ(msg.projected_point.x, 5.0);
  EXPECT_DOUBLE_EQ(msg.projected_point.y, 2.0);
  EXPECT_DOUBLE_EQ(msg.goal.x, 10.0);
  ASSERT_EQ(msg.window.points.size(), 4u);
  const auto back = conv::WindowFromPolygon(msg.window);
  ASSERT_TRUE(back);
  EXPECT_TRUE(back->min.isApprox(window.min));
  EXPECT_TRUE(back->max.isApprox(window.max));
}

TEST(Conversions, GoalItselfIsSentAsThePointWithoutABorder) {
  ProjectedGoal p;
  p.projection_case = ProjectionCase::kSameNodeInWindow;
  p.goal = Vec2(2, 3);
  p.on_border = false;
  const spott_msgs::ProjectedGoal msg = conv::ToMsg(p, "map", ros::Time(1.0));
  EXPECT_EQ(msg.projection_case, spott_msgs::ProjectedGoal::CASE_SAME_NODE_IN_WINDOW);
  EXPECT_FALSE(msg.on_border);
  EXPECT_DOUBLE_EQ(msg.border_start.x, 2.0);
  EXPECT_DOUBLE_EQ(msg.border_end.y, 3.0);
}

TEST(Conversions, EmptyOrNonFiniteWindowPolygonIsRefused) {
  geometry_msgs::Polygon empty;
  EXPECT_FALSE(conv::WindowFromPolygon(empty));
  geometry_msgs::Polygon bad;
  geometry_msgs::Point32 p;
  p.x = std::numeric_limits<float>::quiet_NaN();
  bad.points.push_back(p);
  EXPECT_FALSE(conv::WindowFromPolygon(bad));
}

TEST(Conversions, MarkersShowClosedDoorsBlockedPassagesPathAndProjection) {
  GlobalPlanner planner(test::MakeTestBuilding());
  auto& graph = planner.mutable_graph();
  graph.SetDoorState("dBC", spott_map::DoorState::kClosed);
  graph.SetBlockedPassages(*graph.FindRoom("H"),
                           {{*graph.FindDoor("dAH"), *graph.FindDoor("dCH")}});
  const PlanResult r = planner.Plan(Vec2(3, 3), Vec2(10, 2));
  ASSERT_TRUE(r.ok());
  const ProjectedGoal p = ProjectGoalOntoWindow(planner.graph(), *r.path, Vec2(3, 3), Vec2(10, 2),
                                                Box{Vec2(1, 1), Vec2(5, 5)});
  const auto markers = conv::ToMarkers(planner.graph(), &*r.path, &p, "map", ros::Time(1.0));
  const auto find = [&](const std::string& ns, int id) -> const visualization_msgs::Marker* {
    for (const auto& m : markers.markers) {
      if (m.ns == ns && m.id == id) return &m;
    }
    return nullptr;
  };
  ASSERT_TRUE(find("graph_nodes", 0));
  EXPECT_EQ(find("graph_nodes", 0)->points.size(), 4u);
  ASSERT_TRUE(find("graph_edges", 0));
  EXPECT_EQ(find("graph_edges", 0)->points.size(), 4u * 4u);  // four open doors
  ASSERT_TRUE(find("graph_edges", 1));
  EXPECT_EQ(find("graph_edges", 1)->points.size(), 4u);  // dBC, closed
  ASSERT_TRUE(find("graph_edges", 2));
  EXPECT_EQ(find("graph_edges", 2)->points.size(), 4u);  // H: dAH - dCH blocked
  ASSERT_TRUE(find("path", 0));
  EXPECT_EQ(find("path", 0)->points.size(), r.path->waypoints.size());
  ASSERT_TRUE(find("border", 0));
  EXPECT_EQ(find("border", 0)->action, visualization_msgs::Marker::ADD);
  ASSERT_TRUE(find("window", 0));
  EXPECT_EQ(find("window", 0)->points.size(), 5u);
  // Without a projection the projection markers are deleted.
  const auto bare = conv::ToMarkers(planner.graph(), nullptr, nullptr, "map", ros::Time(1.0));
  for (const auto& m : bare.markers) {
    if (m.ns == "border" || m.ns == "window" || m.ns == "path") {
      EXPECT_EQ(m.action, visualization_msgs::Marker::DELETE) << m.ns;
    }
  }
}

}  // namespace
}  // namespace spott_global_planner
