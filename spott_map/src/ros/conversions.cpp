#include "spott_map/ros/conversions.h"

#include <cmath>

#include <tf2/LinearMath/Quaternion.h>

namespace spott_map::ros_conversions {

namespace {

// Finite and within the size rule (conversions.h).
bool Plausible(const Vec2& p) {
  return std::abs(p.x()) <= kMaxCoordinateM && std::abs(p.y()) <= kMaxCoordinateM;
}
bool PlausibleSize(double v) { return v >= 0.0 && v <= kMaxSizeM; }

geometry_msgs::Quaternion YawQuaternion(double yaw) {
  tf2::Quaternion q;
  q.setRPY(0, 0, yaw);
  geometry_msgs::Quaternion m;
  m.x = q.x();
  m.y = q.y();
  m.z = q.z();
  m.w = q.w();
  return m;
}

double QuaternionYaw(const geometry_msgs::Quaternion& q) {
  return std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
}

}  // namespace

geometry_msgs::Point ToPoint(const Vec2& p, double z) {
  geometry_msgs::Point m;
  m.x = p.x();
  m.y = p.y();
  m.z = z;
  return m;
}

// Marker heights (m) above the map plane, so that rviz draws doors over walls over room
// outlines over the occupancy grid instead of letting them flicker in one plane.
constexpr double kRoomZ = 0.02;
constexpr double kWallZ = 0.04;
constexpr double kDoorZ = 0.06;

Vec2 FromPoint(const geometry_msgs::Point& p) { return Vec2(p.x, p.y); }

geometry_msgs::Pose2D ToPose2D(const Pose2& p) {
  geometry_msgs::Pose2D m;
  m.x = p.x;
  m.y = p.y;
  m.theta = p.yaw;
  return m;
}

Pose2 FromPose2D(const geometry_msgs::Pose2D& p) { return Pose2{p.x, p.y, p.theta}; }

geometry_msgs::Polygon ToPolygon(const Polygon& polygon) {
  geometry_msgs::Polygon m;
  for (const Vec2& p : polygon) {
    geometry_msgs::Point32 q;
    q.x = static_cast<float>(p.x());
    q.y = static_cast<float>(p.y());
    m.points.push_back(q);
  }
  return m;
}

std::uint8_t ToMsg(DoorState state) {
  switch (state) {
    case DoorState::kOpen:
      return spott_msgs::Door::OPEN;
    case DoorState::kClosed:
      return spott_msgs::Door::CLOSED;
    case DoorState::kUnknown:
      break;
  }
  return spott_msgs::Door::UNKNOWN;
}

std::optional<DoorState> DoorStateFromMsg(std::uint8_t state) {
  switch (state) {
    case spott_msgs::Door::OPEN:
      return DoorState::kOpen;
    case spott_msgs::Door::CLOSED:
      return DoorState::kClosed;
    case spott_msgs::Door::UNKNOWN:
      return DoorState::kUnknown;
    default:
      return std::nullopt;
  }
}

spott_msgs::MapFeature ToMsg(const MapFeature& f) {
  spott_msgs::MapFeature m;
  m.id = f.id;
  m.type = static_cast<std::uint8_t>(f.type);
  m.source = f.source == FeatureSource::kCad ? spott_msgs::MapFeature::SOURCE_CAD
                                             : spott_msgs::MapFeature::SOURCE_SENSED;
  m.label = f.label;
  for (const Vec2& p : f.points) m.points.push_back(ToPoint(p));
  m.pose.position.x = f.pose.x;
  m.pose.position.y = f.pose.y;
  m.pose.orientation = YawQuaternion(f.pose.yaw);
  m.size.x = f.size_x;
  m.size.y = f.size_y;
  m.size.z = f.size_z;
  for (const auto& [key, value] : f.attributes) {
    spott_msgs::Attribute a;
    a.key = key;
    a.value = value;
    m.attributes.push_back(a);
  }
  return m;
}

std::optional<MapFeature> FromMsg(const spott_msgs::MapFeature& m, std::string* error) {
  const auto fail = [&](const std::string& why) -> std::optional<MapFeature> {
    if (error) *error = "map feature '" + m.id + "': " + why;
    return std::nullopt;
  };
  if (m.type > spott_msgs::MapFeature::GEON_ELLIPSOID) {
    return fail("unknown type " + std::to_string(m.type));
  }
  MapFeature f;
  f.id = m.id;
  f.type = static_cast<FeatureType>(m.type);
  f.source =
      m.source == spott_msgs::MapFeature::SOURCE_CAD ? FeatureSource::kCad : FeatureSource::kSensed;
  f.label = m.label;
  if (m.points.size() > kMaxPoints)
    return fail("more than " + std::to_string(kMaxPoints) + " points");
  for (const auto& p : m.points) {
    f.points.push_back(FromPoint(p));
    if (!Plausible(f.points.back())) return fail("a point is not finite or beyond 10 km");
  }
  if (f.type == FeatureType::kPoint && f.points.size() != 1) return fail("a point needs 1 point");
  if (f.type == FeatureType::kLineSegment && f.points.size() != 2) {
    return fail("a line segment needs 2 points");
  }
  f.pose = Pose2{m.pose.position.x, m.pose.position.y, QuaternionYaw(m.pose.orientation)};
  f.size_x = m.size.x;
  f.size_y = m.size.y;
  f.size_z = m.size.z;
  if (!std::isfinite(f.pose.x) || !std::isfinite(f.pose.y) || !std::isfinite(f.pose.yaw) ||
      !std::isfinite(f.size_x) || !std::isfinite(f.size_y) || !std::isfinite(f.size_z)) {
    return fail("pose or size is not finite");
  }
  if (f.size_x < 0 || f.size_y < 0 || f.size_z < 0) return fail("negative size");
  if (!Plausible(Vec2(f.pose.x, f.pose.y))) return fail("pose beyond 10 km of the origin");
  if (!PlausibleSize(f.size_x) || !PlausibleSize(f.size_y) || !PlausibleSize(f.size_z))
    return fail("size over 1 km");
  const bool area = f.type != FeatureType::kPoint && f.type != FeatureType::kLineSegment;
  if (area && (f.size_x <= 0 || f.size_y <= 0)) return fail("an area feature needs a size");
  for (const auto& a : m.attributes) f.attributes[a.key] = a.value;
  return f;
}

spott_msgs::MapFeatureArray ToMsg(const std::vector<MapFeature>& features,
                                  const std::string& frame_id, const ros::Time& stamp) {
  spott_msgs::MapFeatureArray m;
  m.header.frame_id = frame_id;
  m.header.stamp = stamp;
  for (const MapFeature& f : features) m.features.push_back(ToMsg(f));
  return m;
}

spott_msgs::Room ToMsg(const Room& room) {
  spott_msgs::Room m;
  m.id = room.id;
  m.name = room.name;
  m.kind = room.kind == RoomKind::kHallway ? spott_msgs::Room::HALLWAY : spott_msgs::Room::ROOM;
  m.polygon = ToPolygon(room.polygon);
  m.centre = ToPoint(Centroid(room.polygon));
  return m;
}

spott_msgs::Door ToMsg(const Door& door) {
  spott_msgs::Door m;
  m.id = door.id;
  m.room_a = door.room_a;
  m.room_b = door.room_b;
  m.state = ToMsg(door.state);
  m.width = door.width;
  m.centre = ToPoint(door.center);
  m.opening = {ToPoint(door.opening.a), ToPoint(door.opening.b)};
  m.kind = door.kind == DoorKind::kOpening ? spott_msgs::Door::KIND_OPENING
                                           : spott_msgs::Door::KIND_DOOR;
  return m;
}

spott_msgs::RoomDoorGraph ToMsg(const RoomDoorGraph& graph, const std::string& world_name,
                                const std::string& frame_id, const ros::Time& stamp) {
  spott_msgs::RoomDoorGraph m;
  m.header.frame_id = frame_id;
  m.header.stamp = stamp;
  m.world = world_name;
  for (const Room& r : graph.rooms()) m.rooms.push_back(ToMsg(r));
  for (const Door& d : graph.doors()) m.doors.push_back(ToMsg(d));
  return m;
}

std::optional<RoomDoorGraph> FromMsg(const spott_msgs::RoomDoorGraph& m, std::string* error) {
  const auto fail = [&](const std::string& why) -> std::optional<RoomDoorGraph> {
    if (error) *error = why;
    return std::nullopt;
  };
  std::vector<Room> rooms;
  for (const auto& r : m.rooms) {
    Room room;
    room.id = r.id;
    room.name = r.name;
    room.kind = r.kind == spott_msgs::Room::HALLWAY ? RoomKind::kHallway : RoomKind::kRoom;
    for (const auto& p : r.polygon.points) {
      room.polygon.emplace_back(p.x, p.y);
      if (!Plausible(room.polygon.back()))
        return fail("room " + r.id + ": point is not finite or beyond 10 km");
    }
    if (room.polygon.size() < 3) return fail("room " + r.id + ": fewer than 3 points");
    rooms.push_back(room);
  }
  std::vector<Door> doors;
  for (const auto& d : m.doors) {
    Door door;
    door.id = d.id;
    door.room_a = d.room_a;
    door.room_b = d.room_b;
    door.kind = d.kind == spott_msgs::Door::KIND_OPENING ? DoorKind::kOpening : DoorKind::kDoor;
    auto state = DoorStateFromMsg(d.state);
    if (!state) return fail("door " + d.id + ": invalid state " + std::to_string(d.state));
    door.state = *state;
    door.width = d.width;
    door.center = FromPoint(d.centre);
    if (d.opening.size() != 2) return fail("door " + d.id + ": opening needs 2 points");
    door.opening = Segment{FromPoint(d.opening[0]), FromPoint(d.opening[1])};
    if (!Plausible(door.center) || !Plausible(door.opening.a) || !Plausible(door.opening.b) ||
        !PlausibleSize(door.width)) {
      return fail("door " + d.id + ": value is not finite, beyond 10 km, or a width over 1 km");
    }
    doors.push_back(door);
  }
  try {
    return RoomDoorGraph(std::move(rooms), std::move(doors));
  } catch (const std::invalid_argument& e) {
    return fail(e.what());
  }
}

namespace {
std::string Indexed(const char* field, std::size_t i) {
  return std::string(field) + "[" + std::to_string(i) + "]";
}
}  // namespace

std::string PlacesProblem(const spott_msgs::WorldPlaces& places) {
  for (std::size_t i = 0; i < places.places.size(); ++i) {
    const auto& p = places.places[i].pose;
    if (!Plausible(Vec2(p.x, p.y)) || !std::isfinite(p.theta))
      return Indexed("places", i) + ".pose: not finite or beyond 10 km";
  }
  for (std::size_t i = 0; i < places.zones.size(); ++i) {
    const auto& points = places.zones[i].polygon.points;
    if (points.size() < 3) return Indexed("zones", i) + ".polygon: fewer than 3 points";
    for (const auto& q : points)
      if (!Plausible(Vec2(q.x, q.y)))
        return Indexed("zones", i) + ".polygon: not finite or beyond 10 km";
  }
  for (std::size_t i = 0; i < places.paths.size(); ++i) {
    const auto& path = places.paths[i];
    if (path.points.empty()) return Indexed("paths", i) + ".points: empty";
    for (const auto& q : path.points)
      if (!Plausible(Vec2(q.x, q.y)))
        return Indexed("paths", i) + ".points: not finite or beyond 10 km";
    if (path.has_final_heading && !std::isfinite(path.final_heading))
      return Indexed("paths", i) + ".final_heading: not finite";
  }
  return "";
}

spott_msgs::NamedPlace ToMsg(const Place& place) {
  spott_msgs::NamedPlace m;
  m.name = place.name;
  m.kind = place.kind;
  m.pose = ToPose2D(place.pose);
  return m;
}

spott_msgs::Zone ToMsg(const Zone& zone) {
  spott_msgs::Zone m;
  m.id = zone.id;
  m.polygon = ToPolygon(zone.polygon);
  return m;
}

spott_msgs::NamedPath ToMsg(const NamedPath& path) {
  spott_msgs::NamedPath m;
  m.id = path.id;
  for (const Vec2& p : path.points) m.points.push_back(ToPoint(p));
  m.has_final_heading = path.final_yaw.has_value();
  m.final_heading = path.final_yaw.value_or(0.0);
  return m;
}

spott_msgs::WorldPlaces ToPlacesMsg(const World& world, const std::string& frame_id,
                                    const ros::Time& stamp) {
  spott_msgs::WorldPlaces m;
  m.header.frame_id = frame_id;
  m.header.stamp = stamp;
  m.world = world.name;
  for (const Place& p : world.places) m.places.push_back(ToMsg(p));
  for (const Zone& z : world.zones) m.zones.push_back(ToMsg(z));
  for (const NamedPath& p : world.paths) m.paths.push_back(ToMsg(p));
  return m;
}

nav_msgs::OccupancyGrid MakeGrid(const Vec2& origin, int width, int height, double resolution_m,
                                 const std::string& frame_id, const ros::Time& stamp) {
  nav_msgs::OccupancyGrid g;
  g.header.frame_id = frame_id;
  g.header.stamp = stamp;
  g.info.map_load_time = stamp;
  g.info.resolution = static_cast<float>(resolution_m);
  g.info.width = static_cast<std::uint32_t>(width);
  g.info.height = static_cast<std::uint32_t>(height);
  g.info.origin.position.x = origin.x();
  g.info.origin.position.y = origin.y();
  g.info.origin.orientation.w = 1.0;
  g.data.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), -1);
  return g;
}

