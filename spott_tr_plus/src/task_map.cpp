#include "task_map.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "task_geometry.h"

namespace spott_tr_plus {
namespace internal {

namespace {

// A point is on a room's boundary (a door's centre, a wall) within this distance (m).
constexpr double kOnBoundaryM = 0.1;

spott_map::Vec2 V2(double x, double y) { return spott_map::Vec2(x, y); }

int RoomIndex(const spott_map::MapDatabase& db, const std::string& id) {
  const auto& rooms = db.graph().rooms();
  for (size_t i = 0; i < rooms.size(); ++i) {
    if (rooms[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

std::vector<int> AllRooms(const spott_map::MapDatabase& db) {
  std::vector<int> all(db.graph().rooms().size());
  for (size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  return all;
}

// Rooms whose outline holds or passes within `d` of the segment a-b.
std::vector<int> RoomsNear(const spott_map::MapDatabase& db, spott_map::Vec2 a, spott_map::Vec2 b,
                           double d) {
  std::vector<int> out;
  const auto& rooms = db.graph().rooms();
  const spott_map::Segment s{a, b};
  for (size_t i = 0; i < rooms.size(); ++i) {
    const spott_map::Polygon& poly = rooms[i].polygon;
    bool near = spott_map::PointInPolygon(s.Midpoint(), poly);
    for (size_t k = 0; k < poly.size() && !near; ++k) {
      near = spott_map::DistanceSegmentSegment(spott_map::PolygonEdge(poly, k), s) <= d;
    }
    if (near) out.push_back(static_cast<int>(i));
  }
  return out;
}

std::string RoomList(const spott_map::MapDatabase& db, const std::vector<int>& rooms) {
  std::string s;
  for (size_t i = 0; i < rooms.size(); ++i) {
    s += (i == 0 ? "" : i + 1 == rooms.size() ? " and " : ", ") + db.graph().rooms()[rooms[i]].id;
  }
  return s.empty() ? std::string("no room") : s;
}

}  // namespace

std::vector<int> RightRooms(const Target& t, const TargetGeometry& g,
                            const std::string& preposition, const spott_map::MapDatabase& db,
                            double near_m) {
  const std::vector<int> all = AllRooms(db);
  if (preposition == "far") return all;
  const spott_map::Vec2 c = V2(g.x, g.y);
  if (t.word == "room" || t.word == "hallway") {
    const bool inside = preposition.empty() || preposition == "in" || preposition == "inside" ||
                        preposition == "along";
    int home = g.map_id.empty() ? -1 : RoomIndex(db, g.map_id);
    if (home < 0) {
      if (const spott_map::Room* r = db.graph().RoomContaining(c)) home = RoomIndex(db, r->id);
    }
    if (inside && home >= 0) return {home};
    return all;  // the region itself keeps out of the room
  }
  if (t.word == "door") {
    if (const spott_map::Door* d = g.map_id.empty() ? nullptr : db.graph().FindDoor(g.map_id)) {
      std::vector<int> two;
      for (const std::string& id : {d->room_a, d->room_b}) {
        const int i = RoomIndex(db, id);
        if (i >= 0) two.push_back(i);
      }
      if (!two.empty()) return two;
    }
    std::vector<int> near = RoomsNear(db, c, c, kOnBoundaryM);
    return near.empty() ? all : near;
  }
  if (t.word == "wall" || t.word == "line") {
    const Vec e = Axis(g);
    const spott_map::Vec2 a = V2(g.x - g.half_length * e.x, g.y - g.half_length * e.y);
    const spott_map::Vec2 b = V2(g.x + g.half_length * e.x, g.y + g.half_length * e.y);
    std::vector<int> near = RoomsNear(db, a, b, kOnBoundaryM);
    return near.empty() ? all : near;
  }
  if (const spott_map::Room* r = db.graph().RoomContaining(c)) return {RoomIndex(db, r->id)};
  std::vector<int> near = RoomsNear(db, c, c, near_m);
  return near.empty() ? all : near;
}

bool FitGoalToFreeSpace(GoalRegion& r, const std::vector<int>& rooms, const FreeSpace& space,
                        const spott_map::MapDatabase& db, const std::string& what,
                        std::string* why) {
  const auto& all = db.graph().rooms();
  std::vector<char> allowed(all.size(), 0);
  r.rooms.clear();
  for (int i : rooms) {
    allowed[i] = 1;
    r.rooms.push_back(all[i].id);
  }
  const spott_map::Vec2 preferred = V2(r.goal_x, r.goal_y);
  int in_rooms = 0, free = 0, reachable = 0, best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  for (int cell = 0; cell < space.num_cells(); ++cell) {
    const int room = space.RoomOf(cell);
    if (room < 0 || !allowed[room]) continue;
    const spott_map::Vec2 p = space.Centre(cell);
    if (!r.Contains(p.x(), p.y())) continue;
    ++in_rooms;
    if (!space.Free(cell)) continue;
    ++free;
    if (!space.Reachable(cell)) continue;
    ++reachable;
    const double d = (p - preferred).norm();
    if (d < best_d) {
      best_d = d;
      best = cell;
    }
  }
  r.free_area_m2 = reachable * space.cell_area_m2();
  if (best < 0) {
    const std::string where = RoomList(db, rooms);
    if (in_rooms == 0) {
      *why = what + " has no point in " + where +
             " (where the target is): it lies beyond the room's walls";
    } else if (free == 0) {
      *why = what + " in " + where + " lies all within obstacles or their padding of " +
             Number(space.padding_m()) + " m (robot radius + localization error)";
    } else {
      bool by_doors = false;  // is any of the rooms reachable through passable doors?
      if (space.robot_room() >= 0) {
        const auto reach = db.graph().ReachableFrom(all[space.robot_room()].id);
        for (int i : rooms) {
          by_doors = by_doors || std::find(reach.begin(), reach.end(), all[i].id) != reach.end();
        }
      }
      *why = what + " in " + where + " cannot be reached from the robot" +
             (space.robot_room() >= 0 ? " in " + all[space.robot_room()].id : std::string()) +
             (by_doors ? ": known obstacles cut its free part off" : ": no open door leads there");
    }
    return false;
  }
  const int pc = space.CellOf(preferred);
  const int pr = pc >= 0 ? space.RoomOf(pc) : -1;
  const bool keep = pr >= 0 && allowed[pr] && space.Free(pc) && space.Reachable(pc) &&
                    spott_map::PointInPolygon(preferred, all[pr].polygon) &&
                    space.Clear(preferred) && r.Contains(preferred.x(), preferred.y());
  if (!keep) {
    const spott_map::Vec2 p = space.Centre(best);
    r.goal_x = p.x();
    r.goal_y = p.y();
  }
  return true;
}

}  // namespace internal

PlaceResolver MapPlaceResolver(const spott_map::MapDatabase& db,
                               const std::vector<spott_map::Place>& places) {
  return [&db, &places](const Target& t) -> std::optional<TargetGeometry> {
    if (t.name.empty()) return std::nullopt;
    TargetGeometry g;
    g.map_id = t.name;
    if (t.word == "room" || t.word == "hallway") {
      const spott_map::Room* room = db.graph().FindRoom(t.name);
      if (!room || room->polygon.size() < 3) return std::nullopt;
      // Its outline, with the box of its bounds along the longer side as the axes.
      const spott_map::Box b = spott_map::BoundingBox(room->polygon);
      const spott_map::Vec2 c = spott_map::Centroid(room->polygon);
      const spott_map::Vec2 size = b.max - b.min;
      g.x = c.x();
      g.y = c.y();
      g.theta = size.x() >= size.y() ? 0.0 : M_PI / 2;
      g.half_length = 0.5 * std::max(size.x(), size.y());
      g.half_width = 0.5 * std::min(size.x(), size.y());
      for (const spott_map::Vec2& v : room->polygon) g.polygon.emplace_back(v.x(), v.y());
      return g;
    }
    if (t.word == "door") {
      const spott_map::Door* d = db.graph().FindDoor(t.name);
      if (!d) return std::nullopt;
      g.x = d->center.x();
      g.y = d->center.y();
      const spott_map::Vec2 dir = d->opening.Direction();
      g.theta = std::atan2(dir.y(), dir.x());
      g.half_length = 0.5 * d->width;
      return g;
    }
    if (t.word == "point") {
      for (const spott_map::Place& p : places) {
        if (p.name != t.name) continue;
        g.x = p.pose.x;
        g.y = p.pose.y;
        return g;
      }
      return std::nullopt;
    }
    // Walls, chairs, desks: features of the database by id.
    const spott_map::MapFeature* f = db.FindFeature(t.name);
    if (!f) return std::nullopt;
    if (f->type == spott_map::FeatureType::kPoint) {
      if (f->points.empty()) return std::nullopt;
      g.x = f->points[0].x();
      g.y = f->points[0].y();
    } else if (f->type == spott_map::FeatureType::kLineSegment) {
      if (f->points.size() < 2) return std::nullopt;
      const spott_map::Vec2 a = f->points[0], b = f->points[1];
      g.x = 0.5 * (a.x() + b.x());
      g.y = 0.5 * (a.y() + b.y());
      g.theta = std::atan2(b.y() - a.y(), b.x() - a.x());
      g.half_length = 0.5 * (b - a).norm();
      g.half_width = 0.5 * f->size_y;
    } else {
      g.x = f->pose.x;
      g.y = f->pose.y;
      g.theta = f->pose.yaw;
      g.half_length = 0.5 * f->size_x;
      g.half_width = 0.5 * f->size_y;
      for (const spott_map::Vec2& v : f->Outline()) g.polygon.emplace_back(v.x(), v.y());
    }
    return g;
  };
}

}  // namespace spott_tr_plus
