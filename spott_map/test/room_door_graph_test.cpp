#include "spott_map/room_door_graph.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "test_worlds.h"

namespace spott_map {
namespace {

std::vector<std::string> Sorted(std::vector<std::string> v) {
  std::sort(v.begin(), v.end());
  return v;
}

std::vector<std::string> NeighbourIds(const RoomDoorGraph& g, const std::string& room) {
  std::vector<std::string> ids;
  for (const auto& [id, door] : g.NeighboursThroughOpenDoors(room)) ids.push_back(id);
  return Sorted(ids);
}

TEST(RoomDoorGraph, WhichRoomHoldsAPoint) {
  const RoomDoorGraph g(testing::TwoRoomsWorld());
  EXPECT_EQ(g.RoomContaining(Vec2(5, 1))->id, "hall");
  EXPECT_EQ(g.RoomContaining(Vec2(1, 5))->id, "office");
  EXPECT_EQ(g.RoomContaining(Vec2(9, 5))->id, "lab");
  EXPECT_EQ(g.RoomContaining(Vec2(11, 1)), nullptr);
}

TEST(RoomDoorGraph, ClosedDoorCutsTheEdgeAndUnknownCountsAsOpen) {
  RoomDoorGraph g(testing::TwoRoomsWorld());
  // d_lab (hall-lab) is closed; d_office_lab is unknown, hence passable.
  EXPECT_EQ(NeighbourIds(g, "hall"), (std::vector<std::string>{"office"}));
  EXPECT_EQ(NeighbourIds(g, "lab"), (std::vector<std::string>{"office"}));
  EXPECT_TRUE(g.IsConnected());
  ASSERT_TRUE(g.SetDoorState("d_office_lab", DoorState::kClosed));
  EXPECT_TRUE(NeighbourIds(g, "lab").empty());
  EXPECT_FALSE(g.IsConnected());
  EXPECT_EQ(Sorted(g.ReachableFrom("hall")), (std::vector<std::string>{"hall", "office"}));
  ASSERT_TRUE(g.SetDoorState("d_lab", DoorState::kOpen));
  EXPECT_EQ(NeighbourIds(g, "hall"), (std::vector<std::string>{"lab", "office"}));
  EXPECT_TRUE(g.IsConnected());
}

TEST(RoomDoorGraph, UnknownDoorsAndClosingOpeningsAreRefused) {
  RoomDoorGraph g(testing::TwoRoomsWorld());
  EXPECT_FALSE(g.SetDoorState("no_such_door", DoorState::kOpen));
  Room a{"a", "a", RoomKind::kHallway, {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)}, {}};
  Room b{"b", "b", RoomKind::kHallway, {Vec2(1, 0), Vec2(2, 0), Vec2(2, 1), Vec2(1, 1)}, {}};
  Door o;
  o.id = "o";
  o.room_a = "a";
  o.room_b = "b";
  o.kind = DoorKind::kOpening;
  o.state = DoorState::kOpen;
  RoomDoorGraph h({a, b}, {o});
  EXPECT_FALSE(h.SetDoorState("o", DoorState::kClosed));
  EXPECT_EQ(h.FindDoor("o")->state, DoorState::kOpen);
}

TEST(RoomDoorGraph, RoomCentreIsTheAreaCentroid) {
  const RoomDoorGraph g(testing::TwoRoomsWorld());
  const Vec2 c = g.RoomCentre("lab");
  EXPECT_NEAR(c.x(), 7.0, 1e-9);
  EXPECT_NEAR(c.y(), 4.0, 1e-9);
  EXPECT_EQ(g.DoorsOf("office").size(), 2u);
}

}  // namespace
}  // namespace spott_map
