// Round trips between the core types and ROS messages (no master needed).
#include "spott_map/ros/conversions.h"

#include <cmath>

#include <gtest/gtest.h>

#include "spott_map/ros/map_update.h"
#include "spott_map/world_loader.h"

namespace spott_map {
namespace {

namespace conv = ros_conversions;

World TestWorld() {
  auto r = LoadWorldFile(std::string(TEST_DATA_DIR) + "/two_rooms.yaml");
  EXPECT_TRUE(r.ok()) << FormatErrors(r.errors);
  return *r.world;
}

TEST(Conversions, FeatureRoundTripKeepsEverything) {
  MapFeature f;
  f.id = "desk_7";
  f.type = FeatureType::kRectangle;
  f.source = FeatureSource::kSensed;
  f.label = "desk";
  f.pose = Pose2{1.5, -2.0, 0.7};
  f.size_x = 1.6;
  f.size_y = 0.8;
  f.size_z = 0.75;
  f.attributes["colour"] = "grey";
  std::string error;
  auto back = conv::FromMsg(conv::ToMsg(f), &error);
  ASSERT_TRUE(back) << error;
  EXPECT_EQ(back->id, f.id);
  EXPECT_EQ(back->type, f.type);
  EXPECT_EQ(back->source, f.source);
  EXPECT_EQ(back->label, f.label);
  EXPECT_NEAR(back->pose.yaw, 0.7, 1e-12);
  EXPECT_DOUBLE_EQ(back->size_z, 0.75);
  EXPECT_EQ(back->attributes.at("colour"), "grey");
  const MapFeature s = MakeSegment("w", Segment{Vec2(0, 1), Vec2(2, 3)}, "wall", 0.1);
  auto seg = conv::FromMsg(conv::ToMsg(s), &error);
  ASSERT_TRUE(seg);
  EXPECT_DOUBLE_EQ(seg->points[1].y(), 3.0);
  EXPECT_DOUBLE_EQ(seg->size_y, 0.1);
}

TEST(Conversions, MalformedFeaturesAreRefusedWithAReason) {
  spott_msgs::MapFeature m = conv::ToMsg(MakePoint("p", Vec2(1, 1), ""));
  m.points.clear();
  std::string error;
  EXPECT_FALSE(conv::FromMsg(m, &error));
  EXPECT_EQ(error, "map feature 'p': a point needs 1 point");
  m = conv::ToMsg(MakeSegment("s", Segment{Vec2(0, 0), Vec2(1, 0)}, ""));
  m.points[1].x = std::nan("");
  EXPECT_FALSE(conv::FromMsg(m, &error));
  EXPECT_EQ(error, "map feature 's': a point is not finite or beyond 10 km");
  m.points[1].x = 2e4;
  EXPECT_FALSE(conv::FromMsg(m, &error));
  m.type = 42;
  EXPECT_FALSE(conv::FromMsg(m, &error));
  EXPECT_EQ(error, "map feature 's': unknown type 42");
}

// A 1e9 m feature was accepted into the map database and republished (issue 21).
TEST(Conversions, FeaturesBeyondTheSizeRuleAreRefused) {
  MapFeature f;
  f.id = "crate";
  f.type = FeatureType::kRectangle;
  f.pose = Pose2{3.0, 8.0, 0.0};
  f.size_x = f.size_y = 0.5;
  std::string error;
  spott_msgs::MapFeature m = conv::ToMsg(f);
  ASSERT_TRUE(conv::FromMsg(m, &error)) << error;
  m.size.x = 1e9;
  EXPECT_FALSE(conv::FromMsg(m, &error));
  EXPECT_EQ(error, "map feature 'crate': size over 1 km");
  m.size.x = conv::kMaxSizeM;  // the limit itself is a (very large) building
  EXPECT_TRUE(conv::FromMsg(m, &error)) << error;
  m.pose.position.x = 1e300;
  EXPECT_FALSE(conv::FromMsg(m, &error));
  EXPECT_EQ(error, "map feature 'crate': pose beyond 10 km of the origin");
}

TEST(Conversions, GraphRoundTripKeepsRoomsDoorsAndStates) {
  const RoomDoorGraph g(TestWorld());
  const auto msg = conv::ToMsg(g, "two_rooms", "map", ros::Time(0));
  EXPECT_EQ(msg.world, "two_rooms");
  ASSERT_EQ(msg.doors.size(), 3u);
  EXPECT_EQ(msg.doors[1].state, spott_msgs::Door::CLOSED);
  std::string error;
  auto back = conv::FromMsg(msg, &error);
  ASSERT_TRUE(back) << error;
  ASSERT_EQ(back->rooms().size(), 3u);
  EXPECT_EQ(back->FindDoor("d_lab")->state, DoorState::kClosed);
  EXPECT_EQ(back->FindDoor("d_office_lab")->state, DoorState::kUnknown);
  EXPECT_EQ(back->RoomContaining(Vec2(9, 5))->id, "lab");
  EXPECT_NEAR(back->FindDoor("d_office")->opening.Length(), 1.0, 1e-6);
  auto broken = msg;
  broken.doors[0].room_b = "attic";
  EXPECT_FALSE(conv::FromMsg(broken, &error));
  EXPECT_NE(error.find("attic"), std::string::npos);
}

TEST(Conversions, PlacesZonesAndPathsThatAreNotFiniteOrTooFewAreRefusedByField) {
  spott_msgs::WorldPlaces places;
  spott_msgs::NamedPath path;
  path.points.resize(1);
  path.points[0].x = 1.0;
  places.paths = {path};
  spott_msgs::Zone zone;
  zone.polygon.points.resize(3);
  places.zones = {zone};
  places.places.resize(1);
  EXPECT_EQ(conv::PlacesProblem(places), "");
  places.places[0].pose.theta = NAN;
  EXPECT_EQ(conv::PlacesProblem(places), "places[0].pose: not finite or beyond 10 km");
  places.places[0].pose.theta = 0.0;
  places.paths[0].has_final_heading = true;
  places.paths[0].final_heading = INFINITY;
  EXPECT_EQ(conv::PlacesProblem(places), "paths[0].final_heading: not finite");
  places.paths[0].has_final_heading = false;
  places.paths[0].points.clear();
  EXPECT_EQ(conv::PlacesProblem(places), "paths[0].points: empty");
  places.paths[0].points.resize(1);
  places.zones[0].polygon.points[2].x = 2e4;  // 20 km
  EXPECT_EQ(conv::PlacesProblem(places), "zones[0].polygon: not finite or beyond 10 km");
  places.zones[0].polygon.points.pop_back();
  EXPECT_EQ(conv::PlacesProblem(places), "zones[0].polygon: fewer than 3 points");
}

TEST(Conversions, OccupancyGridRoundTrip) {
  OccupancyRaster r(Vec2(-1, 2), 4, 3, 0.5);
  r.Mark(1, 2, Cell::kObstacle);
  r.Mark(2, 0, Cell::kPadding);
  const auto grid = conv::ToOccupancyGrid(r, "map", ros::Time(0));
  EXPECT_EQ(grid.info.width, 4u);
  EXPECT_EQ(grid.data[2 * 4 + 1], 100);
  EXPECT_EQ(grid.data[2], 99);
  EXPECT_EQ(grid.data[0], 0);
  std::string error;
  auto back = conv::FromOccupancyGrid(grid, 100, false, &error);
  ASSERT_TRUE(back) << error;
  EXPECT_EQ(back->at(1, 2), Cell::kObstacle);
  EXPECT_EQ(back->at(2, 0), Cell::kFree);  // 99 is below the threshold of 100
  EXPECT_DOUBLE_EQ(back->origin().y(), 2.0);
  auto bad = grid;
  bad.data.pop_back();
  EXPECT_FALSE(conv::FromOccupancyGrid(bad, 65, false, &error));
}

TEST(Conversions, MapUpdateAddsOnlyNewFeaturesAndReportsBadParts) {
  MapDatabase db = MapDatabase::FromWorld(TestWorld());
  const std::size_t walls = db.features().size();
  spott_msgs::MapUpdate u;
  u.added.push_back(conv::ToMsg(MakeSegment("", Segment{Vec2(1, 0.02), Vec2(3, 0.0)}, "")));
  u.added.push_back(conv::ToMsg(MakeSegment("", Segment{Vec2(5, 1), Vec2(6, 1)}, "partition")));
  spott_msgs::DoorState open;
  open.door_id = "d_lab";
  open.state = spott_msgs::Door::OPEN;
  spott_msgs::DoorState bogus;
  bogus.door_id = "d_attic";
  bogus.state = spott_msgs::Door::OPEN;
  u.doors = {open, bogus};
  u.removed = {"no_such_feature"};
  const auto problems = conv::ApplyMapUpdate(u, 0.1, db);
  EXPECT_EQ(db.features().size(), walls + 1);
  EXPECT_EQ(db.graph().FindDoor("d_lab")->state, DoorState::kOpen);
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_EQ(problems[0], "cannot remove unknown feature 'no_such_feature'");
  EXPECT_NE(problems[1].find("d_attic"), std::string::npos);
}

TEST(Conversions, MapUpdateReplacesAFeatureByItsOverlappingSuccessor) {
  // The controller refines a sensed wall: one update removes sonar_1 and adds sonar_2, nearly
  // the same segment. Applied add-first, sonar_2 was dropped as sonar_1's duplicate and then
  // sonar_1 removed: the copies lost the wall (a cim_office demo drove into a crate this way).
  MapDatabase db = MapDatabase::FromWorld(TestWorld());
  const std::size_t walls = db.features().size();
  spott_msgs::MapUpdate first;
  first.added.push_back(conv::ToMsg(MakeSegment("sonar_1", Segment{Vec2(5, 1), Vec2(6, 1)}, "")));
  ASSERT_TRUE(conv::ApplyMapUpdate(first, 0.1, db).empty());
  ASSERT_EQ(db.features().size(), walls + 1);
  spott_msgs::MapUpdate refined;
  refined.added.push_back(
      conv::ToMsg(MakeSegment("sonar_2", Segment{Vec2(5, 1.01), Vec2(6, 1.01)}, "")));
  refined.removed = {"sonar_1"};
  EXPECT_TRUE(conv::ApplyMapUpdate(refined, 0.1, db).empty());
  EXPECT_EQ(db.features().size(), walls + 1);
  EXPECT_EQ(db.FindFeature("sonar_1"), nullptr);
  EXPECT_NE(db.FindFeature("sonar_2"), nullptr);
}

TEST(Conversions, MapUpdateMirrorsTheOwnersSensedFeatures) {
  // The owner sends infrared_1 lying on its sonar_2 (it de-duplicates by its own rules), then
  // refines sonar_2 away: the copy keeps infrared_1 as the owner does.
  MapDatabase db = MapDatabase::FromWorld(TestWorld());
  const std::size_t walls = db.features().size();
  spott_msgs::MapUpdate u;
  u.added.push_back(conv::ToMsg(MakeSegment("sonar_2", Segment{Vec2(5, 1), Vec2(6, 1)}, "")));
  u.added.push_back(
      conv::ToMsg(MakeSegment("infrared_1", Segment{Vec2(5.2, 1), Vec2(5.8, 1.01)}, "")));
  ASSERT_TRUE(conv::ApplyMapUpdate(u, 0.1, db).empty());
  EXPECT_EQ(db.features().size(), walls + 2);
  spott_msgs::MapUpdate refined;
  refined.removed = {"sonar_2"};
  ASSERT_TRUE(conv::ApplyMapUpdate(refined, 0.1, db).empty());
  EXPECT_NE(db.FindFeature("infrared_1"), nullptr);
}

TEST(Conversions, MarkersColourDoorsByState) {
  const MapDatabase db = MapDatabase::FromWorld(TestWorld());
  const auto markers = conv::ToMarkers(db, "map", ros::Time(0));
  int doors = 0;
  for (const auto& m : markers.markers) {
    if (m.ns != "doors") continue;
    ++doors;
    if (m.id == 1) {
      EXPECT_GT(m.color.r, 0.8f);  // d_lab is closed: red
    } else if (m.id == 0) {
      EXPECT_GT(m.color.g, 0.6f);  // d_office is open: green
    }
  }
  EXPECT_EQ(doors, 3);
}

}  // namespace
}  // namespace spott_map
