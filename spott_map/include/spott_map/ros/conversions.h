// Conversions between the spott_map core types and ROS messages. The only spott_map code that
// includes ROS headers (with the world server node).
#pragma once

#include <optional>
#include <string>

#include <geometry_msgs/Point.h>
#include <geometry_msgs/Polygon.h>
#include <geometry_msgs/Pose2D.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/time.h>
#include <spott_msgs/Door.h>
#include <spott_msgs/MapFeature.h>
#include <spott_msgs/MapFeatureArray.h>
#include <spott_msgs/NamedPath.h>
#include <spott_msgs/NamedPlace.h>
#include <spott_msgs/Room.h>
#include <spott_msgs/RoomDoorGraph.h>
#include <spott_msgs/WorldPlaces.h>
#include <spott_msgs/Zone.h>
#include <visualization_msgs/MarkerArray.h>

#include "spott_map/map_database.h"
#include "spott_map/occupancy_raster.h"
#include "spott_map/world.h"
#include "spott_ros/markers.h"

namespace spott_map::ros_conversions {

geometry_msgs::Point ToPoint(const Vec2& p, double z = 0.0);  ///< z (m) above the map plane
/// An occupancy grid with header and info filled and `width` x `height` cells of -1 (unknown);
/// origin (m) is the corner of cell (0, 0) in `frame_id`.
nav_msgs::OccupancyGrid MakeGrid(const Vec2& origin, int width, int height, double resolution_m,
                                 const std::string& frame_id, const ros::Time& stamp);
// The start of every marker (spott_ros/markers.h), for the conversions' callers.
using spott_ros::Colour;
using spott_ros::MakeMarker;
Vec2 FromPoint(const geometry_msgs::Point& p);
geometry_msgs::Pose2D ToPose2D(const Pose2& p);
Pose2 FromPose2D(const geometry_msgs::Pose2D& p);
geometry_msgs::Polygon ToPolygon(const Polygon& polygon);

std::uint8_t ToMsg(DoorState state);
/// nullopt for a value that is not a spott_msgs/Door state constant.
std::optional<DoorState> DoorStateFromMsg(std::uint8_t state);

/// The rule for sizes in map messages: a coordinate lies within kMaxCoordinateM of the map
/// origin and a size (or door width) is at most kMaxSizeM; anything else is a corrupt message,
/// not a building. A feature has at most kMaxPoints points.
constexpr double kMaxCoordinateM = 1e4;
constexpr double kMaxSizeM = 1e3;
constexpr std::size_t kMaxPoints = 100000;

spott_msgs::MapFeature ToMsg(const MapFeature& feature);
/// Checks the type, the number of points, that every number is finite and within the size rule
/// above; on failure returns nullopt and says why in `error`.
std::optional<MapFeature> FromMsg(const spott_msgs::MapFeature& msg, std::string* error);
spott_msgs::MapFeatureArray ToMsg(const std::vector<MapFeature>& features,
                                  const std::string& frame_id, const ros::Time& stamp);

spott_msgs::Room ToMsg(const Room& room);
spott_msgs::Door ToMsg(const Door& door);
spott_msgs::RoomDoorGraph ToMsg(const RoomDoorGraph& graph, const std::string& world_name,
                                const std::string& frame_id, const ros::Time& stamp);
/// Rebuilds the graph; nullopt (with `error`) when a door names an unknown room, a polygon has
/// fewer than three points, or a value is not finite or outside the size rule.
std::optional<RoomDoorGraph> FromMsg(const spott_msgs::RoomDoorGraph& msg, std::string* error);

/// Why world_server's places cannot be taken, as "field: why", or "": a pose, a zone's point or
/// a path's point that is not finite or lies beyond 10 km, a zone of fewer than 3 points, an
/// empty path, a final heading that is not finite.
std::string PlacesProblem(const spott_msgs::WorldPlaces& places);
spott_msgs::NamedPlace ToMsg(const Place& place);
spott_msgs::Zone ToMsg(const Zone& zone);
spott_msgs::NamedPath ToMsg(const NamedPath& path);
/// Every named place, zone and path of `world`.
spott_msgs::WorldPlaces ToPlacesMsg(const World& world, const std::string& frame_id,
                                    const ros::Time& stamp);

/// Free cells 0, padding 99 (like costmap_2d's inscribed cost), obstacles 100.
nav_msgs::OccupancyGrid ToOccupancyGrid(const OccupancyRaster& raster, const std::string& frame_id,
                                        const ros::Time& stamp);
/// Cells at or above `occupied_threshold` (0..100) become obstacles; unknown (-1) cells become
/// obstacles when `unknown_is_obstacle`. nullopt (with `error`) for inconsistent sizes.
std::optional<OccupancyRaster> FromOccupancyGrid(const nav_msgs::OccupancyGrid& grid,
                                                 int occupied_threshold, bool unknown_is_obstacle,
                                                 std::string* error);

/// rviz markers of the database: walls and sensed features, room outlines and names, doors
/// coloured by state (green open, red closed, orange unknown, grey openings).
visualization_msgs::MarkerArray ToMarkers(const MapDatabase& db, const std::string& frame_id,
                                          const ros::Time& stamp);

}  // namespace spott_map::ros_conversions
