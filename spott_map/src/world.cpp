#include "spott_map/world.h"

#include <cmath>

namespace spott_map {

const char* const kIdRule =
    "ids are an ASCII letter or '_' followed by letters, digits and '_' (task commands name "
    "them)";

bool IsValidId(const std::string& id) {
  if (id.empty()) return false;
  const auto letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); };
  if (!letter(id[0]) && id[0] != '_') return false;
  for (char c : id) {
    if (!letter(c) && !(c >= '0' && c <= '9') && c != '_') return false;
  }
  return true;
}

Polygon WorldObject::Footprint() const {
  Polygon corners;
  const double c = std::cos(pose.yaw);
  const double s = std::sin(pose.yaw);
  const auto place = [&](double lx, double ly) {
    corners.emplace_back(pose.x + c * lx - s * ly, pose.y + s * lx + c * ly);
  };
  if (kind == ObjectKind::kCylinder) {
    constexpr int kSides = 24;
    for (int i = 0; i < kSides; ++i) {
      const double a = 2.0 * M_PI * i / kSides;
      place(0.5 * size_x * std::cos(a), 0.5 * size_y * std::sin(a));
    }
  } else {
    place(-0.5 * size_x, -0.5 * size_y);
    place(0.5 * size_x, -0.5 * size_y);
    place(0.5 * size_x, 0.5 * size_y);
    place(-0.5 * size_x, 0.5 * size_y);
  }
  return corners;
}

const Room* World::FindRoom(const std::string& id) const {
  for (const Room& r : rooms) {
    if (r.id == id) return &r;
  }
  return nullptr;
}

const Door* World::FindDoor(const std::string& id) const {
  for (const Door& d : doors) {
    if (d.id == id) return &d;
  }
  return nullptr;
}

const Place* World::FindPlace(const std::string& name) const {
  for (const Place& p : places) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

const WorldObject* World::FindObject(const std::string& id) const {
  for (const WorldObject& o : objects) {
    if (o.id == id) return &o;
  }
  return nullptr;
}

const Zone* World::FindZone(const std::string& id) const {
  for (const Zone& z : zones) {
    if (z.id == id) return &z;
  }
  return nullptr;
}

const NamedPath* World::FindPath(const std::string& id) const {
  for (const NamedPath& p : paths) {
    if (p.id == id) return &p;
  }
  return nullptr;
}

const Room* World::RoomContaining(const Vec2& p) const {
  for (const Room& r : rooms) {
    if (PointInPolygon(p, r.polygon, 1e-9)) return &r;
  }
  return nullptr;
}

Box World::Bounds() const {
  Polygon points;
  for (const Wall& w : walls) {
    points.push_back(w.segment.a);
    points.push_back(w.segment.b);
  }
  for (const Room& r : rooms) points.insert(points.end(), r.polygon.begin(), r.polygon.end());
  if (points.empty()) return Box{};
  return BoundingBox(points);
}

const char* ToString(RoomKind kind) { return kind == RoomKind::kHallway ? "hallway" : "room"; }

const char* ToString(DoorState state) {
  switch (state) {
    case DoorState::kOpen:
      return "open";
    case DoorState::kClosed:
      return "closed";
    case DoorState::kUnknown:
      break;
  }
  return "unknown";
}

const char* ToString(DoorKind kind) { return kind == DoorKind::kOpening ? "opening" : "door"; }

const char* ToString(ObjectKind kind) {
  switch (kind) {
    case ObjectKind::kChair:
      return "chair";
    case ObjectKind::kDesk:
      return "desk";
    case ObjectKind::kPartition:
      return "partition";
    case ObjectKind::kShelf:
      return "shelf";
    case ObjectKind::kCylinder:
      return "cylinder";
    case ObjectKind::kCuboid:
      break;
  }
  return "cuboid";
}

std::optional<RoomKind> ParseRoomKind(const std::string& text) {
  if (text == "room") return RoomKind::kRoom;
  if (text == "hallway") return RoomKind::kHallway;
  return std::nullopt;
}

std::optional<DoorState> ParseDoorState(const std::string& text) {
  if (text == "open") return DoorState::kOpen;
  if (text == "closed") return DoorState::kClosed;
  if (text == "unknown") return DoorState::kUnknown;
  return std::nullopt;
}

std::optional<DoorKind> ParseDoorKind(const std::string& text) {
  if (text == "door") return DoorKind::kDoor;
  if (text == "opening") return DoorKind::kOpening;
  return std::nullopt;
}

std::optional<ObjectKind> ParseObjectKind(const std::string& text) {
  for (ObjectKind k : {ObjectKind::kChair, ObjectKind::kDesk, ObjectKind::kPartition,
                       ObjectKind::kShelf, ObjectKind::kCuboid, ObjectKind::kCylinder}) {
    if (text == ToString(k)) return k;
  }
  return std::nullopt;
}

}  // namespace spott_map
