#include "spott_map/world_loader.h"

#include <gtest/gtest.h>

#include <fstream>

#include "test_worlds.h"

namespace spott_map {
namespace {

// Loads `text` as "bad.yaml" and returns its errors as "line:column: message" strings.
std::vector<std::string> Errors(const std::string& text) {
  const WorldLoadResult r = LoadWorldFromString(text, "bad.yaml");
  std::vector<std::string> out;
  for (const SourceError& e : r.errors) {
    EXPECT_EQ(e.where.file, "bad.yaml");
    out.push_back(std::to_string(e.where.line) + ":" + std::to_string(e.where.column) + ": " +
                  e.message);
  }
  EXPECT_FALSE(r.ok());
  return out;
}

// A minimal valid world; tests replace one line at a time.
const char* kMinimal = R"(world:
  name: tiny
rooms:
  - id: a
    polygon: [[0, 0], [4, 0], [4, 4], [0, 4]]
  - id: b
    polygon: [[4, 0], [8, 0], [8, 4], [4, 4]]
doors:
  - id: d1
    between: [a, b]
    center: [4, 2]
    width: 0.9
robot_start:
  pose: [1, 1, 0]
)";

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(WorldLoader, TheTestWorldLoadsWithItsContents) {
  const World w = testing::TwoRoomsWorld();
  EXPECT_EQ(w.name, "two_rooms");
  ASSERT_EQ(w.rooms.size(), 3u);
  EXPECT_EQ(w.rooms[0].kind, RoomKind::kHallway);
  EXPECT_EQ(w.rooms[0].name, "Hallway");
  EXPECT_EQ(w.rooms[1].name, "office");  // defaults to the id
  EXPECT_GT(SignedArea(w.rooms[2].polygon), 0.0) << "clockwise outline is normalized";
  ASSERT_EQ(w.doors.size(), 3u);
  EXPECT_EQ(w.doors[0].state, DoorState::kOpen);
  EXPECT_EQ(w.doors[1].state, DoorState::kClosed);
  EXPECT_EQ(w.doors[2].state, DoorState::kUnknown);
  // The opening lies along the shared edge y = 2, 1 m wide around x = 2.
  const Segment o = w.doors[0].opening;
  EXPECT_NEAR(std::min(o.a.x(), o.b.x()), 1.5, 1e-9);
  EXPECT_NEAR(std::max(o.a.x(), o.b.x()), 2.5, 1e-9);
  EXPECT_NEAR(o.a.y(), 2.0, 1e-9);
  ASSERT_EQ(w.objects.size(), 1u);
  EXPECT_EQ(w.objects[0].kind, ObjectKind::kDesk);
  EXPECT_DOUBLE_EQ(w.objects[0].height, 0.75);
  ASSERT_EQ(w.places.size(), 1u);
  EXPECT_EQ(w.places[0].kind, "localization");
  EXPECT_DOUBLE_EQ(w.robot_start.x, 9.0);
  EXPECT_EQ(w.walls.size(), 9u);
  EXPECT_EQ(w.RoomContaining(Vec2(6, 5))->id, "lab");
  ASSERT_NE(w.FindZone("ZONE1"), nullptr);
  EXPECT_EQ(w.FindZone("ZONE1")->polygon.size(), 4u);
  ASSERT_NE(w.FindPath("PATH1"), nullptr);
  EXPECT_EQ(w.FindPath("PATH1")->points.size(), 3u);
  EXPECT_NEAR(*w.FindPath("PATH1")->final_yaw, 1.5708, 1e-12);
}

TEST(WorldLoader, ZonesMustBeSimpleAndPathsInsideRooms) {
  const std::string zone = std::string(kMinimal) +
                           "zones:\n"
                           "  - id: Z\n"
                           "    polygon: [[1, 1], [2, 2], [2, 1], [1, 2]]\n";
  const auto e = Errors(zone);
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0], "16:5: zone Z: polygon is self-intersecting (edge 0 meets edge 2)");
  const std::string path = std::string(kMinimal) +
                           "paths:\n"
                           "  - id: P\n"
                           "    points: [[1, 1], [9, 1]]\n";
  const auto p = Errors(path);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0], "16:5: path P: point 1 (9.00, 1.00) is outside every room");
}

