#include "world_validation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "spott_map/wall_generation.h"
#include "spott_map/world_loader.h"

namespace spott_map {

namespace {

std::string Metres(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.2f m", v);
  return buffer;
}

std::string PointText(const Vec2& p) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "(%.2f, %.2f)", p.x(), p.y());
  return buffer;
}

class Validator {
 public:
  Validator(World& world, std::vector<SourceError>& errors, std::vector<SourceError>& warnings)
      : world_(world), errors_(errors), warnings_(warnings) {}

  void CheckIds() {
    std::map<std::string, std::string> seen;  // id -> what first used it
    const auto check = [&](const std::string& id, const SourceLocation& where,
                           const std::string& what) {
      // The loader checked each id against the rule where it is written (world.h, IsValidId);
      // generated wall ids follow it.
      if (!IsValidId(id)) return;
      auto [it, inserted] = seen.emplace(id, what);
      if (!inserted)
        Error(where, "duplicate id '" + id + "' (already used by a " + it->second + ")");
    };
    for (const Room& r : world_.rooms) check(r.id, r.where, "room");
    for (const Door& d : world_.doors) check(d.id, d.where, "door");
    for (const Wall& w : world_.walls) check(w.id, w.where, "wall");
    for (const WorldObject& o : world_.objects) check(o.id, o.where, "object");
    for (const Zone& z : world_.zones) check(z.id, z.where, "zone");
    for (const NamedPath& p : world_.paths) check(p.id, p.where, "path");
    std::map<std::string, bool> places;
    for (const Place& p : world_.places) {
      if (!IsValidId(p.name)) continue;  // reported by the loader
      if (!places.emplace(p.name, true).second) {
        Error(p.where, "duplicate place name '" + p.name + "'");
      }
    }
  }

  // Everything must lie within kWorldMaxCoordinate of the origin: maps of the world are rasters,
  // and a stray "1e9" would otherwise ask world_server for an impossible grid.
  void CheckExtent(const SourceLocation& start_where) {
    const auto far = [](const Vec2& p) {
      return std::abs(p.x()) > kWorldMaxCoordinate || std::abs(p.y()) > kWorldMaxCoordinate;
    };
    const std::string limit =
        " lies beyond " + Metres(kWorldMaxCoordinate) + " of the origin (the supported extent)";
    // The first vertex of `points` beyond the extent, if any, is reported for `what`.
    const auto check_points = [&](const std::vector<Vec2>& points, const std::string& what,
                                  const SourceLocation& where) {
      const auto beyond = std::find_if(points.begin(), points.end(), far);
      if (beyond != points.end()) Error(where, what + PointText(*beyond) + limit);
    };
    for (const Room& r : world_.rooms)
      check_points(r.polygon, "room " + r.id + ": vertex ", r.where);
    for (const Zone& z : world_.zones)
      check_points(z.polygon, "zone " + z.id + ": vertex ", z.where);
    for (const Wall& w : world_.walls) {
      if (far(w.segment.a) || far(w.segment.b) || w.thickness > kWorldMaxCoordinate)
        Error(w.where, "wall " + w.id + limit);
    }
    for (const Door& d : world_.doors) {
      if (far(d.center) || d.width > kWorldMaxCoordinate) Error(d.where, "door " + d.id + limit);
    }
    for (const WorldObject& o : world_.objects) {
      if (far(o.pose.Position()) || o.size_x > kWorldMaxCoordinate ||
          o.size_y > kWorldMaxCoordinate || o.height > kWorldMaxCoordinate) {
        Error(o.where, "object " + o.id + limit);
      }
    }
    for (const Place& p : world_.places) {
      if (far(p.pose.Position())) Error(p.where, "place " + p.name + limit);
    }
    for (const NamedPath& path : world_.paths) {
      check_points(path.points, "path " + path.id + ": point ", path.where);
    }
    if (far(world_.robot_start.Position())) Error(start_where, "robot_start" + limit);
  }

