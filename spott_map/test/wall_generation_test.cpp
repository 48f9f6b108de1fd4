#include "spott_map/wall_generation.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "test_worlds.h"

namespace spott_map {
namespace {

// A wall as "x0,y0-x1,y1" with the ends in increasing order, for order-free comparison.
std::string Key(const Segment& s) {
  Vec2 a = s.a;
  Vec2 b = s.b;
  if (b.x() < a.x() - 1e-9 || (std::abs(b.x() - a.x()) <= 1e-9 && b.y() < a.y())) std::swap(a, b);
  char text[96];
  std::snprintf(text, sizeof(text), "%.2f,%.2f-%.2f,%.2f", a.x() + 0.0, a.y() + 0.0, b.x() + 0.0,
                b.y() + 0.0);
  return text;
}

TEST(WallGeneration, SharedEdgesMergeAndDoorOpeningsAreCutOut) {
  const World w = testing::TwoRoomsWorld();
  std::vector<std::string> keys;
  for (const Wall& wall : w.walls) {
    EXPECT_TRUE(wall.generated);
    EXPECT_DOUBLE_EQ(wall.thickness, 0.1);
    keys.push_back(Key(wall.segment));
  }
  std::sort(keys.begin(), keys.end());
  // Hand-derived from data/two_rooms.yaml: y=2 is shared by all three rooms and holds two doors
  // (1.5..2.5 and 6.5..7.5); x=4 holds the office-lab door (3.6..4.4).
  const std::vector<std::string> expected = {
      "0.00,0.00-0.00,6.00",  "0.00,0.00-10.00,0.00",  "0.00,2.00-1.50,2.00",
      "0.00,6.00-10.00,6.00", "10.00,0.00-10.00,6.00", "2.50,2.00-6.50,2.00",
      "4.00,2.00-4.00,3.60",  "4.00,4.40-4.00,6.00",   "7.50,2.00-10.00,2.00"};
  EXPECT_EQ(keys, expected);
}

TEST(WallGeneration, AnOpeningAsWideAsTheSharedEdgeLeavesNoWallThere) {
  Room a{"a", "a", RoomKind::kHallway, {Vec2(0, 0), Vec2(2, 0), Vec2(2, 2), Vec2(0, 2)}, {}};
  Room b{"b", "b", RoomKind::kHallway, {Vec2(2, 0), Vec2(4, 0), Vec2(4, 2), Vec2(2, 2)}, {}};
  Door d;
  d.id = "o";
  d.kind = DoorKind::kOpening;
  d.opening = Segment{Vec2(2, 0), Vec2(2, 2)};
  const auto walls = GenerateWallsFromRooms({a, b}, {d}, 0.1, 0.01);
  for (const Wall& wall : walls) {
    EXPECT_FALSE(std::abs(wall.segment.a.x() - 2.0) < 1e-9 &&
                 std::abs(wall.segment.b.x() - 2.0) < 1e-9)
        << "a wall was generated across the opening: " << Key(wall.segment);
  }
  EXPECT_EQ(walls.size(), 4u);  // bottom, top (both merged), left, right
}

}  // namespace
}  // namespace spott_map
