// world_server: serves a world file's a priori map (SPOTT's CAD map and room/door graph) to the
// node graph and keeps the map database current as door states and sensed features arrive.
//
// Publishes (latched): map (nav_msgs/OccupancyGrid), room_door_graph, map_features,
// world_places (named places, zones and paths), world_markers. Subscribes: map_updates.
// Services: ~set_door_state, ~locate_room, ~lookup_place, ~load_world. Parameters and topics
// are documented in spott_map/README.md.
#include <cmath>

#include <ros/ros.h>
#include <spott_msgs/LoadWorld.h>
#include <spott_msgs/LocateRoom.h>
#include <spott_msgs/LookupPlace.h>
#include <spott_msgs/MapUpdate.h>
#include <spott_msgs/SetDoorState.h>
#include <spott_msgs/WorldPlaces.h>

#include "spott_map/local_map.h"
#include "spott_map/ros/conversions.h"
#include "spott_map/ros/map_update.h"
#include "spott_map/ros/world_server_parameters.h"
#include "spott_map/world_loader.h"
#include "spott_ros/input_refusals.h"
#include "spott_ros/parameter_reader.h"

namespace spott_map {
namespace {

namespace conv = ros_conversions;

class WorldServer {
 public:
  WorldServer(ros::NodeHandle& nh, ros::NodeHandle& pnh, WorldServerParameters params, World world)
      : params_(std::move(params)), world_(std::move(world)), refusals_(nh, "world_server") {
    db_ = InitialDatabase();
    map_pub_ = nh.advertise<nav_msgs::OccupancyGrid>("map", 1, true);
    graph_pub_ = nh.advertise<spott_msgs::RoomDoorGraph>("room_door_graph", 1, true);
    features_pub_ = nh.advertise<spott_msgs::MapFeatureArray>("map_features", 1, true);
    markers_pub_ = nh.advertise<visualization_msgs::MarkerArray>("world_markers", 1, true);
    places_pub_ = nh.advertise<spott_msgs::WorldPlaces>("world_places", 1, true);
    updates_sub_ = nh.subscribe("map_updates", 10, &WorldServer::OnMapUpdate, this);
    door_srv_ = pnh.advertiseService("set_door_state", &WorldServer::OnSetDoorState, this);
    locate_srv_ = pnh.advertiseService("locate_room", &WorldServer::OnLocateRoom, this);
    lookup_srv_ = pnh.advertiseService("lookup_place", &WorldServer::OnLookupPlace, this);
    load_srv_ = pnh.advertiseService("load_world", &WorldServer::OnLoadWorld, this);
    PublishAll();
    ROS_INFO("world_server: serving world '%s' (%zu rooms, %zu doors, %zu walls%s) from %s",
             world_.name.c_str(), world_.rooms.size(), world_.doors.size(), world_.walls.size(),
             params_.a_priori_map ? "" : "; no a priori map: the database starts empty",
             params_.world_file.c_str());
  }

 private:
  // The world's map, or nothing of it (~a_priori_map false); the world's extent still sizes the
  // occupancy map.
  MapDatabase InitialDatabase() const {
    return params_.a_priori_map ? MapDatabase::FromWorld(world_) : MapDatabase{};
  }

  void PublishAll() {
    const ros::Time now = ros::Time::now();
    const Box b = world_.Bounds().Inflated(0.5);
    // The latched map stays below kMaxMapCells (25 M cells, 25 MB): a world too large for
    // ~map_resolution is published coarser rather than exhausting memory.
    constexpr double kMaxMapCells = 25e6;
    const double area = (b.max.x() - b.min.x()) * (b.max.y() - b.min.y());
    double res = params_.map_resolution_m;
    if (area / (res * res) > kMaxMapCells) {
      res = std::sqrt(area / kMaxMapCells);
      ROS_WARN(
          "world_server: world '%s' is too large for ~map_resolution %.3f m; publishing the "
          "map at %.3f m",
          world_.name.c_str(), params_.map_resolution_m, res);
    }
    OccupancyRaster raster(
        Vec2(std::floor(b.min.x() / res) * res, std::floor(b.min.y() / res) * res),
        static_cast<int>(std::ceil((b.max.x() - b.min.x()) / res)) + 1,
        static_cast<int>(std::ceil((b.max.y() - b.min.y()) / res)) + 1, res);
    RasterizeDatabase(db_, 0.0, 0.05, raster);
    map_pub_.publish(conv::ToOccupancyGrid(raster, params_.frame_id, now));
    graph_pub_.publish(conv::ToMsg(db_.graph(), world_.name, params_.frame_id, now));
    features_pub_.publish(conv::ToMsg(db_.features(), params_.frame_id, now));
    markers_pub_.publish(conv::ToMarkers(db_, params_.frame_id, now));
    places_pub_.publish(conv::ToPlacesMsg(world_, params_.frame_id, now));
  }

