// rostest of the global_planner node with the world_server as the map's owner, on the building
// of the unit tests (test/data/three_rooms_hallway.yaml), the robot fixed at (1.1,1.1) in room A
// by a static transform this test broadcasts. Doors are closed through the world server (as the
// map's owner does when the robot finds one closed) and the node must replan; an obstacle sent
// as a map update blocks a passage through the hallway; bad requests (and a malformed graph) are
// refused and the node keeps its goal and graph; the window the local planner publishes on
// local_window is the one the goal is projected onto.
#include <geometry_msgs/PolygonStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <spott_msgs/Door.h>
#include <spott_msgs/GlobalGoal.h>
#include <spott_msgs/GlobalPath.h>
#include <spott_msgs/GlobalPlanStatus.h>
#include <spott_msgs/MapUpdate.h>
#include <spott_msgs/PlanGlobalPath.h>
#include <spott_msgs/ProjectedGoal.h>
#include <spott_msgs/RoomDoorGraph.h>
#include <spott_msgs/SetDoorState.h>
#include <tf2_ros/static_transform_broadcaster.h>

#include "spott_ros/testing/node_process.h"

#include <cmath>
#include <functional>
#include <optional>

namespace {

using Ids = std::vector<std::string>;

using spott_ros::testing::Latest;

class GlobalPlannerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(ros::service::waitForService("/world_server/set_door_state", ros::Duration(30)));
    ASSERT_TRUE(
        ros::service::waitForService("/global_planner/plan_global_path", ros::Duration(30)));
    goal_pub_ = nh_.advertise<spott_msgs::GlobalGoal>("global_goal", 1, true);
    updates_pub_ = nh_.advertise<spott_msgs::MapUpdate>("map_updates", 10);
    // Publishers connect before anything is sent.
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(10.0);
    while ((goal_pub_.getNumSubscribers() == 0 || updates_pub_.getNumSubscribers() < 2) &&
           ros::WallTime::now() < end) {
      ros::WallDuration(0.05).sleep();
    }
  }

  // Sends a goal as the Navigate server does, with a new id; returns the id.
  std::string SendGoal(double x, double y, const std::string& frame = "map") {
    static int count = 0;
    spott_msgs::GlobalGoal g;
    g.header.frame_id = frame;
    g.header.stamp = ros::Time::now();
    g.goal_id = "goal_" + std::to_string(++count);
    g.target.x = x;
    g.target.y = y;
    goal_pub_.publish(g);
    return g.goal_id;
  }

  void SetDoor(const std::string& id, uint8_t state) {
    spott_msgs::SetDoorState srv;
    srv.request.door_id = id;
    srv.request.state = state;
    ASSERT_TRUE(ros::service::call("/world_server/set_door_state", srv));
    ASSERT_TRUE(srv.response.success) << srv.response.message;
  }

  ros::NodeHandle nh_;
  ros::Publisher goal_pub_, updates_pub_;
};

bool Near(const geometry_msgs::Point& p, double x, double y) {
  return std::abs(p.x - x) < 1e-3 && std::abs(p.y - y) < 1e-3;
}