  // A room or zone outline must be simple with at least `min_area_m2`; it is made
  // counter-clockwise. Returns false (with an error) when it is not usable.
  bool NormalizeOutline(Polygon& polygon, const std::string& what, const SourceLocation& where,
                        double min_area_m2) {
    if (auto crossing = FindSelfIntersection(polygon)) {
      Error(where, what + ": polygon is self-intersecting (edge " +
                       std::to_string(crossing->first) + " meets edge " +
                       std::to_string(crossing->second) + ")");
      return false;
    }
    const double area = SignedArea(polygon);
    if (std::abs(area) < min_area_m2) {
      Error(where, what + ": polygon has no area");
      return false;
    }
    if (area < 0.0) std::reverse(polygon.begin(), polygon.end());
    return true;
  }

  void CheckRooms() {
    for (Room& room : world_.rooms) {
      NormalizeOutline(room.polygon, "room " + room.id, room.where, 0.01);
    }
    for (std::size_t i = 0; i < world_.rooms.size(); ++i) {
      for (std::size_t j = i + 1; j < world_.rooms.size(); ++j) {
        const Room& a = world_.rooms[i];
        const Room& b = world_.rooms[j];
        if (PolygonsOverlap(a.polygon, b.polygon, kWorldTolerance)) {
          Error(b.where, "room " + b.id + " overlaps room " + a.id);
        }
      }
    }
  }

  void CheckDoors() {
    for (Door& door : world_.doors) {
      const Room* a = world_.FindRoom(door.room_a);
      const Room* b = world_.FindRoom(door.room_b);
      if (!a)
        Error(door.where, "door " + door.id + " is between unknown room '" + door.room_a + "'");
      if (!b)
        Error(door.where, "door " + door.id + " is between unknown room '" + door.room_b + "'");
      if (!a || !b) continue;
      if (a == b) {
        Error(door.where, "door " + door.id + " joins room " + a->id + " to itself");
        continue;
      }
      PlaceDoorOnSharedBoundary(door, *a, *b);
    }
  }

  void CheckWalls() {
    for (const Wall& wall : world_.walls) {
      if (wall.segment.Length() < 1e-3) {
        Error(wall.where, "wall " + wall.id + " has no length");
        continue;
      }
      for (const Door& door : world_.doors) {
        if (door.opening.Length() <= 0.0 || wall.generated) continue;
        if (DistanceSegmentSegment(wall.segment, Segment{door.center, door.center}) <
            0.5 * wall.thickness + kWorldTolerance) {
          Error(wall.where, "wall " + wall.id + " blocks the opening of door " + door.id + " at " +
                                PointText(door.center));
        }
      }
    }
  }

  void CheckObjects() {
    for (const WorldObject& object : world_.objects) {
      if (!world_.RoomContaining(object.pose.Position())) {
        Error(object.where, "object " + object.id + " at " + PointText(object.pose.Position()) +
                                " is outside every room");
      }
    }
  }

  void CheckPlaces(const SourceLocation& start_where) {
    for (const Place& place : world_.places) {
      if (!world_.RoomContaining(place.pose.Position())) {
        Error(place.where, "place " + place.name + " at " + PointText(place.pose.Position()) +
                               " is outside every room");
      }
    }
    const Vec2 start = world_.robot_start.Position();
    if (!world_.RoomContaining(start)) {
      Error(start_where, "robot_start " + PointText(start) + " is outside every room");
      return;
    }
    for (const WorldObject& object : world_.objects) {
      if (PointInPolygon(start, object.Footprint())) {
        Error(start_where, "robot_start " + PointText(start) + " is inside object " + object.id);
      }
    }
    for (const Wall& wall : world_.walls) {
      if (DistancePointSegment(start, wall.segment) < 0.5 * wall.thickness) {
        Error(start_where, "robot_start " + PointText(start) + " is inside wall " + wall.id);
      }
    }
  }

  void CheckZonesAndPaths() {
    for (Zone& zone : world_.zones) {
      NormalizeOutline(zone.polygon, "zone " + zone.id, zone.where, 1e-4);
    }
    for (const NamedPath& path : world_.paths) {
      for (std::size_t i = 0; i < path.points.size(); ++i) {
        if (!world_.RoomContaining(path.points[i])) {
          Error(path.where, "path " + path.id + ": point " + std::to_string(i) + " " +
                                PointText(path.points[i]) + " is outside every room");
        }
      }
    }
  }

