// rostest of the world_server node: latched topics, services, map updates, and bad input that
// must leave the node running with its world intact.
#include <gtest/gtest.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/ros.h>
#include <spott_msgs/LoadWorld.h>
#include <spott_msgs/LocateRoom.h>
#include <spott_msgs/LookupPlace.h>
#include <spott_msgs/MapFeatureArray.h>
#include <spott_msgs/MapUpdate.h>
#include <spott_msgs/RoomDoorGraph.h>
#include <spott_msgs/SetDoorState.h>
#include <spott_msgs/WorldPlaces.h>

#include "spott_ros/testing/node_process.h"

#include <functional>
#include <optional>

namespace {

using spott_ros::testing::Latest;

uint8_t DoorState(const spott_msgs::RoomDoorGraph& g, const std::string& id) {
  for (const auto& d : g.doors) {
    if (d.id == id) return d.state;
  }
  return 255;
}

class WorldServerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(ros::service::waitForService("/world_server/set_door_state", ros::Duration(20)));
  }
  ros::NodeHandle nh_;
};

TEST_F(WorldServerTest, PublishesTheWorldLatched) {
  Latest<spott_msgs::RoomDoorGraph> graph(nh_, "room_door_graph");
  ASSERT_TRUE(graph.WaitFor([](const auto& g) { return !g.rooms.empty(); }));
  EXPECT_EQ(graph.msg()->world, "two_rooms");
  EXPECT_EQ(graph.msg()->header.frame_id, "map");
  EXPECT_EQ(graph.msg()->rooms.size(), 3u);
  EXPECT_EQ(graph.msg()->doors.size(), 3u);
  Latest<nav_msgs::OccupancyGrid> map(nh_, "map");
  ASSERT_TRUE(map.WaitFor([](const auto& m) { return !m.data.empty(); }));
  EXPECT_NEAR(map.msg()->info.resolution, 0.1, 1e-6);
  // The world spans 10 x 6 m plus 0.5 m on each side.
  EXPECT_NEAR(map.msg()->info.width * 0.1, 11.0, 0.25);
  Latest<spott_msgs::MapFeatureArray> features(nh_, "map_features");
  ASSERT_TRUE(features.WaitFor([](const auto& f) { return !f.features.empty(); }));
  EXPECT_EQ(features.msg()->features.size(), 9u);  // the generated walls
}

TEST_F(WorldServerTest, DoorStateServiceChangesTheGraphAndRefusesUnknownDoors) {
  Latest<spott_msgs::RoomDoorGraph> graph(nh_, "room_door_graph");
  spott_msgs::SetDoorState srv;
  srv.request.door_id = "d_office";
  srv.request.state = spott_msgs::Door::CLOSED;
  ASSERT_TRUE(ros::service::call("/world_server/set_door_state", srv));
  EXPECT_TRUE(srv.response.success) << srv.response.message;
  EXPECT_TRUE(graph.WaitFor(
      [](const auto& g) { return DoorState(g, "d_office") == spott_msgs::Door::CLOSED; }));
  srv.request.door_id = "d_attic";
  ASSERT_TRUE(ros::service::call("/world_server/set_door_state", srv));
  EXPECT_FALSE(srv.response.success);
  EXPECT_EQ(srv.response.message, "unknown door 'd_attic' in world 'two_rooms'");
  srv.request.door_id = "d_office";
  srv.request.state = 7;
  ASSERT_TRUE(ros::service::call("/world_server/set_door_state", srv));
  EXPECT_FALSE(srv.response.success);
  EXPECT_NE(srv.response.message.find("invalid state 7"), std::string::npos);
  srv.request.state = spott_msgs::Door::OPEN;
  ASSERT_TRUE(ros::service::call("/world_server/set_door_state", srv));
  EXPECT_TRUE(srv.response.success);
}

TEST_F(WorldServerTest, LocatesRooms) {
  spott_msgs::LocateRoom srv;
  srv.request.point.x = 9;
  srv.request.point.y = 5;
  ASSERT_TRUE(ros::service::call("/world_server/locate_room", srv));
  EXPECT_TRUE(srv.response.found);
  EXPECT_EQ(srv.response.room_id, "lab");
  srv.request.point.x = 50;
  ASSERT_TRUE(ros::service::call("/world_server/locate_room", srv));
  EXPECT_FALSE(srv.response.found);
  EXPECT_NE(srv.response.message.find("outside every room"), std::string::npos);
}

