// Goal points respect the map (task_command.h, TaskMap): on the test world
// test/data/goal_regions.yaml, each case where the geometry alone puts the goal inside the
// padding of a wall, in the wrong room, beyond a wall or inside a table, and the refusals of
// regions the robot cannot reach. Padding 0.325 m = the Nomad's radius 0.225 m + 0.1 m of
// localization error (the planners' default).
#include <gtest/gtest.h>

#include <cmath>

#include "spott_map/map_database.h"
#include "spott_map/world_loader.h"
#include "spott_tr_plus/task_command.h"

namespace spott_tr_plus {
namespace {

constexpr double kPadding = 0.325;

class TaskMapTest : public ::testing::Test {
 protected:
  void SetUp() override {
    spott_map::WorldLoadResult r = spott_map::LoadWorldFile(TEST_DATA_DIR "/goal_regions.yaml");
    ASSERT_TRUE(r.ok()) << spott_map::FormatErrors(r.errors);
    world_ = *r.world;
    db_ = spott_map::MapDatabase::FromWorld(world_);
    // The objects as the controller records them once sensed (or as an a priori map holds
    // them): rectangles labelled by kind.
    for (const spott_map::WorldObject& o : world_.objects) {
      spott_map::MapFeature f;
      f.id = o.id;
      f.type = spott_map::FeatureType::kRectangle;
      f.label = spott_map::ToString(o.kind);
      f.pose = o.pose;
      f.size_x = o.size_x;
      f.size_y = o.size_y;
      ASSERT_TRUE(db_.AddFeature(f));
    }
    map_.database = &db_;
    map_.padding_m = kPadding;
    resolve_ = MapPlaceResolver(db_, world_.places);
  }

  TaskInterpretResult Run(const std::string& text, double rx, double ry, bool with_map = true) {
    const TaskParseResult p = ParseTaskCommand(text);
    EXPECT_TRUE(p.ok()) << FormatDiagnostics(p.diagnostics);
    if (!p.ok()) return {};
    return with_map ? InterpretTask(*p.command, rx, ry, 0, params_, map_, resolve_)
                    : InterpretTask(*p.command, rx, ry, 0, params_, resolve_);
  }
  GoalRegion Goal(const std::string& text, double rx, double ry, bool with_map = true) {
    const TaskInterpretResult r = Run(text, rx, ry, with_map);
    EXPECT_TRUE(r.ok()) << text << ": " << FormatDiagnostics(r.diagnostics);
    if (!r.ok() || !r.interpretation->goal) return GoalRegion{};
    return *r.interpretation->goal;
  }
  // Distance from p to the nearest obstacle of the map (walls, objects, closed doors).
  double Clearance(double x, double y) const {
    double best = 1e9;
    for (const auto& f : db_.features()) best = std::min(best, f.DistanceTo({x, y}));
    for (const auto& d : db_.graph().doors()) {
      if (d.state == spott_map::DoorState::kClosed) {
        best = std::min(best, spott_map::DistancePointSegment({x, y}, d.opening) - 0.025);
      }
    }
    return best;
  }
  std::string RoomAt(double x, double y) const {
    const spott_map::Room* r = db_.graph().RoomContaining({x, y});
    return r ? r->id : "";
  }

