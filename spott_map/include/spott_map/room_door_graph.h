// The abstract graph of SPOTT section III: nodes are rooms and portions of hallway, edges are
// the doors between them with their state. A door of unknown state is taken as open (paper
// III.D.2: "edge, initially assumed to be open").
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "spott_map/world.h"

namespace spott_map {

class RoomDoorGraph {
 public:
  RoomDoorGraph() = default;
  /// The graph of a (validated) world: its rooms and doors.
  explicit RoomDoorGraph(const World& world);
  RoomDoorGraph(std::vector<Room> rooms, std::vector<Door> doors);

  const std::vector<Room>& rooms() const { return rooms_; }
  const std::vector<Door>& doors() const { return doors_; }
  const Room* FindRoom(const std::string& id) const;
  const Door* FindDoor(const std::string& id) const;

  /// The node holding `p` (boundary included), or nullptr when `p` is in no room.
  const Room* RoomContaining(const Vec2& p) const;

  /// The centre used for path costs: the area centroid of the room's outline (m).
  Vec2 RoomCentre(const std::string& room_id) const;

  /// Sets a door's state; false when there is no such door or an opening would be closed.
  bool SetDoorState(const std::string& door_id, DoorState state);

  /// A door can be passed when it is open or its state is unknown.
  static bool Passable(const Door& door) { return door.state != DoorState::kClosed; }

  /// Doors of `room_id` (any state).
  std::vector<const Door*> DoorsOf(const std::string& room_id) const;

  /// Rooms reachable in one step from `room_id` through passable doors, with the door used.
  std::vector<std::pair<std::string, const Door*>> NeighboursThroughOpenDoors(
      const std::string& room_id) const;

  /// Every room reachable from `room_id` through passable doors (itself included).
  std::vector<std::string> ReachableFrom(const std::string& room_id) const;

  /// True when every room is reachable from every other through passable doors.
  bool IsConnected() const;

 private:
  void Index();

  std::vector<Room> rooms_;
  std::vector<Door> doors_;
  std::map<std::string, std::size_t> room_index_;
  std::map<std::string, std::size_t> door_index_;
  std::vector<std::vector<std::size_t>> doors_of_room_;  // indices into doors_
};

}  // namespace spott_map
