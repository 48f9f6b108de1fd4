// The shipped worlds load, their buildings are connected through their doors, and each holds
// what the papers' experiments rely on.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "spott_map/room_door_graph.h"
#include "spott_map/world_loader.h"

namespace spott_map {
namespace {

World Load(const std::string& name) {
  const WorldLoadResult r = LoadWorldFile(std::string(WORLDS_DIR) + "/" + name + ".yaml");
  EXPECT_TRUE(r.ok()) << FormatErrors(r.errors);
  EXPECT_TRUE(r.warnings.empty()) << FormatErrors(r.warnings);
  if (!r.ok()) throw std::runtime_error(name + " does not load");
  return *r.world;
}

// Connected through its doors: every room reachable when every door is open (a closed door
// is still a way through once opened).
void ExpectConnectedThroughDoors(const World& world) {
  std::vector<Door> doors = world.doors;
  for (Door& d : doors) d.state = DoorState::kOpen;
  const RoomDoorGraph all_open(world.rooms, doors);
  EXPECT_TRUE(all_open.IsConnected()) << world.name;
  for (const Room& r : world.rooms) {
    EXPECT_FALSE(all_open.DoorsOf(r.id).empty())
        << world.name << ": room " << r.id << " has no door";
  }
}

TEST(Worlds, CimOfficeIsAnOfficeFloorWithAnOpenLab) {
  const World w = Load("cim_office");
  ExpectConnectedThroughDoors(w);
  const Box b = w.Bounds();
  EXPECT_NEAR(b.max.x() - b.min.x(), 30.0, 0.5);
  EXPECT_NEAR(b.max.y() - b.min.y(), 20.0, 0.5);
  int hallways = 0;
  for (const Room& r : w.rooms) hallways += r.kind == RoomKind::kHallway;
  EXPECT_GE(hallways, 2);
  ASSERT_NE(w.FindRoom("lab"), nullptr);
  // Things the CAD map does not know: a partition, desks and chairs.
  int partitions = 0, desks = 0, chairs = 0;
  for (const WorldObject& o : w.objects) {
    partitions += o.kind == ObjectKind::kPartition;
    desks += o.kind == ObjectKind::kDesk;
    chairs += o.kind == ObjectKind::kChair;
  }
  EXPECT_GE(partitions, 1);
  EXPECT_GE(desks, 3);
  EXPECT_GE(chairs, 3);
  // Localization places are in a hallway, at least 1 m from any object.
  int localization = 0;
  for (const Place& p : w.places) {
    if (p.kind != "localization") continue;
    ++localization;
    EXPECT_EQ(w.RoomContaining(p.pose.Position())->kind, RoomKind::kHallway) << p.name;
    for (const WorldObject& o : w.objects) {
      EXPECT_GT((o.pose.Position() - p.pose.Position()).norm(), 1.0) << p.name << " " << o.id;
    }
  }
  EXPECT_GE(localization, 2);
  // The start is near a CAD corner: within 2 m of the end of two walls meeting there.
  const Vec2 start = w.robot_start.Position();
  int near_ends = 0;
  for (const Wall& wall : w.walls) {
    for (const Vec2& end : {wall.segment.a, wall.segment.b}) {
      near_ends += (end - start).norm() < 2.0;
    }
  }
  EXPECT_GE(near_ends, 2);
}

TEST(Worlds, BonnDepartmentCorridorIsSymmetricButTheRoomsAreNot) {
  const World w = Load("bonn_department");
  ExpectConnectedThroughDoors(w);
  const Box b = w.Bounds();
  EXPECT_NEAR(b.max.x() - b.min.x(), 27.0, 0.5);
  EXPECT_NEAR(b.max.y() - b.min.y(), 20.0, 0.5);
  const Vec2 centre = 0.5 * (b.min + b.max);
  const auto half_turn = [&](const Vec2& p) { return Vec2(2 * centre - p); };
  // Every door has a twin under the half turn with the same state: a robot in the corridor
  // sees the same thing from both ends.
  for (const Door& d : w.doors) {
    const Door* twin = nullptr;
    for (const Door& e : w.doors) {
      if ((e.center - half_turn(d.center)).norm() < 1e-6) twin = &e;
    }
    ASSERT_NE(twin, nullptr) << d.id << " has no symmetric twin";
    EXPECT_EQ(twin->state, d.state) << d.id << " and " << twin->id;
    EXPECT_DOUBLE_EQ(twin->width, d.width);
  }
  // B and C, and A and D, are half-turn images of each other.
  const auto image_of = [&](const std::string& a, const std::string& c) {
    const Vec2 ca = Centroid(w.FindRoom(a)->polygon);
    const Vec2 cc = Centroid(w.FindRoom(c)->polygon);
    return (half_turn(ca) - cc).norm() < 1e-6;
  };
  EXPECT_TRUE(image_of("room_b", "room_c"));
  EXPECT_TRUE(image_of("room_a", "room_d"));
  // ...but the CAD walls inside them differ: some wall has no half-turn twin.
  int walls_without_twin = 0;
  for (const Wall& wall : w.walls) {
    bool twin = false;
    for (const Wall& other : w.walls) {
      const bool same = (half_turn(wall.segment.a) - other.segment.a).norm() < 1e-6 &&
                        (half_turn(wall.segment.b) - other.segment.b).norm() < 1e-6;
      const bool flipped = (half_turn(wall.segment.a) - other.segment.b).norm() < 1e-6 &&
                           (half_turn(wall.segment.b) - other.segment.a).norm() < 1e-6;
      twin = twin || same || flipped;
    }
    walls_without_twin += !twin;
  }
  EXPECT_EQ(walls_without_twin, 2);  // room B's cupboard and room A's stub
  // Seen from the corridor's east end, B is the nearest room with an open door; from the west
  // end its twin C is: the closed end rooms make B and C the cheapest to enter.
  const auto nearest_open_room = [&](const Vec2& from) {
    const Door* best = nullptr;
    for (const Door& d : w.doors) {
      if (d.kind != DoorKind::kDoor || d.state != DoorState::kOpen) continue;
      if (!best || (d.center - from).norm() < (best->center - from).norm()) best = &d;
    }
    return w.FindRoom(best->room_a)->kind == RoomKind::kRoom ? best->room_a : best->room_b;
  };
  EXPECT_EQ(nearest_open_room(w.FindPlace("position_3")->pose.Position()), "room_b");
  EXPECT_EQ(nearest_open_room(half_turn(w.FindPlace("position_3")->pose.Position())), "room_c");
  // What the runs name.
  for (const char* p : {"position_1", "position_2", "position_3"}) {
    ASSERT_NE(w.FindPlace(p), nullptr) << p;
    EXPECT_EQ(w.RoomContaining(w.FindPlace(p)->pose.Position())->kind, RoomKind::kHallway);
  }
  EXPECT_NEAR(w.FindPlace("position_1")->pose.yaw, -3 * M_PI / 4, 0.01);  // south-west
  const WorldObject* shelf = w.FindObject("wolframs_shelf");
  ASSERT_NE(shelf, nullptr);
  EXPECT_EQ(w.RoomContaining(shelf->pose.Position())->id, "room_b");
  EXPECT_EQ(w.RoomContaining(w.robot_start.Position())->id, "corridor_e");
  EXPECT_GT(w.robot_start.x, 24.0);  // the east end
}

TEST(Worlds, HilareRoomHoldsExampleTwoInMetres) {
  const World w = Load("hilare_room");
  ExpectConnectedThroughDoors(w);
  const Zone* zone = w.FindZone("ZONE109");
  ASSERT_NE(zone, nullptr);
  const Box z = BoundingBox(zone->polygon);
  EXPECT_DOUBLE_EQ(z.min.x(), 1.5);
  EXPECT_DOUBLE_EQ(z.min.y(), 5.0);
  EXPECT_DOUBLE_EQ(z.max.x(), 3.5);
  EXPECT_DOUBLE_EQ(z.max.y(), 7.0);
  const NamedPath* path = w.FindPath("PATH");
  ASSERT_NE(path, nullptr);
  ASSERT_EQ(path->points.size(), 3u);
  EXPECT_DOUBLE_EQ(path->points[0].x(), 1.8);
  EXPECT_DOUBLE_EQ(path->points[1].x(), 3.5);
  EXPECT_DOUBLE_EQ(path->points[2].x(), 3.6);
  EXPECT_DOUBLE_EQ(path->points[2].y(), 3.2);
  EXPECT_FALSE(PointInPolygon(w.robot_start.Position(), zone->polygon)) << "start outside zone";
  // The room's east wall is one straight wall for Example 1's wall following.
  bool straight_east_wall = false;
  for (const Wall& wall : w.walls) {
    straight_east_wall |= std::abs(wall.segment.a.x() - 8.0) < 1e-9 &&
                          std::abs(wall.segment.b.x() - 8.0) < 1e-9 && wall.segment.Length() > 6.0;
  }
  EXPECT_TRUE(straight_east_wall);
}

}  // namespace
}  // namespace spott_map