// The example in README.md is what users copy: it must stay a valid world. (The test runs in
// spott_map/test, see CMakeLists.txt.)
TEST(WorldLoader, TheReadmeExampleLoads) {
  std::ifstream readme("../README.md");
  ASSERT_TRUE(readme.good());
  std::string line, example;
  bool inside = false;
  while (std::getline(readme, line)) {
    if (line == "```yaml") {
      inside = true;
    } else if (inside && line == "```") {
      break;
    } else if (inside) {
      example += line + "\n";
    }
  }
  const WorldLoadResult r = LoadWorldFromString(example, "README.md");
  ASSERT_TRUE(r.ok()) << FormatErrors(r.errors);
  EXPECT_EQ(r.world->rooms.size(), 2u);
  EXPECT_EQ(r.world->doors.size(), 1u);
  EXPECT_EQ(r.world->objects.size(), 1u);
  EXPECT_EQ(r.world->zones.size(), 1u);
  EXPECT_EQ(r.world->paths.size(), 1u);
}

TEST(WorldLoader, MinimalWorldIsValid) {
  const WorldLoadResult r = LoadWorldFromString(kMinimal, "tiny.yaml");
  EXPECT_TRUE(r.ok()) << FormatErrors(r.errors);
}

TEST(WorldLoader, MissingFileNamesThePath) {
  const WorldLoadResult r = LoadWorldFile("data/no_such_world.yaml");
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0].ToString(),
            "data/no_such_world.yaml: cannot read world file: no such file");
}

// /dev/zero would have been read into memory until it was exhausted (issue 21).
TEST(WorldLoader, ADeviceOrDirectoryIsRefusedWithoutReadingIt) {
  for (const char* path : {"/dev/zero", "/dev/urandom", "data"}) {
    const WorldLoadResult r = LoadWorldFile(path);
    ASSERT_EQ(r.errors.size(), 1u) << path;
    EXPECT_NE(r.errors[0].message.find("not a regular file"), std::string::npos)
        << r.errors[0].ToString();
  }
}

TEST(WorldLoader, YamlSyntaxErrorHasItsPosition) {
  const auto e = Errors(Replace(kMinimal, "width: 0.9", "width: [0.9"));
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].substr(0, 4), "13:1");
  EXPECT_NE(e[0].find("YAML syntax error"), std::string::npos);
}

TEST(WorldLoader, UnknownKeySuggestsTheNearestOne) {
  const auto e = Errors(Replace(kMinimal, "    center: [4, 2]", "    centre: [4, 2]"));
  ASSERT_EQ(e.size(), 2u);
  EXPECT_EQ(e[0].substr(0, 43), "11:5: doors[0] (d1): unknown key 'centre' (");
  EXPECT_NE(e[0].find("did you mean 'center'?"), std::string::npos);
  EXPECT_EQ(e[1], "9:5: doors[0] (d1): missing required key 'center'");
}

TEST(WorldLoader, DuplicateKeyIsAnError) {
  const auto e = Errors(Replace(kMinimal, "    width: 0.9", "    width: 0.9\n    width: 1.0"));
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0], "13:5: doors[0] (d1): duplicate key 'width'");
}

TEST(WorldLoader, DoorBetweenUnknownRooms) {
  const auto e = Errors(Replace(kMinimal, "between: [a, b]", "between: [a, c]"));
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0], "9:5: door d1 is between unknown room 'c'");
}

TEST(WorldLoader, DoorNotOnTheSharedBoundary) {
  const auto e = Errors(Replace(kMinimal, "center: [4, 2]", "center: [3, 2]"));
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0],
            "9:5: door d1: center (3.00, 2.00) is not on the boundary of room a (nearest edge "
            "1.00 m away); a door must lie on the boundary its two rooms share");
}

TEST(WorldLoader, DoorWiderThanTheSharedBoundary) {
  const auto e = Errors(Replace(kMinimal, "width: 0.9", "width: 5"));
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0],
            "9:5: door d1 (width 5.00 m) does not fit on the boundary shared by rooms a and b "
            "at (4.00, 2.00)");
}

TEST(WorldLoader, SelfIntersectingPolygon) {
  const auto e = Errors(
      Replace(kMinimal, "[[0, 0], [4, 0], [4, 4], [0, 4]]", "[[0, 0], [4, 4], [4, 0], [0, 4]]"));
  ASSERT_GE(e.size(), 1u);
  EXPECT_EQ(e[0], "4:5: room a: polygon is self-intersecting (edge 0 meets edge 2)");
}