TEST_F(GlobalPlannerTest, ReplansWhenDoorsCloseAndFailsNamingThemWhenNoPathIsLeft) {
  Latest<spott_msgs::GlobalPath> path(nh_, "global_path");
  Latest<spott_msgs::ProjectedGoal> projected(nh_, "projected_goal");
  Latest<spott_msgs::GlobalPlanStatus> status(nh_, "global_plan_status");
  const std::string id = SendGoal(11, 1);

  // A-dAB-B-dBC-C, 8 m; every answer names the goal it answers.
  ASSERT_TRUE(path.WaitFor([](const auto& p) { return p.doors == Ids{"dAB", "dBC"}; }));
  EXPECT_EQ(path.msg()->goal_id, id);
  EXPECT_EQ(path.msg()->rooms, (Ids{"A", "B", "C"}));
  EXPECT_NEAR(path.msg()->cost, 8.0, 1e-9);
  // The modelled window: 7 m around (1.1,1.1) on the 0.2 m lattice, [-2.4,4.6]^2. dAB (x = 4)
  // is inside, dBC (x = 8) is not: case 3, e_k = dBC, n_k = B; the line y = 2 through B's centre
  // (6,2) and dBC's centre (8,2) crosses the border at (4.6,2); B holds y in [0,4] of that side.
  ASSERT_TRUE(projected.WaitFor([](const auto& g) { return g.edge_id == "dBC"; }));
  const auto& g = *projected.msg();
  EXPECT_EQ(g.goal_id, id);
  EXPECT_EQ(g.projection_case, spott_msgs::ProjectedGoal::CASE_GENERAL);
  EXPECT_EQ(g.node_id, "B");
  EXPECT_TRUE(g.on_border);
  EXPECT_TRUE(Near(g.projected_point, 4.6, 2.0));
  EXPECT_TRUE((Near(g.border_start, 4.6, 0.0) && Near(g.border_end, 4.6, 4.0)) ||
              (Near(g.border_start, 4.6, 4.0) && Near(g.border_end, 4.6, 0.0)));
  ASSERT_TRUE(status.WaitFor(
      [](const auto& s) { return s.state == spott_msgs::GlobalPlanStatus::PLANNED; }));
  EXPECT_EQ(status.msg()->goal_id, id);
  EXPECT_EQ(status.msg()->path_summary, "A -> dAB -> B -> dBC -> C");

  // dBC closes: A-dAH-H-dCH-C.
  SetDoor("dBC", spott_msgs::Door::CLOSED);
  ASSERT_TRUE(path.WaitFor([](const auto& p) { return p.doors == Ids{"dAH", "dCH"}; }));
  EXPECT_NEAR(path.msg()->cost, 4.0 + 2.0 * std::sqrt(17.0), 1e-9);
  ASSERT_TRUE(status.WaitFor([](const auto& s) { return s.replans == 1; }));
  EXPECT_EQ(status.msg()->state, spott_msgs::GlobalPlanStatus::PLANNED);
  // dAH (y = 4) is inside the window now, dCH is not.
  ASSERT_TRUE(projected.WaitFor([](const auto& g) { return g.edge_id == "dCH"; }));
  EXPECT_EQ(projected.msg()->node_id, "H");

  // An obstacle across the hallway between dAH and dBH (sent to the map's owner) blocks the
  // passage dAH -> dCH through H: A-dAB-B-dBH-H-dCH-C.
  spott_msgs::MapUpdate update;
  spott_msgs::MapFeature partition;
  partition.id = "partition1";
  partition.type = spott_msgs::MapFeature::RECTANGLE;
  partition.source = spott_msgs::MapFeature::SOURCE_SENSED;
  partition.label = "partition";
  partition.pose.position.x = 4.0;
  partition.pose.position.y = 5.0;
  partition.pose.orientation.w = 1.0;
  partition.size.x = 0.5;
  partition.size.y = 2.0;
  update.header.frame_id = "map";
  update.added.push_back(partition);
  updates_pub_.publish(update);
  ASSERT_TRUE(path.WaitFor([](const auto& p) {
    return p.doors == Ids{"dAB", "dBH", "dCH"};
  })) << "path still "
      << (path.msg() ? path.msg()->doors.size() : 0) << " doors";
  ASSERT_TRUE(status.WaitFor([](const auto& s) { return s.replans == 2; }));

  // dCH closes too: no path; the status names both closed doors.
  SetDoor("dCH", spott_msgs::Door::CLOSED);
  ASSERT_TRUE(status.WaitFor(
      [](const auto& s) { return s.state == spott_msgs::GlobalPlanStatus::FAILED; }));
  EXPECT_EQ(status.msg()->closed_doors, (Ids{"dBC", "dCH"}));
  EXPECT_EQ(status.msg()->message, "no path from node 'A' to node 'C': doors dBC, dCH are closed");
  ASSERT_TRUE(path.WaitFor([](const auto& p) { return p.doors.empty() && p.rooms.empty(); }));

  // dBC opens again: back to the short way.
  SetDoor("dBC", spott_msgs::Door::OPEN);
  ASSERT_TRUE(path.WaitFor([](const auto& p) { return p.doors == Ids{"dAB", "dBC"}; }));
  ASSERT_TRUE(status.WaitFor(
      [](const auto& s) { return s.state == spott_msgs::GlobalPlanStatus::PLANNED; }));
}