  void OnMapUpdate(const spott_msgs::MapUpdate& update) {
    const auto before = db_.revision();
    for (const std::string& problem :
         conv::ApplyMapUpdate(update, params_.feature_tolerance_m, db_)) {
      refusals_.Refuse("map_updates", "update", problem);  // the rest of the update applies
    }
    if (db_.revision() != before) PublishAll();
  }

  bool OnSetDoorState(spott_msgs::SetDoorState::Request& req,
                      spott_msgs::SetDoorState::Response& res) {
    const auto state = conv::DoorStateFromMsg(req.state);
    if (!state) {
      res.success = false;
      res.message = "invalid state " + std::to_string(req.state) +
                    " (use spott_msgs/Door UNKNOWN=0, OPEN=1, CLOSED=2)";
    } else if (!db_.graph().FindDoor(req.door_id)) {
      res.success = false;
      res.message = "unknown door '" + req.door_id + "' in world '" + world_.name + "'";
    } else if (!db_.SetDoorState(req.door_id, *state)) {
      res.success = false;
      res.message = "door '" + req.door_id + "' is an opening and cannot be closed";
    } else {
      res.success = true;
      res.message = "door " + req.door_id + " is " + ToString(*state);
      PublishAll();
    }
    if (!res.success) ROS_WARN("world_server: set_door_state: %s", res.message.c_str());
    return true;
  }

  bool OnLocateRoom(spott_msgs::LocateRoom::Request& req, spott_msgs::LocateRoom::Response& res) {
    const Vec2 p = conv::FromPoint(req.point);
    const Room* room = p.allFinite() ? db_.graph().RoomContaining(p) : nullptr;
    res.found = room != nullptr;
    res.room_id = room ? room->id : "";
    res.message = room ? room->name
                       : "point (" + std::to_string(p.x()) + ", " + std::to_string(p.y()) +
                             ") is outside every room of world '" + world_.name + "'";
    return true;
  }

  bool OnLookupPlace(spott_msgs::LookupPlace::Request& req,
                     spott_msgs::LookupPlace::Response& res) {
    res.frame_id = params_.frame_id;
    if (const Place* p = world_.FindPlace(req.name)) {
      res.found = true;
      res.kind = "place";
      res.place = conv::ToMsg(*p);
    } else if (const Zone* z = world_.FindZone(req.name)) {
      res.found = true;
      res.kind = "zone";
      res.zone = conv::ToMsg(*z);
    } else if (const NamedPath* path = world_.FindPath(req.name)) {
      res.found = true;
      res.kind = "path";
      res.path = conv::ToMsg(*path);
    } else {
      res.found = false;
      std::string names;
      for (const Place& p : world_.places) names += (names.empty() ? "" : ", ") + p.name;
      for (const Zone& z : world_.zones) names += (names.empty() ? "" : ", ") + z.id;
      for (const NamedPath& q : world_.paths) names += (names.empty() ? "" : ", ") + q.id;
      res.message = "world '" + world_.name + "' has no place, zone or path '" + req.name +
                    "' (it has: " + (names.empty() ? "none" : names) + ")";
    }
    return true;
  }

  bool OnLoadWorld(spott_msgs::LoadWorld::Request& req, spott_msgs::LoadWorld::Response& res) {
    WorldLoadResult loaded = LoadWorldFile(req.path);
    res.success = loaded.ok();
    for (const SourceError& e : loaded.errors) res.errors.push_back(e.ToString());
    if (!loaded.ok()) {
      ROS_ERROR("world_server: refusing world %s, keeping '%s':\n%s", req.path.c_str(),
                world_.name.c_str(), FormatErrors(loaded.errors).c_str());
      return true;
    }
    world_ = std::move(*loaded.world);
    params_.world_file = req.path;
    db_ = InitialDatabase();
    PublishAll();
    ROS_INFO("world_server: now serving world '%s' from %s", world_.name.c_str(), req.path.c_str());
    return true;
  }

  WorldServerParameters params_;
  World world_;
  MapDatabase db_;
  ros::Publisher map_pub_, graph_pub_, features_pub_, markers_pub_, places_pub_;
  ros::Subscriber updates_sub_;
  ros::ServiceServer door_srv_, locate_srv_, lookup_srv_, load_srv_;
  spott_ros::InputRefusals refusals_;
};

}  // namespace
}  // namespace spott_map

int main(int argc, char** argv) {
  ros::init(argc, argv, "world_server");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  const auto params = spott_ros::ReadNodeParameters<spott_map::WorldServerParameters>(
      pnh, "world_server", spott_map::ReadParameters);
  if (!params) return 1;
  spott_map::WorldLoadResult loaded = spott_map::LoadWorldFile(params->world_file);
  for (const auto& w : loaded.warnings) ROS_WARN("world_server: %s", w.ToString().c_str());
  if (!loaded.ok()) {
    ROS_FATAL("world_server: invalid world file:\n%s",
              spott_map::FormatErrors(loaded.errors).c_str());
    return 1;
  }
  spott_map::WorldServer server(nh, pnh, *params, std::move(*loaded.world));
  ros::spin();
  return 0;
}