  spott_map::World world_;
  spott_map::MapDatabase db_;
  TaskMap map_;
  PlaceResolver resolve_;
  TaskInterpretationParameters params_;
};

TEST_F(TaskMapTest, NearADoorTheGoalKeepsThePaddingFromTheWall) {
  // The robot in the hall nearly in line with the office's wall: the geometric point, 0.5 m
  // from the door on the robot's side, is 0.11 m from the wall's face.
  const GoalRegion geometric = Goal("go near door(d_office)", 0.3, 1.7, false);
  EXPECT_LT(Clearance(geometric.goal_x, geometric.goal_y), 0.15);
  const GoalRegion g = Goal("go near door(d_office)", 0.3, 1.7);
  EXPECT_GE(Clearance(g.goal_x, g.goal_y), kPadding);
  EXPECT_TRUE(g.Contains(g.goal_x, g.goal_y));
  EXPECT_EQ(g.rooms, (std::vector<std::string>{"hall", "office"}));
  EXPECT_EQ(RoomAt(g.goal_x, g.goal_y), "hall");  // the robot's side, nearest the preferred point
  // Moved no farther than needed: its whole 0.05 m cell out of the padding below the wall
  // (y = 1.95 - 0.325 = 1.625), i.e. the first or second cell centre below 1.625.
  EXPECT_LE(g.goal_y, 1.6 + 1e-9);
  EXPECT_GE(g.goal_y, 1.55 - 1e-9);
  EXPECT_NEAR(g.goal_x, geometric.goal_x, 0.05);
  EXPECT_GT(g.free_area_m2, 1.0);
}

TEST_F(TaskMapTest, WithoutAPrioriMapTheGoalIsTheGeometrys) {
  // SPOTT's Experiment 1: nothing known but what the sonar added (here one wall segment); no
  // room holds the robot, and the goal point is where the command puts it.
  spott_map::MapDatabase sensed;
  spott_map::MapFeature f;
  f.id = "sonar_1";
  f.type = spott_map::FeatureType::kRectangle;
  f.label = "wall";
  f.pose = {3.0, 1.0, 0.0};
  f.size_x = 2.0;
  f.size_y = 0.1;
  ASSERT_TRUE(sensed.AddFeature(f));
  const TaskMap map{&sensed, kPadding};
  const TaskParseResult p = ParseTaskCommand("go to point(5, 2)");
  ASSERT_TRUE(p.ok());
  const TaskInterpretResult r = InterpretTask(*p.command, 1, 1, 0, params_, map, resolve_);
  ASSERT_TRUE(r.ok()) << FormatDiagnostics(r.diagnostics);
  ASSERT_TRUE(r.interpretation->goal);
  const GoalRegion geometric = Goal("go to point(5, 2)", 1, 1, false);
  EXPECT_DOUBLE_EQ(r.interpretation->goal->goal_x, geometric.goal_x);
  EXPECT_DOUBLE_EQ(r.interpretation->goal->goal_y, geometric.goal_y);
  EXPECT_NEAR(std::hypot(geometric.goal_x - 5, geometric.goal_y - 2), 0.0, 1e-9);  // "to": on it
  // With the building's rooms the same robot outside every room is refused (nothing to fit in).
  EXPECT_FALSE(InterpretTask(*p.command, -50, -50, 0, params_, map_, resolve_).ok());
}

TEST_F(TaskMapTest, AlongAHallwayStaysInTheHallway) {
  // The geometry alone took `along` as beside the hallway's long axis: in the closed room.
  const GoalRegion beside = Goal("go alongside hallway(hall)", 1, 1, false);
  EXPECT_NE(RoomAt(beside.goal_x, beside.goal_y), "hall");
  // along a hallway: its length, inside it, to the end away from the robot.
  const GoalRegion g = Goal("go along hallway(hall)", 1, 1);
  EXPECT_EQ(RoomAt(g.goal_x, g.goal_y), "hall");
  EXPECT_EQ(g.rooms, std::vector<std::string>{"hall"});
  EXPECT_NEAR(g.goal_x, 11.0, 1e-9);  // 12 m long: 1 m (near) short of the far end
  EXPECT_NEAR(g.goal_y, 1.0, 1e-9);
  // From the other end it goes the other way.
  EXPECT_NEAR(Goal("go along hallway(hall)", 11.5, 1).goal_x, 1.0, 1e-9);
}

TEST_F(TaskMapTest, BehindADeskAgainstAWallIsRefusedNotPutInTheNextOffice) {
  // desk_1 stands 5 cm from the office's back wall; behind it (seen from the robot in the
  // office) the geometry alone chose a point in office2, beyond the wall.
  const GoalRegion geometric = Goal("go behind desk(desk_1)", 1.5, 3.5, false);
  EXPECT_EQ(RoomAt(geometric.goal_x, geometric.goal_y), "office2");
  const TaskInterpretResult r = Run("go behind desk(desk_1)", 1.5, 3.5);
  ASSERT_FALSE(r.ok());
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].ToString(),
            "task:1:11: the goal region behind desk in office lies all within obstacles or "
            "their padding of 0.325 m (robot radius + localization error)");
}

TEST_F(TaskMapTest, BehindAFreeDeskTheGoalKeepsThePadding) {
  // desk_2 (1.2 x 0.6 m at (2, 8)) seen from (2, 7): behind it is y > 8.3; the geometric point
  // 0.3 m past it is inside the padding, the fitted one just outside.
  const GoalRegion g = Goal("go behind desk(desk_2)", 2, 7);
  EXPECT_EQ(RoomAt(g.goal_x, g.goal_y), "office2");
  EXPECT_GE(Clearance(g.goal_x, g.goal_y), kPadding);
  EXPECT_GT(g.goal_y, 8.3 + kPadding);
  EXPECT_LT(g.goal_y, 8.3 + kPadding + 0.1);
  EXPECT_NEAR(g.goal_x, 2.0, 0.05);
  EXPECT_TRUE(g.Contains(g.goal_x, g.goal_y));
}

