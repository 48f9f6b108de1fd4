// A building as a world file describes it: the CAD walls, rooms and hallway portions (the nodes
// of the abstract graph), doors (its edges), objects that are not in the CAD map, named places
// and the robot's start. Metres and radians in the map frame (REP-103, REP-105).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "spott_map/geometry.h"
#include "spott_map/source_location.h"

namespace spott_map {

/// A planar pose: position (m) and heading (rad, counter-clockwise from +x).
struct Pose2 {
  double x = 0.0;
  double y = 0.0;
  double yaw = 0.0;
  Vec2 Position() const { return Vec2(x, y); }
};

enum class RoomKind { kRoom, kHallway };

/// A node of the abstract graph: a room or a portion of hallway.
struct Room {
  std::string id;
  std::string name;
  RoomKind kind = RoomKind::kRoom;
  Polygon polygon;  ///< Counter-clockwise outline (m), normalized by the loader.
  SourceLocation where;
};

enum class DoorState { kUnknown, kOpen, kClosed };

/// kDoor has a leaf that can be open or closed; kOpening is an access way without one (e.g.
/// between two portions of a hallway): always open, and no wall is generated across it.
enum class DoorKind { kDoor, kOpening };

/// An edge of the abstract graph: an access way between two rooms.
struct Door {
  std::string id;
  std::string room_a;
  std::string room_b;
  DoorKind kind = DoorKind::kDoor;
  DoorState state = DoorState::kUnknown;
  Vec2 center{0.0, 0.0};  ///< Centre of the opening (m), on the shared boundary.
  double width = 0.0;     ///< Clear opening (m).
  Segment opening;        ///< The opening along the shared boundary, computed by the loader.
  SourceLocation where;
};

/// A CAD wall: a segment with a thickness (m).
struct Wall {
  std::string id;
  Segment segment;
  double thickness = 0.1;
  bool generated = false;  ///< Made from a room outline rather than listed in the file.
  SourceLocation where;
};

enum class ObjectKind { kChair, kDesk, kPartition, kShelf, kCuboid, kCylinder };

/// Something in the building that the CAD map does not show (the simulator builds it; the stack
/// has to discover it).
struct WorldObject {
  std::string id;
  ObjectKind kind = ObjectKind::kCuboid;
  Pose2 pose;           ///< Centre and heading.
  double size_x = 0.0;  ///< Full extent along the object's x axis (m); cylinder: diameter.
  double size_y = 0.0;  ///< Full extent along its y axis (m); cylinder: diameter.
  double height = 0.0;  ///< (m)
  std::string label;    ///< Optional name ("Wolfram's shelf").
  SourceLocation where;
  /// Footprint corners (counter-clockwise); cylinders are approximated by 24 points.
  Polygon Footprint() const;
};

/// A named pose: localization places, experiment positions, landmarks, waypoints.
struct Place {
  std::string name;
  std::string kind;  ///< localization | position | landmark | waypoint
  Pose2 pose;
  SourceLocation where;
};

/// A named region (a surveillance zone of Noreils and Chatila's missions, e.g. ZONE109).
struct Zone {
  std::string id;
  Polygon polygon;  ///< Counter-clockwise outline (m), normalized by the loader.
  SourceLocation where;
};

/// A named polyline (a mission's path argument, e.g. smooth-move(PATH)).
struct NamedPath {
  std::string id;
  std::vector<Vec2> points;         ///< (m)
  std::optional<double> final_yaw;  ///< Heading to end with (rad), if given.
  SourceLocation where;
};

struct World {
  std::string name;
  std::string description;
  std::string source_file;
  std::vector<Wall> walls;
  std::vector<Room> rooms;
  std::vector<Door> doors;
  std::vector<WorldObject> objects;
  std::vector<Place> places;
  std::vector<Zone> zones;
  std::vector<NamedPath> paths;
  Pose2 robot_start;

  const Room* FindRoom(const std::string& id) const;
  const Door* FindDoor(const std::string& id) const;
  const Place* FindPlace(const std::string& name) const;
  const WorldObject* FindObject(const std::string& id) const;
  const Zone* FindZone(const std::string& id) const;
  const NamedPath* FindPath(const std::string& id) const;
  /// The room that holds `p` (boundary included; the first one listed wins), or nullptr.
  const Room* RoomContaining(const Vec2& p) const;
  /// Box around every wall and room.
  Box Bounds() const;
};

/// The one rule for the ids of a world (rooms, doors, walls, objects, zones, paths) and the
/// names of its places, which task commands name (`go in room(office_101)`): an ASCII letter or
/// '_', then ASCII letters, digits and '_'. The world loader refuses any other id with its
/// file:line:column; the task-command parser reads exactly these as names.
bool IsValidId(const std::string& id);

/// The rule in words, for error messages.
extern const char* const kIdRule;

const char* ToString(RoomKind kind);
const char* ToString(DoorState state);
const char* ToString(DoorKind kind);
const char* ToString(ObjectKind kind);
std::optional<RoomKind> ParseRoomKind(const std::string& text);
std::optional<DoorState> ParseDoorState(const std::string& text);
std::optional<DoorKind> ParseDoorKind(const std::string& text);
std::optional<ObjectKind> ParseObjectKind(const std::string& text);

}  // namespace spott_map