TEST_F(GlobalPlannerTest, BadRequestsAndGoalsAreRefusedWithTheReason) {
  spott_msgs::PlanGlobalPath srv;
  srv.request.start.x = 1.0;
  srv.request.start.y = 1.0;
  srv.request.goal.x = 30.0;
  srv.request.goal.y = 30.0;
  ASSERT_TRUE(ros::service::call("/global_planner/plan_global_path", srv));
  EXPECT_FALSE(srv.response.success);
  EXPECT_EQ(srv.response.message, "goal (30.000, 30.000) is outside every room of the graph");

  srv.request.goal.x = 11.0;
  srv.request.goal.y = 5.0;
  ASSERT_TRUE(ros::service::call("/global_planner/plan_global_path", srv));
  ASSERT_TRUE(srv.response.success) << srv.response.message;
  EXPECT_EQ(srv.response.path.doors, (Ids{"dAH"}));  // 2 + sqrt(17) < 7 through B
  EXPECT_NEAR(srv.response.path.cost, 2.0 + std::sqrt(17.0), 1e-9);

  Latest<spott_msgs::GlobalPlanStatus> status(nh_, "global_plan_status");
  Latest<spott_msgs::GlobalPath> path(nh_, "global_path");
  const std::string outside = SendGoal(50, 50);
  ASSERT_TRUE(status.WaitFor([&](const auto& s) {
    return s.goal_id == outside && s.state == spott_msgs::GlobalPlanStatus::REFUSED &&
           s.message.find("outside every room") != std::string::npos;
  })) << (status.msg() ? status.msg()->message : "no status");
  const std::string odom = SendGoal(2, 2, "odom");
  ASSERT_TRUE(status.WaitFor([&](const auto& s) {
    return s.goal_id == odom && s.state == spott_msgs::GlobalPlanStatus::REFUSED &&
           s.message.find("frame 'odom'") != std::string::npos;
  }));
  // The same target as the first test under a new id is answered in full again.
  const std::string again = SendGoal(11, 1);
  ASSERT_TRUE(path.WaitFor([&](const auto& p) { return p.goal_id == again; }));
  EXPECT_TRUE(Near(path.msg()->waypoints.back(), 11.0, 1.0));
  ASSERT_TRUE(status.WaitFor([&](const auto& s) {
    return s.goal_id == again && s.state == spott_msgs::GlobalPlanStatus::PLANNED;
  }));

  // A malformed graph (a door naming a room that does not exist) is refused; the node keeps its
  // graph and still plans.
  ros::Publisher graph_pub = nh_.advertise<spott_msgs::RoomDoorGraph>("room_door_graph", 1);
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(10.0);
  while (graph_pub.getNumSubscribers() == 0 && ros::WallTime::now() < end) {
    ros::WallDuration(0.05).sleep();
  }
  spott_msgs::RoomDoorGraph bad;
  bad.world = "broken";
  bad.doors.resize(1);
  bad.doors[0].id = "dX";
  bad.doors[0].room_a = "A";
  bad.doors[0].room_b = "Z";
  graph_pub.publish(bad);
  ros::WallDuration(1.0).sleep();
  ASSERT_TRUE(ros::service::call("/global_planner/plan_global_path", srv));
  EXPECT_TRUE(srv.response.success) << srv.response.message;
}

TEST_F(GlobalPlannerTest, FollowsTheWindowTheLocalPlannerPublishes) {
  // After the first test dBC is open again: A-dAB-B-dBC-C. A local window [-1,3]^2 leaves dAB
  // (x = 4) outside: e_k = dAB, n_k = A, the line y = 2 from A's centre (2,2) leaves the window
  // at (3,2); A holds y in [0,3] of the right side x = 3.
  ros::Publisher window_pub = nh_.advertise<geometry_msgs::PolygonStamped>("local_window", 1, true);
  geometry_msgs::PolygonStamped w;
  w.header.frame_id = "map";
  for (const auto& [x, y] : {std::pair<float, float>{-1, -1}, {3, -1}, {3, 3}, {-1, 3}}) {
    geometry_msgs::Point32 p;
    p.x = x;
    p.y = y;
    w.polygon.points.push_back(p);
  }
  window_pub.publish(w);
  Latest<spott_msgs::ProjectedGoal> projected(nh_, "projected_goal");
  ASSERT_TRUE(projected.WaitFor([](const auto& g) { return g.edge_id == "dAB"; }))
      << (projected.msg() ? projected.msg()->edge_id : "no projected goal");
  const auto& g = *projected.msg();
  EXPECT_EQ(g.node_id, "A");
  EXPECT_TRUE(Near(g.projected_point, 3.0, 2.0));
  EXPECT_TRUE((Near(g.border_start, 3.0, 0.0) && Near(g.border_end, 3.0, 3.0)) ||
              (Near(g.border_start, 3.0, 3.0) && Near(g.border_end, 3.0, 0.0)));
  ASSERT_EQ(g.window.points.size(), 4u);
  EXPECT_FLOAT_EQ(g.window.points[0].x, -1.0f);
  EXPECT_FLOAT_EQ(g.window.points[2].y, 3.0f);
}

TEST(GlobalPlannerNode, AnUnknownOrMistypedParameterStopsTheNodeNamingIt) {
  const auto run = spott_ros::testing::RunNode(
      GLOBAL_PLANNER_EXE, "__name:=bad_global_planner _update_rate:=5.0 _window/fit_node:=3");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("~update_rate is not a parameter"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("~window/fit_node must be true or false"), std::string::npos)
      << run.output;
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "global_planner_rostest");
  ros::NodeHandle nh;
  // The robot stands at (1.1,1.1) in room A: no localization or simulator in this test.
  tf2_ros::StaticTransformBroadcaster broadcaster;
  geometry_msgs::TransformStamped pose;
  pose.header.stamp = ros::Time::now();
  pose.header.frame_id = "map";
  pose.child_frame_id = "base_link";
  pose.transform.translation.x = 1.1;
  pose.transform.translation.y = 1.1;
  pose.transform.rotation.w = 1.0;
  broadcaster.sendTransform(pose);
  return RUN_ALL_TESTS();
}