TEST_F(WorldServerTest, BadWorldIsRefusedWithItsPositionAndTheOldWorldIsKept) {
  ros::NodeHandle pnh("~");
  std::string bad;
  ASSERT_TRUE(pnh.getParam("bad_world_file", bad));
  spott_msgs::LoadWorld srv;
  srv.request.path = bad;
  ASSERT_TRUE(ros::service::call("/world_server/load_world", srv));
  EXPECT_FALSE(srv.response.success);
  ASSERT_EQ(srv.response.errors.size(), 1u);
  EXPECT_NE(srv.response.errors[0].find("bad_door.yaml:10:5: door d1: center (3.00, 2.00)"),
            std::string::npos)
      << srv.response.errors[0];
  // Still serving the old world.
  spott_msgs::LocateRoom locate;
  locate.request.point.x = 9;
  locate.request.point.y = 5;
  ASSERT_TRUE(ros::service::call("/world_server/locate_room", locate));
  EXPECT_EQ(locate.response.room_id, "lab");
  Latest<spott_msgs::RoomDoorGraph> graph(nh_, "room_door_graph");
  ASSERT_TRUE(graph.WaitFor([](const auto& g) { return !g.rooms.empty(); }));
  EXPECT_EQ(graph.msg()->world, "two_rooms");
}

TEST_F(WorldServerTest, MapUpdatesAddNewFeaturesOnce) {
  Latest<spott_msgs::MapFeatureArray> features(nh_, "map_features");
  ASSERT_TRUE(features.WaitFor([](const auto& f) { return !f.features.empty(); }));
  const std::size_t before = features.msg()->features.size();
  ros::Publisher pub = nh_.advertise<spott_msgs::MapUpdate>("map_updates", 10);
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(10);
  while (pub.getNumSubscribers() == 0 && ros::WallTime::now() < end)
    ros::WallDuration(0.01).sleep();
  spott_msgs::MapUpdate u;
  spott_msgs::MapFeature partition;
  partition.type = spott_msgs::MapFeature::LINE_SEGMENT;
  partition.label = "partition";
  partition.points.resize(2);
  partition.points[0].x = 5;
  partition.points[0].y = 1;
  partition.points[1].x = 6;
  partition.points[1].y = 1;
  u.added = {partition, partition};  // the second is already there when it arrives
  pub.publish(u);
  ASSERT_TRUE(
      features.WaitFor([before](const auto& f) { return f.features.size() == before + 1; }));
  pub.publish(u);  // again: nothing new
  ros::WallDuration(0.5).sleep();
  ros::spinOnce();
  EXPECT_EQ(features.msg()->features.size(), before + 1);
}

TEST_F(WorldServerTest, ServesPlacesZonesAndPathsByName) {
  Latest<spott_msgs::WorldPlaces> places(nh_, "world_places");
  ASSERT_TRUE(places.WaitFor([](const auto& p) { return !p.places.empty(); }));
  EXPECT_EQ(places.msg()->header.frame_id, "map");
  EXPECT_EQ(places.msg()->world, "two_rooms");
  ASSERT_EQ(places.msg()->zones.size(), 1u);
  ASSERT_EQ(places.msg()->paths.size(), 1u);
  for (const std::string& name :
       {places.msg()->places[0].name, places.msg()->zones[0].id, places.msg()->paths[0].id}) {
    spott_msgs::LookupPlace srv;
    srv.request.name = name;
    ASSERT_TRUE(ros::service::call("/world_server/lookup_place", srv));
    EXPECT_TRUE(srv.response.found) << name;
    EXPECT_EQ(srv.response.frame_id, "map");
  }
  spott_msgs::LookupPlace zone;
  zone.request.name = places.msg()->zones[0].id;
  ASSERT_TRUE(ros::service::call("/world_server/lookup_place", zone));
  EXPECT_EQ(zone.response.kind, "zone");
  EXPECT_EQ(zone.response.zone.polygon.points.size(), places.msg()->zones[0].polygon.points.size());
  spott_msgs::LookupPlace none;
  none.request.name = "nowhere";
  ASSERT_TRUE(ros::service::call("/world_server/lookup_place", none));
  EXPECT_FALSE(none.response.found);
  EXPECT_NE(none.response.message.find(places.msg()->places[0].name), std::string::npos)
      << none.response.message;
}

TEST(WorldServerNode, AnUnknownParameterStopsTheNodeNamingIt) {
  const auto run = spott_ros::testing::RunNode(WORLD_SERVER_EXE,
                                               "__name:=bad_world_server _map_resolution:=0.1");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("~map_resolution is not a parameter"), std::string::npos) << run.output;
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "world_server_rostest");
  return RUN_ALL_TESTS();
}
