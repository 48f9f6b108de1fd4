// The room/door graph of spott_map (SPOTT III.A) indexed for search: rooms and doors by number,
// each room's doors with the cost of crossing them, a grid index to find the room holding a
// point, door states (a door of unknown state is passable, III.D.2), and passages through a
// node that an obstacle blocks (the way from one of its doors to another, III: "the path from
// one access way to another ... is blocked by a newly discovered obstacle").
//
// Not thread-safe: one owner changes and reads it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "spott_map/room_door_graph.h"

namespace spott_global_planner {

using spott_map::Door;
using spott_map::DoorState;
using spott_map::Room;
using spott_map::RoomDoorGraph;

/// A blocked passage: inside `room`, no free way joins door `door_a` and door `door_b` (the
/// passage is undirected). Ids as in the graph.
struct BlockedPassage {
  std::string room;
  std::string door_a;
  std::string door_b;
  bool operator==(const BlockedPassage& o) const {
    return room == o.room && door_a == o.door_a && door_b == o.door_b;
  }
};

class PlanningGraph {
 public:
  /// One way out of a room: through `door` into `to_room`. `cost` (m) is the length of the
  /// polyline from this room's centre to the door's centre to the other room's centre.
  struct Arc {
    /// The search state "in to_room, entered through this door": 2 door + (1 when to_room is
    /// the door's room_b, else 0).
    int to_state;
    int to_room;
    double cost;
    int door() const { return to_state >> 1; }
  };

  PlanningGraph() = default;
  /// Indexes `graph` (rooms, doors, centres, the point-location grid).
  explicit PlanningGraph(RoomDoorGraph graph);

  const RoomDoorGraph& source() const { return graph_; }
  int room_count() const { return static_cast<int>(graph_.rooms().size()); }
  int door_count() const { return static_cast<int>(graph_.doors().size()); }
  const Room& room(int i) const { return graph_.rooms()[static_cast<std::size_t>(i)]; }
  const Door& door(int i) const { return graph_.doors()[static_cast<std::size_t>(i)]; }
  /// Index of a room or door id; nullopt when there is none.
  std::optional<int> FindRoom(const std::string& id) const;
  std::optional<int> FindDoor(const std::string& id) const;

  /// Area centroid of the room's outline (m): the node centre of the path costs.
  const spott_map::Vec2& RoomCentre(int room) const { return room_centre_[room]; }
  /// The door's centre (m).
  const spott_map::Vec2& DoorCentre(int d) const { return door(d).center; }
  /// The two rooms a door joins.
  std::pair<int, int> DoorRooms(int door) const { return door_rooms_[door]; }

  /// Room holding `p` (boundary included; the first listed wins, as in spott_map), or -1.
  int RoomContaining(const spott_map::Vec2& p) const;

  /// The arcs of a room, one per door (whatever its state).
  const Arc* ArcsBegin(int room) const { return arcs_.data() + arc_start_[room]; }
  const Arc* ArcsEnd(int room) const { return arcs_.data() + arc_start_[room + 1]; }

  /// Open and unknown doors are passable; closed ones are not (their edge is removed).
  bool DoorPassable(int door) const { return passable_[door] != 0; }
  /// Changes a door's state; false for an unknown door or an opening that would be closed.
  bool SetDoorState(const std::string& door_id, DoorState state);
  /// Ids of the closed doors, in graph order.
  std::vector<std::string> ClosedDoors() const;

  /// Replaces the blocked passages of `room`: each pair names two of its doors (indices).
  void SetBlockedPassages(int room, const std::vector<std::pair<int, int>>& pairs);
  bool HasBlockedPassages(int room) const { return room_blocks_[room] != 0; }
  bool PassageBlocked(int room, int door_a, int door_b) const;
  /// Every blocked passage, rooms in graph order, pairs sorted.
  std::vector<BlockedPassage> BlockedPassages() const;
  std::vector<BlockedPassage> BlockedPassagesOf(int room) const;

 private:
  static std::uint64_t PairKey(int a, int b);
  void BuildLocator();

  RoomDoorGraph graph_;
  std::unordered_map<std::string, int> room_index_;
  std::unordered_map<std::string, int> door_index_;
  std::vector<spott_map::Vec2> room_centre_;
  std::vector<std::pair<int, int>> door_rooms_;
  std::vector<int> arc_start_;
  std::vector<Arc> arcs_;
  std::vector<std::uint8_t> passable_;
  // Per room: sorted keys of its blocked door pairs (empty for most rooms).
  std::vector<std::vector<std::uint64_t>> blocked_of_room_;
  std::vector<std::uint8_t> room_blocks_;  // 1 where blocked_of_room_ is not empty (hot path)

  // Point location: a uniform grid over the rooms' bounding boxes; each cell lists the rooms
  // whose box meets it (room order kept, so the first listed room wins).
  spott_map::Vec2 grid_origin_{0.0, 0.0};
  double grid_cell_ = 1.0;
  int grid_nx_ = 0;
  int grid_ny_ = 0;
  std::vector<int> grid_start_;
  std::vector<int> grid_rooms_;
};

}  // namespace spott_global_planner