  bool ok() const { return errors_.empty(); }

 private:
  // Finds a pair of parallel edges, one of each room, that both hold the door's opening, and
  // stores the opening along them.
  void PlaceDoorOnSharedBoundary(Door& door, const Room& a, const Room& b) {
    const double tol = kWorldTolerance;
    double nearest_a = DistanceToBoundary(door.center, a.polygon);
    double nearest_b = DistanceToBoundary(door.center, b.polygon);
    if (nearest_a > tol || nearest_b > tol) {
      const Room& off = nearest_a > tol ? a : b;
      Error(door.where, "door " + door.id + ": center " + PointText(door.center) +
                            " is not on the boundary of room " + off.id + " (nearest edge " +
                            Metres(std::max(nearest_a > tol ? nearest_a : 0.0,
                                            nearest_b > tol ? nearest_b : 0.0)) +
                            " away); a door must lie on the boundary its two rooms share");
      return;
    }
    for (std::size_t i = 0; i < a.polygon.size(); ++i) {
      const Segment ea = PolygonEdge(a.polygon, i);
      if (DistancePointSegment(door.center, ea) > tol) continue;
      for (std::size_t j = 0; j < b.polygon.size(); ++j) {
        const Segment eb = PolygonEdge(b.polygon, j);
        if (DistancePointSegment(door.center, eb) > tol) continue;
        if (std::abs(Cross(ea.Direction(), eb.Direction())) > 0.02) continue;  // ~1 degree
        const Vec2 d = ea.Direction();
        // The opening lies on room a's edge line, centred at the door's projection onto it.
        const Vec2 c = ClosestPointOnSegment(door.center, ea);
        const Segment opening{c - 0.5 * door.width * d, c + 0.5 * door.width * d};
        const auto fits = [&](const Segment& edge) {
          return DistancePointSegment(opening.a, edge) <= tol &&
                 DistancePointSegment(opening.b, edge) <= tol;
        };
        if (fits(ea) && fits(eb)) {
          door.opening = opening;
          return;
        }
      }
    }
    Error(door.where, "door " + door.id + " (width " + Metres(door.width) +
                          ") does not fit on the boundary shared by rooms " + a.id + " and " +
                          b.id + " at " + PointText(door.center));
  }

  void Error(const SourceLocation& where, const std::string& message) {
    errors_.push_back(SourceError{where, message});
  }

  World& world_;
  std::vector<SourceError>& errors_;
  std::vector<SourceError>& warnings_;
};

}  // namespace

void ValidateWorld(World& world, const SourceLocation& robot_start_where, bool walls_from_rooms,
                   double wall_thickness, std::vector<SourceError>& errors,
                   std::vector<SourceError>& warnings) {
  Validator v(world, errors, warnings);
  if (world.name.empty())
    errors.push_back(SourceError{SourceLocation{world.source_file, 0, 0}, "world name is empty"});
  if (world.rooms.empty()) {
    errors.push_back(
        SourceError{SourceLocation{world.source_file, 0, 0}, "a world needs at least one room"});
  }
  v.CheckIds();
  v.CheckExtent(robot_start_where);
  if (!v.ok()) return;
  v.CheckRooms();
  if (!v.ok()) return;  // Doors and places are placed against valid room outlines only.
  v.CheckDoors();
  if (!v.ok()) return;
  if (walls_from_rooms) {
    std::vector<Wall> generated =
        GenerateWallsFromRooms(world.rooms, world.doors, wall_thickness, kWorldTolerance);
    world.walls.insert(world.walls.begin(), generated.begin(), generated.end());
    v.CheckIds();  // generated ids must not clash with listed ones
    if (!v.ok()) return;
  }
  v.CheckWalls();
  v.CheckObjects();
  v.CheckPlaces(robot_start_where);
  v.CheckZonesAndPaths();
  if (world.walls.empty()) {
    warnings.push_back(SourceError{SourceLocation{world.source_file, 0, 0},
                                   "the world has no walls (set walls: from_rooms: true?)"});
  }
}

}  // namespace spott_map