nav_msgs::OccupancyGrid ToOccupancyGrid(const OccupancyRaster& raster, const std::string& frame_id,
                                        const ros::Time& stamp) {
  nav_msgs::OccupancyGrid g = MakeGrid(raster.origin(), raster.width(), raster.height(),
                                       raster.resolution(), frame_id, stamp);
  for (std::size_t i = 0; i < raster.cells().size(); ++i) {
    switch (raster.cells()[i]) {
      case Cell::kFree:
        g.data[i] = 0;
        break;
      case Cell::kPadding:
        g.data[i] = 99;
        break;
      case Cell::kObstacle:
        g.data[i] = 100;
        break;
    }
  }
  return g;
}

std::optional<OccupancyRaster> FromOccupancyGrid(const nav_msgs::OccupancyGrid& g,
                                                 int occupied_threshold, bool unknown_is_obstacle,
                                                 std::string* error) {
  const std::size_t cells = static_cast<std::size_t>(g.info.width) * g.info.height;
  if (g.data.size() != cells || g.info.width > 100000 || g.info.height > 100000) {
    if (error) {
      *error = "occupancy grid has " + std::to_string(g.data.size()) + " cells for " +
               std::to_string(g.info.width) + " x " + std::to_string(g.info.height);
    }
    return std::nullopt;
  }
  if (!(g.info.resolution > 0.0f) || !std::isfinite(g.info.origin.position.x) ||
      !std::isfinite(g.info.origin.position.y)) {
    if (error) *error = "occupancy grid resolution must be > 0 and its origin finite";
    return std::nullopt;
  }
  OccupancyRaster raster(Vec2(g.info.origin.position.x, g.info.origin.position.y),
                         static_cast<int>(g.info.width), static_cast<int>(g.info.height),
                         g.info.resolution);
  for (std::size_t i = 0; i < cells; ++i) {
    const int v = g.data[i];
    const bool occupied = v < 0 ? unknown_is_obstacle : v >= occupied_threshold;
    if (occupied) {
      raster.Mark(static_cast<int>(i % g.info.width), static_cast<int>(i / g.info.width),
                  Cell::kObstacle);
    }
  }
  return raster;
}