TEST(WorldLoader, DuplicateIdAcrossKinds) {
  const auto e = Errors(Replace(kMinimal, "  - id: d1", "  - id: a"));
  ASSERT_GE(e.size(), 1u);
  EXPECT_EQ(e[0], "9:5: duplicate id 'a' (already used by a room)");
}

// One id rule for worlds and tasks (world.h, IsValidId): `go near door(d-1)` cannot name a door
// whose id the task lexer does not read as one word, so such ids are refused where they are
// written.
TEST(WorldLoader, IdsFollowTheOneIdRuleOfWorldsAndTasks) {
  const std::string rule =
      "ids are an ASCII letter or '_' followed by letters, digits and '_' (task commands name "
      "them)";
  const auto hyphen = Errors(Replace(kMinimal, "  - id: d1", "  - id: d-1"));
  ASSERT_EQ(hyphen.size(), 1u);
  EXPECT_EQ(hyphen[0], "9:9: doors[0] (d-1): 'd-1' is not a valid id: " + rule);
  const auto digit = Errors(Replace(kMinimal, "  - id: a\n", "  - id: 1door\n"));
  ASSERT_GE(digit.size(), 1u);
  EXPECT_EQ(digit[0], "4:9: rooms[0] (1door): '1door' is not a valid id: " + rule);
  const auto space = Errors(Replace(kMinimal, "  - id: b\n", "  - id: \"room b\"\n"));
  ASSERT_GE(space.size(), 1u);
  EXPECT_EQ(space[0].substr(0, 40), "6:9: rooms[1] (room b): 'room b' is not ");
  const auto place = Errors(std::string(kMinimal) +
                            "places:\n  - {name: corner-1, kind: position, pose: [1, 1, 0]}\n");
  ASSERT_EQ(place.size(), 1u);
  EXPECT_EQ(place[0], "16:12: places[0] (corner-1): 'corner-1' is not a valid place name: " + rule);
  EXPECT_TRUE(IsValidId("office_101"));
  EXPECT_TRUE(IsValidId("_x9"));
  EXPECT_TRUE(IsValidId("ZONE109"));
  EXPECT_FALSE(IsValidId(""));
  EXPECT_FALSE(IsValidId("d-1"));
  EXPECT_FALSE(IsValidId("1door"));
  EXPECT_FALSE(IsValidId("caf\xc3\xa9"));
}

// Every shipped world follows the rule (they load).
TEST(WorldLoader, ShippedWorldsLoad) {
  for (const char* name : {"cim_office", "bonn_department", "hilare_room"}) {
    const WorldLoadResult r = LoadWorldFile(std::string(WORLDS_DIR) + "/" + name + ".yaml");
    EXPECT_TRUE(r.ok()) << name << ": " << FormatErrors(r.errors);
  }
}

TEST(WorldLoader, NanAndNegativeSizes) {
  const auto nan = Errors(Replace(kMinimal, "width: 0.9", "width: .nan"));
  ASSERT_EQ(nan.size(), 1u);
  EXPECT_EQ(nan[0], "12:12: doors[0] (d1): width: must be a finite number, got '.nan'");
  const auto negative = Errors(Replace(kMinimal, "width: 0.9", "width: -0.9"));
  ASSERT_EQ(negative.size(), 1u);
  EXPECT_EQ(negative[0], "12:12: doors[0] (d1): width: must be greater than 0, got -0.9");
  const std::string with_object = std::string(kMinimal) +
                                  "objects:\n"
                                  "  - id: box\n"
                                  "    kind: cuboid\n"
                                  "    pose: [2, 2, 0]\n"
                                  "    size: [0.5, -1]\n"
                                  "    height: 1\n";
  const auto size = Errors(with_object);
  ASSERT_EQ(size.size(), 1u);
  EXPECT_EQ(size[0], "19:17: objects[0] (box): size[1]: must be greater than 0, got -1");
}

TEST(WorldLoader, WrongTypeSaysWhatWasExpected) {
  const auto e = Errors(Replace(kMinimal, "polygon: [[4, 0]", "polygon: [[4, x]"));
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0], "7:19: rooms[1] (b): polygon[0].y: expected a number, got 'x'");
}

