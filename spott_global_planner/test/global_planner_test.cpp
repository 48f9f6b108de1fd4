#include "spott_global_planner/global_planner.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "spott_global_planner/synthetic_building.h"
#include "test_building.h"

namespace spott_global_planner {
namespace {

using spott_map::Vec2;
using test::kSqrt17;
using test::MakeTestBuilding;

using Ids = std::vector<std::string>;

TEST(GlobalPlanner, ShortestPathGoesThroughRoomsAndDoorsWithGeometricCost) {
  GlobalPlanner planner(MakeTestBuilding());
  const PlanResult r = planner.Plan(Vec2(1, 1), Vec2(11, 1));
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.path->rooms, (Ids{"A", "B", "C"}));
  EXPECT_EQ(r.path->doors, (Ids{"dAB", "dBC"}));
  // A-dAB-B = 4, B-dBC-C = 4 (the detour through H costs 4 + 2 sqrt(17) = 12.25).
  EXPECT_NEAR(r.path->cost, 8.0, 1e-9);
  ASSERT_EQ(r.path->waypoints.size(), 4u);
  EXPECT_TRUE(r.path->waypoints[0].isApprox(Vec2(1, 1)));
  EXPECT_TRUE(r.path->waypoints[1].isApprox(Vec2(4, 2)));
  EXPECT_TRUE(r.path->waypoints[2].isApprox(Vec2(8, 2)));
  EXPECT_TRUE(r.path->waypoints[3].isApprox(Vec2(11, 1)));
}

TEST(GlobalPlanner, PathIntoHallwayTakesTheCheaperDoor) {
  GlobalPlanner planner(MakeTestBuilding());
  // A-dAH-H = 2 + sqrt(17) = 6.12 beats A-dAB-B-dBH-H = 4 + 3 = 7.
  const PlanResult r = planner.Plan(Vec2(1, 1), Vec2(11, 5));
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.path->rooms, (Ids{"A", "H"}));
  EXPECT_EQ(r.path->doors, (Ids{"dAH"}));
  EXPECT_NEAR(r.path->cost, 2.0 + kSqrt17, 1e-9);
}

TEST(GlobalPlanner, StartAndGoalInOneNodeGiveAnEmptyDoorSequence) {
  GlobalPlanner planner(MakeTestBuilding());
  const PlanResult r = planner.Plan(Vec2(1, 5), Vec2(11, 5));
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.path->rooms, (Ids{"H"}));
  EXPECT_TRUE(r.path->doors.empty());
  EXPECT_EQ(r.path->cost, 0.0);
  EXPECT_EQ(r.path->waypoints.size(), 2u);
}

TEST(GlobalPlanner, ClosedDoorForcesReplanThroughOtherDoor) {
  GlobalPlanner planner(MakeTestBuilding());
  ASSERT_TRUE(planner.mutable_graph().SetDoorState("dBC", spott_map::DoorState::kClosed));
  const PlanResult r = planner.Plan(Vec2(1, 1), Vec2(11, 1));
  ASSERT_TRUE(r.ok()) << r.message;
  // A-dAH-H-dCH-C = 2 (2 + sqrt(17)) = 12.25 beats A-dAB-B-dBH-H-dCH-C = 4 + 3 + 2 + sqrt(17).
  EXPECT_EQ(r.path->rooms, (Ids{"A", "H", "C"}));
  EXPECT_EQ(r.path->doors, (Ids{"dAH", "dCH"}));
  EXPECT_NEAR(r.path->cost, 4.0 + 2.0 * kSqrt17, 1e-9);
}

TEST(GlobalPlanner, DoorOfUnknownStateIsAssumedOpen) {
  GlobalPlanner planner(MakeTestBuilding());
  auto& graph = planner.mutable_graph();
  ASSERT_TRUE(graph.SetDoorState("dBC", spott_map::DoorState::kClosed));
  ASSERT_TRUE(graph.SetDoorState("dBC", spott_map::DoorState::kUnknown));
  const PlanResult r = planner.Plan(Vec2(1, 1), Vec2(11, 1));
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.path->doors, (Ids{"dAB", "dBC"}));
}

