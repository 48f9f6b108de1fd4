// rostest of the world_server node: latched topics, services, map updates, and bad input that
// must leave the node running with its world intact.
#include <gtest/gtest.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/ros.h>
#include <spott_msgs/LoadWorld.h>
#include <spott_msgs/LocateRoom.h>
#include <spott_msgs/MapFeatureArray.h>
#include <spott_msgs/MapUpdate.h>
#include <spott_msgs/RoomDoorGraph.h>
#include <spott_msgs/SetDoorState.h>

#include <functional>
#include <optional>

namespace {

template <class Msg>
class Latest {
 public:
  Latest(ros::NodeHandle& nh, const std::string& topic)
      : sub_(nh.subscribe(topic, 10, &Latest::On, this)) {}
  // Waits until a message satisfying `ok` arrives (or has arrived).
  bool WaitFor(const std::function<bool(const Msg&)>& ok, double seconds = 10.0) {
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
    while (ros::ok() && ros::WallTime::now() < end) {
      ros::spinOnce();
      if (msg_ && ok(*msg_)) return true;
      ros::WallDuration(0.01).sleep();
    }
    return false;
  }
  const Msg& msg() const { return *msg_; }

 private:
  void On(const Msg& m) { msg_ = m; }
  ros::Subscriber sub_;
  std::optional<Msg> msg_;
};

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
  EXPECT_EQ(graph.msg().world, "two_rooms");
  EXPECT_EQ(graph.msg().header.frame_id, "map");
  EXPECT_EQ(graph.msg().rooms.size(), 3u);
  EXPECT_EQ(graph.msg().doors.size(), 3u);
  Latest<nav_msgs::OccupancyGrid> map(nh_, "map");
  ASSERT_TRUE(map.WaitFor([](const auto& m) { return !m.data.empty(); }));
  EXPECT_NEAR(map.msg().info.resolution, 0.1, 1e-6);
  // The world spans 10 x 6 m plus 0.5 m on each side.
  EXPECT_NEAR(map.msg().info.width * 0.1, 11.0, 0.25);
  Latest<spott_msgs::MapFeatureArray> features(nh_, "map_features");
  ASSERT_TRUE(features.WaitFor([](const auto& f) { return !f.features.empty(); }));
  EXPECT_EQ(features.msg().features.size(), 9u);  // the generated walls
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
  EXPECT_EQ(graph.msg().world, "two_rooms");
}

TEST_F(WorldServerTest, MapUpdatesAddNewFeaturesOnce) {
  Latest<spott_msgs::MapFeatureArray> features(nh_, "map_features");
  ASSERT_TRUE(features.WaitFor([](const auto& f) { return !f.features.empty(); }));
  const std::size_t before = features.msg().features.size();
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
  EXPECT_EQ(features.msg().features.size(), before + 1);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "world_server_rostest");
  return RUN_ALL_TESTS();
}
