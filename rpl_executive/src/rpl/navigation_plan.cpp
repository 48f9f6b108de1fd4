#include "rpl_executive/rpl/navigation_plan.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <sstream>

namespace rpl_executive {
namespace rpl {
namespace office {

namespace {

double Distance(const Point& a, const Point& b) { return std::hypot(a.x_m - b.x_m, a.y_m - b.y_m); }

double DistanceToSegment(const Point& p, const Point& a, const Point& b) {
  const double dx = b.x_m - a.x_m, dy = b.y_m - a.y_m;
  const double l2 = dx * dx + dy * dy;
  double t = l2 > 0 ? ((p.x_m - a.x_m) * dx + (p.y_m - a.y_m) * dy) / l2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return Distance(p, {a.x_m + t * dx, a.y_m + t * dy});
}

double DistanceToPolygon(const std::vector<Point>& polygon, const Point& p) {
  if (InsidePolygon(polygon, p)) return 0.0;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    best = std::min(best, DistanceToSegment(p, polygon[i], polygon[(i + 1) % polygon.size()]));
  }
  return best;
}

Point Centroid(const std::vector<Point>& polygon) {
  Point c;
  for (const Point& p : polygon) {
    c.x_m += p.x_m / polygon.size();
    c.y_m += p.y_m / polygon.size();
  }
  return c;
}

// The unit normal of the door's opening pointing into room `to`.
Point NormalInto(const BuildingDoor& door, const BuildingRoom* to) {
  double tx = door.end_b.x_m - door.end_a.x_m, ty = door.end_b.y_m - door.end_a.y_m;
  const double l = std::hypot(tx, ty);
  if (l < 1e-9) {  // no opening given: point at the room's centroid
    const Point c = to ? Centroid(to->polygon) : door.centre;
    const double dx = c.x_m - door.centre.x_m, dy = c.y_m - door.centre.y_m;
    const double d = std::max(1e-9, std::hypot(dx, dy));
    return {dx / d, dy / d};
  }
  Point n{-ty / l, tx / l};
  if (to) {
    const Point probe{door.centre.x_m + 0.3 * n.x_m, door.centre.y_m + 0.3 * n.y_m};
    const Point back{door.centre.x_m - 0.3 * n.x_m, door.centre.y_m - 0.3 * n.y_m};
    const bool ahead = InsidePolygon(to->polygon, probe), behind = InsidePolygon(to->polygon, back);
    if (behind && !ahead) return {-n.x_m, -n.y_m};
    if (ahead == behind) {
      const Point c = Centroid(to->polygon);
      if ((c.x_m - door.centre.x_m) * n.x_m + (c.y_m - door.centre.y_m) * n.y_m < 0)
        return {-n.x_m, -n.y_m};
    }
  }
  return n;
}

std::vector<Point> DoorwayPolygon(const BuildingDoor& door, const NavigationPlanParameters& p) {
  double tx = door.end_b.x_m - door.end_a.x_m, ty = door.end_b.y_m - door.end_a.y_m;
  double half = 0.5 * std::hypot(tx, ty);
  if (half < 1e-9) {
    tx = 1.0;
    ty = 0.0;
    half = 0.0;
  } else {
    tx /= 2 * half;
    ty /= 2 * half;
  }
  const double nx = -ty, ny = tx;
  const double a = half + p.doorway_margin_m, d = p.doorway_depth_m;
  const Point& c = door.centre;
  return {{c.x_m - a * tx - d * nx, c.y_m - a * ty - d * ny},
          {c.x_m + a * tx - d * nx, c.y_m + a * ty - d * ny},
          {c.x_m + a * tx + d * nx, c.y_m + a * ty + d * ny},
          {c.x_m - a * tx + d * nx, c.y_m - a * ty + d * ny}};
}

}  // namespace

const char* TravelModeName(TravelMode mode) {
  switch (mode) {
    case TravelMode::kNone:
      return "none";
    case TravelMode::kOffice:
      return "office";
    case TravelMode::kHallway:
      return "hallway";
    case TravelMode::kDoorway:
      return "doorway";
  }
  return "?";
}

bool InsidePolygon(const std::vector<Point>& polygon, const Point& p) {
  const std::size_t n = polygon.size();
  if (n < 3) return false;
  bool inside = false;
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point& a = polygon[i];
    const Point& b = polygon[j];
    if (DistanceToSegment(p, a, b) < 1e-9) return true;  // on the border
    if ((a.y_m > p.y_m) != (b.y_m > p.y_m) &&
        p.x_m < (b.x_m - a.x_m) * (p.y_m - a.y_m) / (b.y_m - a.y_m) + a.x_m) {
      inside = !inside;
    }
  }
  return inside;
}

const BuildingRoom* BuildingMap::FindRoom(const std::string& id) const {
  for (const BuildingRoom& r : rooms) {
    if (r.id == id) return &r;
  }
  return nullptr;
}

const BuildingRoom* BuildingMap::RoomAt(const Point& p, double tolerance_m) const {
  const BuildingRoom* best = nullptr;
  double best_d = tolerance_m;
  for (const BuildingRoom& r : rooms) {
    const double d = DistanceToPolygon(r.polygon, p);
    if (d == 0.0) return &r;
    if (d <= best_d) {
      best_d = d;
      best = &r;
    }
  }
  return best;
}

std::vector<std::string> ValidateParameters(const NavigationPlanParameters& p) {
  std::vector<std::string> e;
  if (!(p.door_approach_m > 0 && p.door_approach_m <= 5))
    e.push_back("door_approach_m: must be in (0, 5] m");
  if (!(p.doorway_depth_m > 0 && p.doorway_depth_m <= 5))
    e.push_back("doorway_depth_m: must be in (0, 5] m");
  if (!(p.doorway_margin_m >= 0 && p.doorway_margin_m <= 2))
    e.push_back("doorway_margin_m: must be in [0, 2] m");
  if (!(p.office_pass_penalty_m >= 0 && p.office_pass_penalty_m <= 1e6))
    e.push_back("office_pass_penalty_m: must be in [0, 1e6] m");
  if (!(p.min_target_spacing_m >= 0 && p.min_target_spacing_m <= 5))
    e.push_back("min_target_spacing_m: must be in [0, 5] m");
  return e;
}

std::string NavigationPlan::Summary() const {
  std::ostringstream s;
  for (std::size_t i = 0; i < rooms.size(); ++i) {
    if (i) s << " -> " << doors[i - 1] << " -> ";
    s << rooms[i];
  }
  s << ": " << targets.size() << " target point" << (targets.size() == 1 ? "" : "s");
  return s.str();
}

std::optional<NavigationPlan> PlanNavigation(const BuildingMap& map, const Point& start,
                                             const Point& destination,
                                             const NavigationPlanParameters& p,
                                             std::string* error) {
  auto fail = [&](const std::string& why) -> std::optional<NavigationPlan> {
    if (error) *error = why;
    return std::nullopt;
  };
  auto where = [](const Point& q) {
    std::ostringstream s;
    s.precision(3);
    s << "(" << q.x_m << ", " << q.y_m << ")";
    return s.str();
  };
  const BuildingRoom* from = map.RoomAt(start);
  if (!from) return fail("the robot's position " + where(start) + " is outside every room");
  const BuildingRoom* to = map.RoomAt(destination);
  if (!to) return fail("the destination " + where(destination) + " is outside every room");

  // Dijkstra over the passages: node 0 is the start, 1 the destination, 2 + 2 i + s "through
  // door i into its room_a (s = 0) or room_b (s = 1)".
  const std::size_t n = 2 * map.doors.size() + 2;
  auto door_of = [](std::size_t v) { return (v - 2) / 2; };
  auto room_of = [&](std::size_t v) -> const std::string& {
    const BuildingDoor& d = map.doors[door_of(v)];
    return (v - 2) % 2 == 0 ? d.room_a : d.room_b;
  };
  auto point = [&](std::size_t v) {
    return v == 0 ? start : v == 1 ? destination : map.doors[door_of(v)].centre;
  };
  auto pass_cost = [&](const std::string& room) {
    const BuildingRoom* r = map.FindRoom(room);
    const bool office = r && !r->hallway;
    return office && room != from->id && room != to->id ? p.office_pass_penalty_m : 0.0;
  };
  std::vector<double> cost(n, std::numeric_limits<double>::infinity());
  std::vector<std::size_t> previous(n, n);
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  cost[0] = 0.0;
  queue.push({0.0, 0});
  std::vector<std::string> closed_on_the_way;
  while (!queue.empty()) {
    // Named copies, not a structured binding: the lambda below captures them (C++17).
    const double c = queue.top().first;
    const std::size_t v = queue.top().second;
    queue.pop();
    if (c > cost[v] || v == 1) continue;
    const std::string& here = v == 0 ? from->id : room_of(v);
    auto relax = [&](std::size_t w, double extra) {
      const double nc = c + Distance(point(v), point(w)) + extra;
      if (nc < cost[w]) {
        cost[w] = nc;
        previous[w] = v;
        queue.push({nc, w});
      }
    };
    const double extra = v == 0 ? 0.0 : pass_cost(here);
    if (here == to->id) relax(1, 0.0);
    for (std::size_t i = 0; i < map.doors.size(); ++i) {
      const BuildingDoor& d = map.doors[i];
      if (v != 0 && i == door_of(v)) continue;
      if (d.room_a != here && d.room_b != here) continue;
      if (!d.open) {
        closed_on_the_way.push_back(d.id);
        continue;
      }
      relax(2 + 2 * i + (d.room_a == here ? 1 : 0), extra);
    }
  }
  if (previous[1] == n) {
    std::sort(closed_on_the_way.begin(), closed_on_the_way.end());
    closed_on_the_way.erase(std::unique(closed_on_the_way.begin(), closed_on_the_way.end()),
                            closed_on_the_way.end());
    std::string why = "no open way from " + from->id + " to " + to->id;
    if (!closed_on_the_way.empty()) {
      why += ": closed ";
      for (std::size_t i = 0; i < closed_on_the_way.size(); ++i)
        why += (i ? ", " : "") + closed_on_the_way[i];
    }
    return fail(why);
  }

  std::vector<std::size_t> doors;
  for (std::size_t v = previous[1]; v != 0; v = previous[v]) doors.push_back(door_of(v));
  std::reverse(doors.begin(), doors.end());

  NavigationPlan plan;
  plan.rooms.push_back(from->id);
  std::vector<Point> targets;
  for (std::size_t k = 0; k < doors.size(); ++k) {
    const BuildingDoor& d = map.doors[doors[k]];
    const std::string next = d.room_a == plan.rooms.back() ? d.room_b : d.room_a;
    plan.doors.push_back(d.id);
    plan.rooms.push_back(next);
    const Point nrm = NormalInto(d, map.FindRoom(next));
    const Point pre{d.centre.x_m - p.door_approach_m * nrm.x_m,
                    d.centre.y_m - p.door_approach_m * nrm.y_m};
    const Point post{d.centre.x_m + p.door_approach_m * nrm.x_m,
                     d.centre.y_m + p.door_approach_m * nrm.y_m};
    const BuildingRoom* before = map.FindRoom(plan.rooms[plan.rooms.size() - 2]);
    const BuildingRoom* after = map.FindRoom(next);
    if (d.opening && before && after && before->hallway && after->hallway) continue;
    const std::vector<Point> doorway = DoorwayPolygon(d, p);
    plan.regions.push_back({TravelMode::kDoorway, d.id, doorway});
    // A robot standing in the doorway already passes it from where it is.
    if (!(k == 0 && InsidePolygon(doorway, start))) targets.push_back(pre);
    // The destination just behind the door: no point beyond it.
    const double dest_depth =
        (destination.x_m - d.centre.x_m) * nrm.x_m + (destination.y_m - d.centre.y_m) * nrm.y_m;
    if (!(k + 1 == doors.size() && dest_depth < p.door_approach_m)) targets.push_back(post);
  }
  targets.push_back(destination);
  for (const std::string& id : plan.rooms) {
    const BuildingRoom* r = map.FindRoom(id);
    if (r) {
      plan.regions.push_back(
          {r->hallway ? TravelMode::kHallway : TravelMode::kOffice, r->id, r->polygon});
    }
  }
  // Leave out points too near the next one (or, for the first, to the start).
  Point last = start;
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const bool final_point = i + 1 == targets.size();
    if (!final_point && (Distance(targets[i], last) < p.min_target_spacing_m ||
                         Distance(targets[i], targets[i + 1]) < p.min_target_spacing_m)) {
      continue;
    }
    plan.targets.push_back(targets[i]);
    last = targets[i];
  }
  return plan;
}

TravelMode TravelModeAt(const std::vector<TravelRegion>& regions, const Point& p) {
  TravelMode found = TravelMode::kNone;
  for (const TravelRegion& r : regions) {
    if (!InsidePolygon(r.polygon, p)) continue;
    if (r.mode == TravelMode::kDoorway) return r.mode;
    if (found == TravelMode::kNone) found = r.mode;
  }
  return found;
}

}  // namespace office
}  // namespace rpl
}  // namespace rpl_executive