visualization_msgs::MarkerArray ToMarkers(const MapDatabase& db, const std::string& frame_id,
                                          const ros::Time& stamp) {
  visualization_msgs::MarkerArray array;
  const auto make = [&](const std::string& ns, int id, int type) {
    visualization_msgs::Marker m = MakeMarker(ns, id, type, frame_id, stamp);
    m.scale.x = 0.05;  // line width
    return m;
  };
  // Clear markers of an earlier, larger world first.
  visualization_msgs::Marker clear;
  clear.action = visualization_msgs::Marker::DELETEALL;
  clear.header.frame_id = frame_id;
  array.markers.push_back(clear);

  visualization_msgs::Marker cad = make("walls", 0, visualization_msgs::Marker::LINE_LIST);
  cad.scale.x = 0.1;
  cad.color = Colour(0.1f, 0.1f, 0.1f);
  visualization_msgs::Marker sensed = make("sensed", 0, visualization_msgs::Marker::LINE_LIST);
  sensed.color = Colour(0.1f, 0.3f, 0.9f);
  int object_id = 0;
  for (const MapFeature& f : db.features()) {
    auto& target = f.source == FeatureSource::kCad ? cad : sensed;
    if (f.type == FeatureType::kLineSegment) {
      target.points.push_back(ToPoint(f.points[0], kWallZ));
      target.points.push_back(ToPoint(f.points[1], kWallZ));
    } else if (f.type == FeatureType::kPoint) {
      auto m = make("sensed_points", object_id++, visualization_msgs::Marker::SPHERE);
      m.pose.position = ToPoint(f.points[0]);
      m.scale.x = m.scale.y = m.scale.z = 0.1;
      m.color = sensed.color;
      array.markers.push_back(m);
    } else {
      const Polygon outline = f.Outline();
      for (std::size_t i = 0; i < outline.size(); ++i) {
        target.points.push_back(ToPoint(outline[i], kWallZ));
        target.points.push_back(ToPoint(outline[(i + 1) % outline.size()], kWallZ));
      }
    }
  }
  if (!cad.points.empty()) array.markers.push_back(cad);
  if (!sensed.points.empty()) array.markers.push_back(sensed);

  int id = 0;
  for (const Room& room : db.graph().rooms()) {
    auto outline = make("rooms", id, visualization_msgs::Marker::LINE_STRIP);
    outline.scale.x = 0.03;
    outline.color = room.kind == RoomKind::kHallway ? Colour(0.8f, 0.7f, 0.2f, 0.8f)
                                                    : Colour(0.3f, 0.5f, 0.8f, 0.8f);
    for (const Vec2& p : room.polygon) outline.points.push_back(ToPoint(p, kRoomZ));
    outline.points.push_back(ToPoint(room.polygon.front(), kRoomZ));
    array.markers.push_back(outline);
    auto label = make("room_names", id++, visualization_msgs::Marker::TEXT_VIEW_FACING);
    label.pose.position = ToPoint(Centroid(room.polygon));
    label.pose.position.z = 0.5;
    label.scale.z = 0.4;
    label.color = Colour(0.2f, 0.2f, 0.2f);
    label.text = room.name;
    array.markers.push_back(label);
  }
  id = 0;
  for (const Door& door : db.graph().doors()) {
    auto m = make("doors", id++, visualization_msgs::Marker::LINE_LIST);
    m.scale.x = 0.15;
    m.color = door.kind == DoorKind::kOpening    ? Colour(0.6f, 0.6f, 0.6f, 0.6f)
              : door.state == DoorState::kOpen   ? Colour(0.1f, 0.7f, 0.2f)
              : door.state == DoorState::kClosed ? Colour(0.9f, 0.1f, 0.1f)
                                                 : Colour(1.0f, 0.55f, 0.0f);
    m.points = {ToPoint(door.opening.a, kDoorZ), ToPoint(door.opening.b, kDoorZ)};
    array.markers.push_back(m);
  }
  return array;
}

}  // namespace spott_map::ros_conversions