TEST(GlobalPlanner, BlockedPassageClosesOnlyThatWayThroughTheNode) {
  GlobalPlanner planner(MakeTestBuilding());
  auto& graph = planner.mutable_graph();
  ASSERT_TRUE(graph.SetDoorState("dBC", spott_map::DoorState::kClosed));
  const int h = *graph.FindRoom("H");
  graph.SetBlockedPassages(h, {{*graph.FindDoor("dAH"), *graph.FindDoor("dCH")}});
  // H can no longer be crossed from dAH to dCH, but from dBH it can:
  // A-dAB-B-dBH-H-dCH-C = 4 + 3 + 2 + sqrt(17).
  const PlanResult r = planner.Plan(Vec2(1, 1), Vec2(11, 1));
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.path->rooms, (Ids{"A", "B", "H", "C"}));
  EXPECT_EQ(r.path->doors, (Ids{"dAB", "dBH", "dCH"}));
  EXPECT_NEAR(r.path->cost, 9.0 + kSqrt17, 1e-9);
  // The node itself is not blocked: H is still entered through dAH.
  const PlanResult into_h = planner.Plan(Vec2(1, 1), Vec2(1, 5));
  ASSERT_TRUE(into_h.ok());
  EXPECT_EQ(into_h.path->doors, (Ids{"dAH"}));
}

TEST(GlobalPlanner, AStarFindsTheSameCostsAsDijkstra) {
  SyntheticBuildingParameters params;
  params.rows = 12;
  params.cols = 15;
  params.seed = 7;
  GlobalPlanner dijkstra(MakeSyntheticBuilding(params), SearchAlgorithm::kDijkstra);
  GlobalPlanner astar(MakeSyntheticBuilding(params), SearchAlgorithm::kAStar);
  for (int i = 0; i < 40; ++i) {
    const Vec2 start(2.5 + 5.0 * (i % 15), 2.5 + 5.0 * (i % 12));
    const Vec2 goal(2.5 + 5.0 * ((7 * i + 3) % 15), 2.5 + 5.0 * ((5 * i + 1) % 12));
    const PlanResult a = dijkstra.Plan(start, goal);
    const PlanResult b = astar.Plan(start, goal);
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_NEAR(a.path->cost, b.path->cost, 1e-9) << "query " << i;
    EXPECT_LE(b.path->expanded, a.path->expanded) << "query " << i;
  }
}

TEST(GlobalPlanner, NoPathNamesTheClosedDoors) {
  GlobalPlanner planner(MakeTestBuilding());
  auto& graph = planner.mutable_graph();
  ASSERT_TRUE(graph.SetDoorState("dBC", spott_map::DoorState::kClosed));
  ASSERT_TRUE(graph.SetDoorState("dCH", spott_map::DoorState::kClosed));
  const PlanResult r = planner.Plan(Vec2(1, 1), Vec2(11, 1));
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error, PlanError::kNoPath);
  EXPECT_EQ(r.closed_doors, (Ids{"dBC", "dCH"}));
  EXPECT_TRUE(r.blocked_passages.empty());
  EXPECT_FALSE(r.disconnected);
  EXPECT_EQ(r.message, "no path from node 'A' to node 'C': doors dBC, dCH are closed");
}

TEST(GlobalPlanner, NoPathNamesClosedDoorAndBlockedPassages) {
  GlobalPlanner planner(MakeTestBuilding());
  auto& graph = planner.mutable_graph();
  ASSERT_TRUE(graph.SetDoorState("dBC", spott_map::DoorState::kClosed));
  const int h = *graph.FindRoom("H");
  const int ah = *graph.FindDoor("dAH"), bh = *graph.FindDoor("dBH"), ch = *graph.FindDoor("dCH");
  graph.SetBlockedPassages(h, {{ah, ch}, {bh, ch}});
  const PlanResult r = planner.Plan(Vec2(1, 1), Vec2(11, 1));
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.closed_doors, (Ids{"dBC"}));
  ASSERT_EQ(r.blocked_passages.size(), 2u);
  EXPECT_EQ(r.blocked_passages[0], (BlockedPassage{"H", "dAH", "dCH"}));
  EXPECT_EQ(r.blocked_passages[1], (BlockedPassage{"H", "dBH", "dCH"}));
  EXPECT_EQ(r.message,
            "no path from node 'A' to node 'C': door dBC is closed; node 'H' is blocked between "
            "doors dAH and dCH; node 'H' is blocked between doors dBH and dCH");
}

TEST(GlobalPlanner, DisconnectedGraphIsReportedAsSuch) {
  auto building = MakeTestBuilding();
  auto rooms = building.rooms();
  rooms.push_back(test::MakeRoom("island", 20, 0, 24, 4));
  GlobalPlanner planner(spott_map::RoomDoorGraph(rooms, building.doors()));
  const PlanResult r = planner.Plan(Vec2(1, 1), Vec2(22, 2));
  ASSERT_FALSE(r.ok());
  EXPECT_TRUE(r.disconnected);
  EXPECT_EQ(r.message,
            "no path from node 'A' to node 'island': the graph has no sequence of doors between "
            "them");
}

