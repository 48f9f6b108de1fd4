// Greedy exploration without a map beyond the window (SPOTT's GO across a building never seen):
// the reachable border cell nearest the goal, and the local planner that falls back on it only
// when the sensed obstacles cut the robot off from the goal.
#include "spott_harmonic_planner/border_exploration.h"

#include <gtest/gtest.h>

#include "spott_harmonic_planner/local_planner.h"
#include "test_maps.h"

namespace spott_harmonic_planner {
namespace {

using spott_map::Pose2;
using testing_maps::Block;
using testing_maps::EmptyRaster;

TEST(NearestReachableBorderCell, IsTheBorderCellNearestTheTargetThatTheStartReaches) {
  // 20 x 20 cells of 1 m; a wall across at y = 10 with a gap at x = 15..16.
  auto r = EmptyRaster(20, 20);
  Block(r, 0, 10, 14, 10);
  Block(r, 17, 10, 19, 10);
  PotentialField field(FieldOptions{});
  field.SetOccupancy(r);
  // The raster's outer cells are the border ring. From the south half, a target far north-west:
  // the gap leads north, so the north border's cell nearest the target (its west end, beside
  // the corner, which no inner cell touches) is reachable.
  auto c = NearestReachableBorderCell(field, Vec2(5.5, 3.5), Vec2(-30.0, 60.0));
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->x(), 1.5, 1e-9);
  EXPECT_NEAR(c->y(), 19.5, 1e-9);
  // The gap closed: only the south half's border is reached; of it, the west side's top cell.
  Block(r, 15, 10, 16, 10);
  field.SetOccupancy(r);
  c = NearestReachableBorderCell(field, Vec2(5.5, 3.5), Vec2(-30.0, 60.0));
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->x(), 0.5, 1e-9);
  EXPECT_NEAR(c->y(), 9.5, 1e-9);
}

TEST(NearestReachableBorderCell, NoneFromAnEnclosedPocketABlockedStartOrOutside) {
  auto r = EmptyRaster(20, 20);
  Block(r, 5, 5, 9, 5);
  Block(r, 5, 9, 9, 9);
  Block(r, 5, 5, 5, 9);
  Block(r, 9, 5, 9, 9);
  PotentialField field(FieldOptions{});
  field.SetOccupancy(r);
  EXPECT_FALSE(NearestReachableBorderCell(field, Vec2(7.5, 7.5), Vec2(50.0, 50.0)));
  EXPECT_FALSE(NearestReachableBorderCell(field, Vec2(5.5, 7.5), Vec2(50.0, 50.0)));
  EXPECT_FALSE(NearestReachableBorderCell(field, Vec2(-5.0, 7.5), Vec2(50.0, 50.0)));
  EXPECT_TRUE(NearestReachableBorderCell(field, Vec2(2.5, 2.5), Vec2(50.0, 50.0)));
}

void AddBox(spott_map::MapDatabase& db, const std::string& id, double x0, double y0, double x1,
            double y1) {
  ASSERT_TRUE(db.AddFeature(
      testing_maps::BoxFeature(id, x0, y0, x1, y1, spott_map::FeatureSource::kSensed)));
}

// A hallway sensed along the robot (walls at y = -1.2 and 1.2 over the whole 7 m window), a
// goal far to the north-east beyond its north wall: the straight projection lies beyond the
// wall. `door_at`: a 1.4 m gap in the north wall there, or none.
spott_map::MapDatabase Hallway(std::optional<double> door_at) {
  spott_map::MapDatabase db;
  AddBox(db, "south", -4.0, -1.3, 4.0, -1.2);
  if (door_at) {
    AddBox(db, "north_w", -4.0, 1.2, *door_at - 0.7, 1.3);
    AddBox(db, "north_e", *door_at + 0.7, 1.2, 4.0, 1.3);
  } else {
    AddBox(db, "north", -4.0, 1.2, 4.0, 1.3);
  }
  return db;
}

PlannerParameters Exploring(bool explore) {
  PlannerParameters p;
  p.window.window_size_m = 7.0;
  p.window.resolution_m = 0.1;
  p.sweeps_per_cycle = 200;
  p.explore_when_cut_off = explore;
  return p;
}