TEST_F(TaskMapTest, InAKitchenTheGoalIsBesideTheTableNotInIt) {
  const GoalRegion geometric = Goal("go in room(kitchen)", 1, 1, false);
  EXPECT_NEAR(geometric.goal_x, 10, 1e-9);  // the room's centre: under the table
  EXPECT_NEAR(geometric.goal_y, 4, 1e-9);
  const GoalRegion g = Goal("go in room(kitchen)", 1, 1);
  EXPECT_EQ(RoomAt(g.goal_x, g.goal_y), "kitchen");
  EXPECT_GE(Clearance(g.goal_x, g.goal_y), kPadding);
  // The nearest free point: across the table's short half-width (0.5 m) plus the padding.
  EXPECT_NEAR(std::fabs(g.goal_y - 4.0), 0.5 + kPadding, 0.06);
  EXPECT_NEAR(g.goal_x, 10.0, 0.05);
}

TEST_F(TaskMapTest, AGoalBehindAClosedDoorIsRefusedWithTheReason) {
  const TaskInterpretResult r = Run("go in room(closed_room)", 1, 1);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics[0].ToString(),
            "task:1:7: the goal region in room in closed_room cannot be reached from the robot "
            "in hall: no open door leads there");
  // Near the closed door, the hall's side is a fine goal.
  const GoalRegion near = Goal("go near door(d_closed)", 1, 1);
  EXPECT_EQ(RoomAt(near.goal_x, near.goal_y), "hall");
  EXPECT_GE(Clearance(near.goal_x, near.goal_y), kPadding);
}

TEST_F(TaskMapTest, ObstaclesThatCutARegionOffAreNamedAsTheReason) {
  // A partition across the office's door opening, recorded in the map: the office is reachable
  // through the graph (its door is open) but not past the partition.
  spott_map::MapFeature wall =
      spott_map::MakeSegment("partition", {{1.2, 1.8}, {2.8, 1.8}}, "partition", 0.05);
  ASSERT_TRUE(db_.AddFeature(wall));
  const TaskInterpretResult r = Run("go in room(office)", 6, 1);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics[0].ToString(),
            "task:1:7: the goal region in room in office cannot be reached from the robot in "
            "hall: known obstacles cut its free part off");
}

TEST_F(TaskMapTest, PathGoalsAndNamedPlacesAreFittedToo) {
  // go to door(d_kitchen), from the hall: at the door, on the robot's side, clear of the jambs.
  const GoalRegion g = Goal("go to door(d_kitchen)", 10, 1);
  EXPECT_GE(Clearance(g.goal_x, g.goal_y), kPadding);
  EXPECT_EQ(g.rooms, (std::vector<std::string>{"hall", "kitchen"}));
  // A place of the world file, by name.
  const GoalRegion p = Goal("go near point(kitchen_door)", 1, 1);
  EXPECT_TRUE(p.Contains(p.goal_x, p.goal_y));
  EXPECT_NEAR(std::hypot(p.goal_x - 10, p.goal_y - 1.4), 0.5, 1e-6);  // `near`/2 toward robot
  EXPECT_EQ(Run("go near point(nowhere)", 1, 1).diagnostics[0].ToString(),
            "task:1:9: point 'nowhere' is not in the map");
}

TEST_F(TaskMapTest, ARobotOutsideTheFreeSpaceIsTold) {
  const TaskInterpretResult r = Run("go in room(kitchen)", 30, 30);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics[0].ToString().substr(0, 44),
            "task:1:1: the robot at (30, 30) has no free ");
}

TEST_F(TaskMapTest, TheResolverFindsRoomsDoorsFeaturesAndPlacesById) {
  Target room;
  room.word = "room";
  room.name = "kitchen";
  const auto k = resolve_(room);
  ASSERT_TRUE(k);
  EXPECT_EQ(k->map_id, "kitchen");
  EXPECT_NEAR(k->x, 10, 1e-9);
  EXPECT_NEAR(k->y, 4, 1e-9);
  EXPECT_EQ(k->polygon.size(), 4u);
  Target door;
  door.word = "door";
  door.name = "d_office2";
  const auto d = resolve_(door);
  ASSERT_TRUE(d);
  EXPECT_NEAR(d->x, 3.4, 1e-9);
  EXPECT_NEAR(d->half_length, 0.45, 1e-9);
  Target desk;
  desk.word = "desk";
  desk.name = "table";
  const auto t = resolve_(desk);
  ASSERT_TRUE(t);
  EXPECT_NEAR(t->half_length, 0.8, 1e-9);
  EXPECT_NEAR(t->half_width, 0.5, 1e-9);
  desk.name = "nothing";
  EXPECT_FALSE(resolve_(desk));
}

}  // namespace
}  // namespace spott_tr_plus
