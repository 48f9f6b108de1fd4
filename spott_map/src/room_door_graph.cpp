#include "spott_map/room_door_graph.h"

#include <deque>
#include <stdexcept>

namespace spott_map {

RoomDoorGraph::RoomDoorGraph(const World& world) : rooms_(world.rooms), doors_(world.doors) {
  Index();
}

RoomDoorGraph::RoomDoorGraph(std::vector<Room> rooms, std::vector<Door> doors)
    : rooms_(std::move(rooms)), doors_(std::move(doors)) {
  Index();
}

void RoomDoorGraph::Index() {
  room_index_.clear();
  door_index_.clear();
  for (std::size_t i = 0; i < rooms_.size(); ++i) room_index_[rooms_[i].id] = i;
  doors_of_room_.assign(rooms_.size(), {});
  for (std::size_t i = 0; i < doors_.size(); ++i) {
    door_index_[doors_[i].id] = i;
    for (const std::string& r : {doors_[i].room_a, doors_[i].room_b}) {
      auto it = room_index_.find(r);
      if (it == room_index_.end()) {
        throw std::invalid_argument("door " + doors_[i].id + " refers to unknown room " + r);
      }
      doors_of_room_[it->second].push_back(i);
    }
  }
}

const Room* RoomDoorGraph::FindRoom(const std::string& id) const {
  auto it = room_index_.find(id);
  return it == room_index_.end() ? nullptr : &rooms_[it->second];
}

const Door* RoomDoorGraph::FindDoor(const std::string& id) const {
  auto it = door_index_.find(id);
  return it == door_index_.end() ? nullptr : &doors_[it->second];
}

const Room* RoomDoorGraph::RoomContaining(const Vec2& p) const {
  for (const Room& r : rooms_) {
    if (PointInPolygon(p, r.polygon, 1e-9)) return &r;
  }
  return nullptr;
}

Vec2 RoomDoorGraph::RoomCentre(const std::string& room_id) const {
  const Room* room = FindRoom(room_id);
  if (!room) throw std::invalid_argument("unknown room " + room_id);
  return Centroid(room->polygon);
}

bool RoomDoorGraph::SetDoorState(const std::string& door_id, DoorState state) {
  auto it = door_index_.find(door_id);
  if (it == door_index_.end()) return false;
  Door& door = doors_[it->second];
  if (door.kind == DoorKind::kOpening && state != DoorState::kOpen) return false;
  door.state = state;
  return true;
}

std::vector<const Door*> RoomDoorGraph::DoorsOf(const std::string& room_id) const {
  std::vector<const Door*> result;
  auto it = room_index_.find(room_id);
  if (it == room_index_.end()) return result;
  for (std::size_t d : doors_of_room_[it->second]) result.push_back(&doors_[d]);
  return result;
}

std::vector<std::pair<std::string, const Door*>> RoomDoorGraph::NeighboursThroughOpenDoors(
    const std::string& room_id) const {
  std::vector<std::pair<std::string, const Door*>> result;
  for (const Door* door : DoorsOf(room_id)) {
    if (!Passable(*door)) continue;
    result.emplace_back(door->room_a == room_id ? door->room_b : door->room_a, door);
  }
  return result;
}

std::vector<std::string> RoomDoorGraph::ReachableFrom(const std::string& room_id) const {
  std::vector<std::string> reached;
  if (!FindRoom(room_id)) return reached;
  std::vector<bool> seen(rooms_.size(), false);
  std::deque<std::string> frontier{room_id};
  seen[room_index_.at(room_id)] = true;
  while (!frontier.empty()) {
    const std::string room = frontier.front();
    frontier.pop_front();
    reached.push_back(room);
    for (const auto& [next, door] : NeighboursThroughOpenDoors(room)) {
      const std::size_t i = room_index_.at(next);
      if (!seen[i]) {
        seen[i] = true;
        frontier.push_back(next);
      }
    }
  }
  return reached;
}

bool RoomDoorGraph::IsConnected() const {
  if (rooms_.empty()) return true;
  return ReachableFrom(rooms_.front().id).size() == rooms_.size();
}

}  // namespace spott_map