TEST(Exploration, AGoalCutOffBeyondASensedWallIsSoughtAlongTheReachableBorderNearestIt) {
  const Vec2 goal(6.0, 9.0);
  // Without exploration the projection is beyond the wall: no way, and steering says so.
  LocalPlanner plain(Exploring(false));
  plain.SetMap(Hallway(std::nullopt));
  plain.CorrectPose(Pose2{0.0, 0.0, 0.0});
  plain.SetGoal(goal);
  for (int i = 0; i < 5; ++i) plain.Cycle();
  EXPECT_FALSE(plain.status().exploring);
  EXPECT_FALSE(plain.Steer(SpeedMode::kSlowly, std::nullopt).valid);

  // With it: along the hallway to its east end (nearer the goal than the west end).
  LocalPlanner planner(Exploring(true));
  planner.SetMap(Hallway(std::nullopt));
  planner.CorrectPose(Pose2{0.0, 0.0, 0.0});
  planner.SetGoal(goal);
  for (int i = 0; i < 5; ++i) planner.Cycle();
  ASSERT_TRUE(planner.status().has_goal) << planner.status().problem;
  EXPECT_TRUE(planner.status().exploring);
  EXPECT_TRUE(planner.status().goal_on_border);
  const SteeringCommand cmd = planner.Steer(SpeedMode::kSlowly, std::nullopt);
  ASSERT_TRUE(cmd.valid) << cmd.reason;
  EXPECT_NEAR(cmd.heading, 0.0, 0.3);
  const auto path = planner.PredictedPath();
  ASSERT_TRUE(path.reached_goal);
  EXPECT_GT(path.points.back().x(), 3.3);
  EXPECT_LT(std::abs(path.points.back().y()), 1.2);
}

TEST(Exploration, AReachableProjectionIsFollowedAsBeforeThroughTheSensedDoor) {
  // A door in the north wall west of the robot: the projection (north-east, beyond the wall)
  // is reachable through it, so the planner does not explore and the path goes through it.
  LocalPlanner planner(Exploring(true));
  planner.SetMap(Hallway(-1.5));
  planner.CorrectPose(Pose2{0.0, 0.0, 0.0});
  planner.SetGoal(Vec2(6.0, 9.0));
  for (int i = 0; i < 5; ++i) planner.Cycle();
  ASSERT_TRUE(planner.status().has_goal) << planner.status().problem;
  EXPECT_FALSE(planner.status().exploring);
  const auto path = planner.PredictedPath();
  ASSERT_TRUE(path.reached_goal);
  EXPECT_GT(path.points.back().y(), 3.3);  // the window's north border
  bool through_door = false;
  for (const Vec2& p : path.points)
    through_door |= std::abs(p.y() - 1.25) < 0.1 && std::abs(p.x() + 1.5) < 0.5;
  EXPECT_TRUE(through_door);
}

TEST(Exploration, TheDoorSensedClosedLaterTurnsTheRobotBackAlongTheHallway) {
  LocalPlanner planner(Exploring(true));
  planner.SetMap(Hallway(-1.5));
  planner.CorrectPose(Pose2{0.0, 0.0, 0.0});
  planner.SetGoal(Vec2(6.0, 9.0));
  for (int i = 0; i < 5; ++i) planner.Cycle();
  ASSERT_FALSE(planner.status().exploring);
  // The robot senses a leaf across the doorway (a map update, same window): cut off now.
  auto db = Hallway(-1.5);
  AddBox(db, "leaf", -2.3, 1.2, -0.7, 1.3);
  planner.SetMap(db);
  for (int i = 0; i < 5; ++i) planner.Cycle();
  EXPECT_TRUE(planner.status().exploring);
  const SteeringCommand cmd = planner.Steer(SpeedMode::kSlowly, std::nullopt);
  ASSERT_TRUE(cmd.valid) << cmd.reason;
  EXPECT_NEAR(cmd.heading, 0.0, 0.3);
}

TEST(Exploration, AnEnclosedRobotIsStillSaidToBeCutOff) {
  spott_map::MapDatabase db = Hallway(std::nullopt);
  AddBox(db, "west", -1.5, -1.3, -1.4, 1.3);
  AddBox(db, "east", 1.4, -1.3, 1.5, 1.3);
  LocalPlanner planner(Exploring(true));
  planner.SetMap(db);
  planner.CorrectPose(Pose2{0.0, 0.0, 0.0});
  planner.SetGoal(Vec2(6.0, 9.0));
  for (int i = 0; i < 5; ++i) planner.Cycle();
  EXPECT_FALSE(planner.status().exploring);
  const SteeringCommand cmd = planner.Steer(SpeedMode::kSlowly, std::nullopt);
  EXPECT_FALSE(cmd.valid);
}

}  // namespace
}  // namespace spott_harmonic_planner
