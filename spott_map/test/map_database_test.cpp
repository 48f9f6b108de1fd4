#include "spott_map/map_database.h"

#include <gtest/gtest.h>

#include "test_worlds.h"

namespace spott_map {
namespace {

using Outcome = MapDatabase::AddResult::Outcome;

TEST(MapDatabase, FromWorldHoldsTheCadWallsButNotTheObjects) {
  const World w = testing::TwoRoomsWorld();
  const MapDatabase db = MapDatabase::FromWorld(w);
  EXPECT_EQ(db.features().size(), w.walls.size());
  for (const MapFeature& f : db.features()) {
    EXPECT_EQ(f.label, "wall");
    EXPECT_EQ(f.source, FeatureSource::kCad);
    EXPECT_EQ(f.type, FeatureType::kLineSegment);
  }
  EXPECT_EQ(db.FindFeature("desk1"), nullptr) << "objects are not in the CAD map";
  EXPECT_EQ(db.graph().rooms().size(), 3u);
}

TEST(MapDatabase, SensedSegmentAlongAWallIsNotAddedTwice) {
  MapDatabase db = MapDatabase::FromWorld(testing::TwoRoomsWorld());
  const std::size_t before = db.features().size();
  const std::uint64_t revision = db.revision();
  // A sonar view of part of the south wall (y = 0), 3 cm off.
  const auto r =
      db.AddSensedFeature(MakeSegment("", Segment{Vec2(3, 0.03), Vec2(6, -0.02)}, ""), 0.05);
  EXPECT_EQ(r.outcome, Outcome::kAlreadyPresent);
  EXPECT_EQ(db.FindFeature(r.id)->label, "wall");
  EXPECT_EQ(db.features().size(), before);
  EXPECT_EQ(db.revision(), revision);
}

TEST(MapDatabase, SensedFeatureWithALabelRelabelsTheExistingOne) {
  MapDatabase db;
  ASSERT_TRUE(db.AddFeature(MakeSegment("s1", Segment{Vec2(0, 0), Vec2(0, 1)}, "")));
  const auto r =
      db.AddSensedFeature(MakeSegment("", Segment{Vec2(0.01, 0.1), Vec2(0, 0.9)}, "door"), 0.05);
  EXPECT_EQ(r.outcome, Outcome::kRelabelled);
  EXPECT_EQ(r.id, "s1");
  EXPECT_EQ(db.FindFeature("s1")->label, "door");
  // The geometry is not fused: the existing segment keeps its ends.
  EXPECT_DOUBLE_EQ(db.FindFeature("s1")->points[1].y(), 1.0);
  EXPECT_EQ(db.features().size(), 1u);
}

TEST(MapDatabase, NewFeaturesAreAddedWithGeneratedIds) {
  MapDatabase db;
  const auto a = db.AddSensedFeature(MakePoint("", Vec2(1, 1), "chair"), 0.1);
  const auto b = db.AddSensedFeature(MakePoint("", Vec2(1.5, 1), "chair"), 0.1);
  const auto c = db.AddSensedFeature(MakePoint("", Vec2(1.05, 1), ""), 0.1);
  EXPECT_EQ(a.outcome, Outcome::kAdded);
  EXPECT_EQ(b.outcome, Outcome::kAdded);
  EXPECT_NE(a.id, b.id);
  EXPECT_EQ(c.outcome, Outcome::kAlreadyPresent);
  EXPECT_EQ(c.id, a.id);
  EXPECT_EQ(db.FindFeature(a.id)->source, FeatureSource::kSensed);
  EXPECT_EQ(db.features().size(), 2u);
}

TEST(MapDatabase, RectangleTurnedHalfWayRoundIsTheSameRectangle) {
  MapDatabase db;
  MapFeature desk;
  desk.type = FeatureType::kRectangle;
  desk.pose = Pose2{2, 3, 0.2};
  desk.size_x = 1.6;
  desk.size_y = 0.8;
  desk.label = "desk";
  ASSERT_EQ(db.AddSensedFeature(desk, 0.05).outcome, Outcome::kAdded);
  MapFeature turned = desk;
  turned.pose.yaw = 0.2 + M_PI;
  EXPECT_EQ(db.AddSensedFeature(turned, 0.05).outcome, Outcome::kAlreadyPresent);
  MapFeature quarter = desk;
  quarter.pose.yaw = 0.2 + M_PI / 2;
  std::swap(quarter.size_x, quarter.size_y);
  EXPECT_EQ(db.AddSensedFeature(quarter, 0.05).outcome, Outcome::kAlreadyPresent);
  MapFeature bigger = desk;
  bigger.size_x = 2.0;
  EXPECT_EQ(db.AddSensedFeature(bigger, 0.05).outcome, Outcome::kAdded);
}

TEST(MapDatabase, DoorStateChangesBumpTheRevision) {
  MapDatabase db = MapDatabase::FromWorld(testing::TwoRoomsWorld());
  const auto before = db.revision();
  EXPECT_TRUE(db.SetDoorState("d_office", DoorState::kClosed));
  EXPECT_GT(db.revision(), before);
  EXPECT_EQ(db.graph().FindDoor("d_office")->state, DoorState::kClosed);
  EXPECT_FALSE(db.SetDoorState("nope", DoorState::kClosed));
}

TEST(MapDatabase, HoldsRobotPoseAndTask) {
  MapDatabase db;
  EXPECT_FALSE(db.robot_pose());
  db.SetRobotPose(Pose2{1, 2, 0.5});
  db.SetTask("go to door(3, 2)");
  EXPECT_DOUBLE_EQ(db.robot_pose()->y, 2.0);
  EXPECT_EQ(db.task(), "go to door(3, 2)");
}

}  // namespace
}  // namespace spott_map