TEST(WorldLoader, OverlappingRooms) {
  const auto e = Errors(
      Replace(kMinimal, "[[4, 0], [8, 0], [8, 4], [4, 4]]", "[[3, 0], [8, 0], [8, 4], [3, 4]]"));
  ASSERT_GE(e.size(), 1u);
  EXPECT_EQ(e[0], "6:5: room b overlaps room a");
}

TEST(WorldLoader, CoordinatesBeyondTheSupportedExtent) {
  const auto e = Errors(
      Replace(kMinimal, "[[4, 0], [8, 0], [8, 4], [4, 4]]", "[[4, 0], [8e6, 0], [8, 4], [4, 4]]"));
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0],
            "6:5: room b: vertex (8000000.00, 0.00) lies beyond 500.00 m of the origin (the "
            "supported extent)");
  const auto start = Errors(Replace(kMinimal, "pose: [1, 1, 0]", "pose: [1, -501, 0]"));
  ASSERT_EQ(start.size(), 1u);
  EXPECT_EQ(start[0],
            "14:3: robot_start lies beyond 500.00 m of the origin (the supported extent)");
}

TEST(WorldLoader, RobotStartOutsideEveryRoom) {
  const auto e = Errors(Replace(kMinimal, "pose: [1, 1, 0]", "pose: [20, 1, 0]"));
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0], "14:3: robot_start (20.00, 1.00) is outside every room");
}

TEST(WorldLoader, InvalidDoorStateAndClosedOpening) {
  const auto state = Errors(Replace(kMinimal, "width: 0.9", "width: 0.9\n    state: ajar"));
  ASSERT_EQ(state.size(), 1u);
  EXPECT_EQ(state[0], "13:12: doors[0] (d1): state must be open, closed or unknown, got 'ajar'");
  const auto opening =
      Errors(Replace(kMinimal, "width: 0.9", "width: 0.9\n    kind: opening\n    state: closed"));
  ASSERT_EQ(opening.size(), 1u);
  EXPECT_EQ(opening[0], "14:12: doors[0] (d1): an opening has no door leaf and is always open");
}

TEST(WorldLoader, ExplicitWallAcrossADoorIsAnError) {
  const std::string text = std::string(kMinimal) +
                           "walls:\n"
                           "  segments:\n"
                           "    - id: w1\n"
                           "      from: [4, 0]\n"
                           "      to: [4, 4]\n";
  const auto e = Errors(text);
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0], "17:7: wall w1 blocks the opening of door d1 at (4.00, 2.00)");
}

TEST(WorldLoader, ObjectOutsideEveryRoomAndUnknownKind) {
  const std::string outside = std::string(kMinimal) +
                              "objects:\n"
                              "  - id: chair1\n"
                              "    kind: chair\n"
                              "    pose: [12, 2, 0]\n"
                              "    size: [0.5, 0.5]\n"
                              "    height: 1\n";
  const auto e = Errors(outside);
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0], "16:5: object chair1 at (12.00, 2.00) is outside every room");
  const auto kind = Errors(Replace(outside, "kind: chair", "kind: sofa"));
  ASSERT_EQ(kind.size(), 1u);
  EXPECT_EQ(kind[0].substr(0, 52), "17:11: objects[0] (chair1): kind must be one of chai");
}

TEST(WorldLoader, MissingTopLevelSections) {
  const auto e = Errors("world:\n  name: x\n");
  ASSERT_EQ(e.size(), 2u);
  EXPECT_EQ(e[0], "1:1: world file: missing required key 'rooms'");
  EXPECT_EQ(e[1], "1:1: world file: missing required key 'robot_start'");
  const auto not_a_map = Errors("- just\n- a list\n");
  ASSERT_EQ(not_a_map.size(), 1u);
  EXPECT_EQ(not_a_map[0], "1:1: world file: expected a mapping, got a list");
}

TEST(WorldLoader, DeeplyNestedInputIsRefusedNotRecursedInto) {
  const auto e = Errors("rooms: " + std::string(10000, '[') + std::string(10000, ']'));
  ASSERT_EQ(e.size(), 1u);
  EXPECT_NE(e[0].find("nested deeper than"), std::string::npos);
}

}  // namespace
}  // namespace spott_map