TEST(GlobalPlanner, PointsOutsideEveryRoomAreRefusedWithTheReason) {
  GlobalPlanner planner(MakeTestBuilding());
  PlanResult r = planner.Plan(Vec2(1, 1), Vec2(20, 20));
  EXPECT_EQ(r.error, PlanError::kGoalOutsideRooms);
  EXPECT_EQ(r.message, "goal (20.000, 20.000) is outside every room of the graph");
  r = planner.Plan(Vec2(-1, 1), Vec2(1, 1));
  EXPECT_EQ(r.error, PlanError::kStartOutsideRooms);
  r = planner.Plan(Vec2(1, 1), Vec2(std::numeric_limits<double>::quiet_NaN(), 1));
  EXPECT_EQ(r.error, PlanError::kInvalidPoint);
  r = planner.PlanBetweenRooms("A", "Z");
  EXPECT_EQ(r.error, PlanError::kUnknownRoom);
  EXPECT_EQ(r.message, "unknown room 'Z'");
  GlobalPlanner empty;
  EXPECT_EQ(empty.Plan(Vec2(1, 1), Vec2(1, 1)).error, PlanError::kNoGraph);
}

TEST(GlobalPlanner, PlanBetweenRoomsRunsFromCentreToCentre) {
  GlobalPlanner planner(MakeTestBuilding());
  const PlanResult r = planner.PlanBetweenRooms("B", "H");
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.path->doors, (Ids{"dBH"}));
  EXPECT_NEAR(r.path->cost, 3.0, 1e-9);
  EXPECT_TRUE(r.path->waypoints.front().isApprox(Vec2(6, 2)));
  EXPECT_TRUE(r.path->waypoints.back().isApprox(Vec2(6, 5)));
}

TEST(PlanningGraph, AnOpeningCannotBeClosedAndUnknownDoorsAreRefused) {
  auto building = MakeTestBuilding();
  auto doors = building.doors();
  doors[2].kind = spott_map::DoorKind::kOpening;  // dAH
  PlanningGraph graph(spott_map::RoomDoorGraph(building.rooms(), doors));
  EXPECT_FALSE(graph.SetDoorState("dAH", spott_map::DoorState::kClosed));
  EXPECT_TRUE(graph.DoorPassable(*graph.FindDoor("dAH")));
  EXPECT_FALSE(graph.SetDoorState("nope", spott_map::DoorState::kClosed));
  EXPECT_TRUE(graph.SetDoorState("dAB", spott_map::DoorState::kClosed));
  EXPECT_EQ(graph.ClosedDoors(), (Ids{"dAB"}));
}

TEST(PlanningGraph, PointLocationMatchesTheRoomOutlines) {
  PlanningGraph graph(MakeTestBuilding());
  EXPECT_EQ(graph.room(graph.RoomContaining(Vec2(1, 1))).id, "A");
  EXPECT_EQ(graph.room(graph.RoomContaining(Vec2(11.9, 5.9))).id, "H");
  EXPECT_EQ(graph.room(graph.RoomContaining(Vec2(12, 6))).id, "H");  // far corner
  // On the shared wall the first listed room wins, as in spott_map.
  EXPECT_EQ(graph.room(graph.RoomContaining(Vec2(4, 1))).id, "A");
  EXPECT_EQ(graph.RoomContaining(Vec2(12.01, 1)), -1);
  EXPECT_EQ(graph.RoomContaining(Vec2(-5, -5)), -1);
  // The grid index agrees with a linear scan on a generated building.
  SyntheticBuildingParameters params;
  params.rows = 9;
  params.cols = 13;
  PlanningGraph big(MakeSyntheticBuilding(params));
  for (double x = -1.3; x < 70; x += 1.7) {
    for (double y = -1.1; y < 50; y += 1.3) {
      const spott_map::Room* expected = big.source().RoomContaining(Vec2(x, y));
      const int got = big.RoomContaining(Vec2(x, y));
      if (!expected) {
        EXPECT_EQ(got, -1) << x << " " << y;
      } else {
        ASSERT_GE(got, 0) << x << " " << y;
        EXPECT_EQ(big.room(got).id, expected->id);
      }
    }
  }
}

}  // namespace
}  // namespace spott_global_planner
