// Interpretation of SPOTT task commands (section III-B): prepositions modify the target
// location into a goal region, the direction biases the local planner's descent, the speed
// word scales the maximum speed. The definitions of every word are in the README ("Task
// commands"); the deictic prepositions are taken from the robot's point of view. With a map
// (TaskMap) the goal point is chosen in the free, reachable space of the target's room
// (task_map.cpp).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "free_space.h"
#include "spott_tr_plus/task_command.h"
#include "task_geometry.h"
#include "task_map.h"

namespace spott_tr_plus {

namespace internal {

double FootprintDistance(const TargetGeometry& g, double x, double y) {
  const Vec d{x - g.x, y - g.y};
  const double u = Dot(d, Axis(g)), v = Dot(d, Across(g));
  if (g.polygon.size() >= 3) {
    double best = 1e300;
    for (size_t i = 0, j = g.polygon.size() - 1; i < g.polygon.size(); j = i++) {
      const Vec a{g.polygon[j].first, g.polygon[j].second};
      const Vec b{g.polygon[i].first, g.polygon[i].second};
      const Vec ab = b - a;
      const double t = std::clamp(Dot(Vec{x, y} - a, ab) / std::max(Dot(ab, ab), 1e-12), 0.0, 1.0);
      best = std::min(best, Norm(Vec{x, y} - (a + t * ab)));
    }
    return InsidePolygon(g.polygon, x, y) ? -best : best;
  }
  const double qx = std::fabs(u) - g.half_length, qy = std::fabs(v) - g.half_width;
  const double outside = std::hypot(std::max(qx, 0.0), std::max(qy, 0.0));
  return outside > 0 ? outside : std::max(qx, qy);
}

bool InsidePolygon(const std::vector<std::pair<double, double>>& poly, double x, double y) {
  bool inside = false;
  for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const auto& a = poly[i];
    const auto& b = poly[j];
    if ((a.second > y) != (b.second > y) &&
        x < (b.first - a.first) * (y - a.second) / (b.second - a.second) + a.first) {
      inside = !inside;
    }
  }
  return inside;
}

std::string Number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.3g", v);
  return buf;
}

}  // namespace internal

using internal::Across;
using internal::Axis;
using internal::Dot;
using internal::FootprintDistance;
using internal::Norm;
using internal::Number;
using internal::Support;
using internal::Unit;
using internal::Vec;

bool GoalRegion::Contains(double x, double y) const {
  const double d = FootprintDistance(target, x, y);
  switch (kind) {
    case Kind::kWithin:
      return d >= min_distance && d <= max_distance;
    case Kind::kBeyond:
      return d >= min_distance;
    case Kind::kInside:
      return d < 0;
    case Kind::kOutside:
      return d > 0 && d <= max_distance;
    case Kind::kAlongside: {
      const Vec p{x - target.x, y - target.y};
      return d > 0 && d <= max_distance && std::fabs(Dot(p, Axis(target))) <= target.half_length;
    }
    case Kind::kDisc:
      return std::hypot(x - goal_x, y - goal_y) <= tolerance;
    case Kind::kSide: {
      // Past the footprint's extent along the side direction, within the span across it.
      const Vec p{x - target.x, y - target.y};
      for (double sign : {1.0, -1.0}) {
        if (sign < 0 && !both_sides) break;
        const Vec dir{sign * side_x, sign * side_y};
        const Vec across{-dir.y, dir.x};
        const double past = Dot(p, dir) - Support(target, dir);
        if (past >= min_distance - 1e-9 && past <= max_distance + 1e-9 &&
            std::fabs(Dot(p, across)) <= half_span + 1e-9) {
          return true;
        }
      }
      return false;
    }
  }
  return false;
}

std::pair<double, double> DirectionBias::At(double rx, double ry, double ryaw) const {
  switch (kind) {
    case Kind::kNone:
      return {0, 0};
    case Kind::kRelativeHeading:
      return {std::cos(ryaw + angle), std::sin(ryaw + angle)};
    case Kind::kAbsoluteHeading:
      return {std::cos(angle), std::sin(angle)};
    case Kind::kAttract: {
      const Vec u = Unit(Vec{x - rx, y - ry}, Vec{0, 0});
      return {u.x, u.y};
    }
    case Kind::kRepel: {
      const Vec u = Unit(Vec{rx - x, ry - y}, Vec{0, 0});
      return {u.x, u.y};
    }
    case Kind::kWaypoint: {
      const Vec d{x - rx, y - ry};
      if (Norm(d) <= radius) return {0, 0};
      const Vec u = Unit(d, Vec{0, 0});
      return {u.x, u.y};
    }
    case Kind::kCirculate: {
      // Tangent to the circle about (x, y): the radial direction turned by +-90 degrees.
      const Vec r = Unit(Vec{rx - x, ry - y}, Vec{1, 0});
      return {-sense * r.y, sense * r.x};
    }
  }
  return {0, 0};
}

std::vector<std::string> ValidateParameters(const TaskInterpretationParameters& p) {
  std::vector<std::string> v;
  auto positive = [&](double value, const char* name) {
    if (!(value > 0)) v.push_back(std::string(name) + " must be > 0 (is " + Number(value) + ")");
  };
  positive(p.at_distance_m, "at_distance_m");
  positive(p.against_distance_m, "against_distance_m");
  positive(p.near_distance_m, "near_distance_m");
  positive(p.far_distance_m, "far_distance_m");
  positive(p.beyond_distance_m, "beyond_distance_m");
  positive(p.goal_tolerance_m, "goal_tolerance_m");
  positive(p.default_door_width_m, "default_door_width_m");
  positive(p.default_chair_radius_m, "default_chair_radius_m");
  positive(p.default_desk_length_m, "default_desk_length_m");
  positive(p.default_desk_width_m, "default_desk_width_m");
  if (!(p.free_space_resolution_m > 0 && p.free_space_resolution_m <= 0.5)) {
    v.push_back("free_space_resolution_m must be in (0, 0.5] (is " +
                Number(p.free_space_resolution_m) + ")");
  }
  if (!(p.near_distance_m < p.far_distance_m)) {
    v.push_back("near_distance_m must be < far_distance_m");
  }
  for (auto [value, name] : {std::pair{p.slow_fraction, "slow_fraction"},
                             std::pair{p.normal_fraction, "normal_fraction"},
                             std::pair{p.quick_fraction, "quick_fraction"}}) {
    if (!(value > 0 && value <= 1)) v.push_back(std::string(name) + " must be in (0, 1]");
  }
  if (!(p.slow_fraction < p.normal_fraction && p.normal_fraction < p.quick_fraction)) {
    v.push_back("slow_fraction < normal_fraction < quick_fraction must hold");
  }
  return v;
}

std::optional<TargetGeometry> GeometryFromAttributes(const Target& t,
                                                     const TaskInterpretationParameters& p) {
  if (!t.has_attributes || !t.name.empty()) return std::nullopt;
  const std::vector<double>& n = t.numbers;
  TargetGeometry g;
  auto segment = [&](double x1, double y1, double x2, double y2) {
    g.x = (x1 + x2) / 2;
    g.y = (y1 + y2) / 2;
    g.theta = std::atan2(y2 - y1, x2 - x1);
    g.half_length = std::hypot(x2 - x1, y2 - y1) / 2;
  };
  const std::string& w = t.word;
  if (w == "wall" || w == "line") {
    segment(n[0], n[1], n[2], n[3]);
    return g;
  }
  g.x = n[0];
  g.y = n[1];
  if (w == "point") return g;
  if (w == "door") {
    g.half_length = (n.size() >= 3 ? n[2] : p.default_door_width_m) / 2;
    g.theta = n.size() >= 4 ? n[3] : 0.0;
    return g;
  }
  if (w == "chair") {
    g.half_length = g.half_width = n.size() >= 3 ? n[2] : p.default_chair_radius_m;
    return g;
  }
  if (w == "desk") {
    g.half_length = (n.size() >= 4 ? n[2] : p.default_desk_length_m) / 2;
    g.half_width = (n.size() >= 4 ? n[3] : p.default_desk_width_m) / 2;
    g.theta = n.size() >= 5 ? n[4] : 0.0;
    return g;
  }
  if (w == "room" || w == "hallway" || w == "rectangle") {
    g.half_length = n[2] / 2;
    g.half_width = n[3] / 2;
    g.theta = n.size() >= 5 ? n[4] : 0.0;
    return g;
  }
  if (w == "ellipse" && t.klass == TargetClass::kModel2D) {
    // The bounding box of the ellipse with semi-axes a (long) and b.
    g.half_length = n[2];
    g.half_width = n[3];
    g.theta = n.size() >= 5 ? n[4] : 0.0;
    return g;
  }
  if (w == "ellipse") {  // geon (x, y, z, a, b, c): its footprint on the floor
    g.half_length = n[3];
    g.half_width = n[4];
    return g;
  }
  if (w == "cuboid") {
    g.half_length = n[3] / 2;
    g.half_width = n[4] / 2;
    g.theta = n.size() >= 7 ? n[6] : 0.0;
    return g;
  }
  if (w == "cylinder") {
    g.half_length = g.half_width = n[3];
    return g;
  }
  return std::nullopt;
}

namespace {

struct Reporter {
  const std::string& source;
  std::vector<Diagnostic>& out;
  void Error(Location where, const std::string& message) {
    out.push_back(Diagnostic{Diagnostic::Severity::kError, source, where, message});
  }
};

bool IsRoomWord(const std::string& word) { return word == "room" || word == "hallway"; }

// --- What the command names ---------------------------------------------------------------------

// The grammar lets every part after the verb be empty; what then names no goal is refused
// here, with the reason (README "Task commands").
bool NamesAGoal(const TaskCommand& c, Reporter& rep) {
  if (c.verb == Verb::kGo && !c.destination && c.orientation.empty() && c.path.empty()) {
    rep.Error(c.where,
              "'go' alone names no goal: give a destination (go near door(3.2, 1)), an "
              "orientation to tele-operate (go forward) or a path (go via point(2, 2)); SPOTT's "
              "go assumes a known goal location and its tele-operation the operator's "
              "direction (III-B, VI-A)");
    return false;
  }
  if (c.verb == Verb::kFind && !c.destination) {
    rep.Error(c.where,
              "'find' needs the object to find: a target (door, hallway, room, wall, chair, "
              "desk, ellipse, line, point, rectangle, cuboid, cylinder)");
    return false;
  }
  if (c.verb == Verb::kFind && !c.preposition.empty() && !c.destination->has_attributes) {
    rep.Error(c.destination->where,
              "'" + c.preposition + "' needs the location of the " + c.destination->word +
                  " to look " + c.preposition + ": give its attributes (find " + c.preposition +
                  " " + c.destination->word + "(x, y)) or leave the preposition out (find " +
                  c.destination->word + ")");
    return false;
  }
  return true;
}

double SpeedFraction(Speed s, const TaskInterpretationParameters& p) {
  return s == Speed::kSlowly    ? p.slow_fraction
         : s == Speed::kQuickly ? p.quick_fraction
                                : p.normal_fraction;
}

// The target's footprint: from its attributes, else from the map.
std::optional<TargetGeometry> Footprint(const Target& t, const TaskInterpretationParameters& p,
                                        const PlaceResolver& resolve, Reporter& rep) {
  if (auto g = GeometryFromAttributes(t, p)) return g;
  if (resolve) {
    if (auto g = resolve(t)) return g;
  }
  rep.Error(t.where, t.name.empty() ? "'" + t.word +
                                          "' without attributes is not in the map: give its "
                                          "coordinates"
                                    : t.word + " '" + t.name + "' is not in the map");
  return std::nullopt;
}

// --- Goal regions (SPOTT III-B: "spatial prepositions act as modifiers of the target
// location"). Each sets the region and the point the geometry prefers in it. ---

// Where the robot (the viewer) sees the target from.
struct View {
  Vec center, toward_robot, left;  // left: the viewer's left as it faces the target
};

View ViewOf(const TargetGeometry& g, Vec robot) {
  View v;
  v.center = Vec{g.x, g.y};
  v.toward_robot = Unit(robot - v.center, Across(g));
  v.left = Vec{v.toward_robot.y, -v.toward_robot.x};
  return v;
}

// Where `at` (and the path word `to`) puts the goal point into its band: halfway in, clear of
// the target, for anything with an extent; on the target itself for a point, which has nothing
// to keep clear of (`go to point(x, y)` ends on (x, y), not at_distance_m / 2 short of it).
double AtOffset(const TargetGeometry& g, const TaskInterpretationParameters& q) {
  const bool point = g.half_length <= 0 && g.half_width <= 0 && g.polygon.empty();
  return point ? 0.0 : q.at_distance_m / 2;
}

void SetGoal(GoalRegion& r, Vec p) {
  r.goal_x = p.x;
  r.goal_y = p.y;
}

// Distance prepositions: a band [min, max] from the footprint, the point on the side facing
// the robot `offset` from it.
GoalRegion Band(GoalRegion r, const View& v, double min_m, double max_m, double offset) {
  r.kind = GoalRegion::Kind::kWithin;
  r.min_distance = min_m;
  r.max_distance = max_m;
  SetGoal(r, v.center + (Support(r.target, v.toward_robot) + offset) * v.toward_robot);
  return r;
}

// Deictic prepositions: past the footprint on side `dir`, [min, max] beyond its extent, within
// the footprint's span across `dir` (its shadow seen from that side) plus the tolerance; the
// point `offset` past it.
GoalRegion Side(GoalRegion r, const View& v, Vec dir, double min_m, double max_m, double offset,
                bool both) {
  r.kind = GoalRegion::Kind::kSide;
  r.side_x = dir.x;
  r.side_y = dir.y;
  r.both_sides = both;
  r.min_distance = min_m;
  r.max_distance = max_m;
  r.half_span = Support(r.target, Vec{-dir.y, dir.x}) + r.tolerance;
  SetGoal(r, v.center + (Support(r.target, dir) + offset) * dir);
  return r;
}

GoalRegion Inside(GoalRegion r, const View& v) {
  r.kind = GoalRegion::Kind::kInside;
  SetGoal(r, v.center);
  return r;
}

// `along` a room or hallway: travel its length inside it, to the end away from the robot.
GoalRegion AlongInside(GoalRegion r, const View& v, Vec robot,
                       const TaskInterpretationParameters& p) {
  r.kind = GoalRegion::Kind::kInside;
  const Vec e1 = Axis(r.target);
  const Vec dir = Dot(robot - v.center, e1) >= 0 ? -1.0 * e1 : e1;
  SetGoal(r, v.center + std::max(r.target.half_length - p.near_distance_m, 0.0) * dir);
  return r;
}

// `along`, `alongside` another target: beside its long axis, on the robot's side.
GoalRegion Alongside(GoalRegion r, const View& v, Vec robot,
                     const TaskInterpretationParameters& p) {
  r.kind = GoalRegion::Kind::kAlongside;
  r.max_distance = p.near_distance_m;
  const Vec e2 = Across(r.target);
  const Vec n = Dot(robot - v.center, e2) >= 0 ? e2 : -1.0 * e2;
  SetGoal(r, v.center + (r.target.half_width + p.at_distance_m) * n);
  return r;
}

// `across`: the robot's mirror image across the target's long axis, on the far side.
GoalRegion AcrossFrom(GoalRegion r, const View& v, Vec robot,
                      const TaskInterpretationParameters& p) {
  const Vec e1 = Axis(r.target), e2 = Across(r.target);
  const double side = Dot(robot - v.center, e2);
  const double along = Dot(robot - v.center, e1);
  const double off = std::max(std::fabs(side), r.target.half_width + p.at_distance_m);
  const Vec far_side = side >= 0 ? -1.0 * e2 : e2;
  r = Side(r, v, far_side, 0.0, off - r.target.half_width + p.near_distance_m, 0.0, false);
  r.half_span = std::max(std::fabs(along), r.target.half_length) + r.tolerance;
  SetGoal(r, v.center + along * e1 + off * far_side);
  return r;
}

// `in-line-with`: on the long axis, `near` past the end nearer the robot.
GoalRegion InLineWith(GoalRegion r, const View& v, Vec robot,
                      const TaskInterpretationParameters& p) {
  const Vec e1 = Axis(r.target);
  const Vec dir = Dot(robot - v.center, e1) >= 0 ? e1 : -1.0 * e1;
  r = Side(r, v, dir, 0.0, p.near_distance_m + r.tolerance, p.near_distance_m, false);
  r.half_span = r.target.half_width + r.tolerance;
  return r;
}

GoalRegion DestinationRegion(const std::string& p, const Target& t, const TargetGeometry& g,
                             Vec robot, const TaskInterpretationParameters& q) {
  GoalRegion r;
  r.target = g;
  r.tolerance = q.goal_tolerance_m;
  const View v = ViewOf(g, robot);
  const Vec u = v.toward_robot;
  // A room or hallway named bare or with in/inside is a place to be in; along it, its length.
  if (IsRoomWord(t.word) && (p.empty() || p == "in" || p == "inside")) return Inside(r, v);
  if (IsRoomWord(t.word) && p == "along") return AlongInside(r, v, robot, q);
  if (p.empty() || p == "at") return Band(r, v, 0, q.at_distance_m, AtOffset(g, q));
  if (p == "against") return Band(r, v, 0, q.against_distance_m, q.against_distance_m / 2);
  if (p == "near" || p == "by") return Band(r, v, 0, q.near_distance_m, q.near_distance_m / 2);
  if (p == "around") {
    return Band(r, v, q.at_distance_m, q.near_distance_m,
                (q.at_distance_m + q.near_distance_m) / 2);
  }
  if (p == "far") {
    r = Band(r, v, q.far_distance_m, 0, q.far_distance_m + q.goal_tolerance_m);
    r.kind = GoalRegion::Kind::kBeyond;
    return r;
  }
  if (p == "in" || p == "inside") return Inside(r, v);
  if (p == "out" || p == "outside") {
    r = Band(r, v, 0, q.near_distance_m, q.near_distance_m / 2);
    r.kind = GoalRegion::Kind::kOutside;
    return r;
  }
  if (p == "along" || p == "alongside") return Alongside(r, v, robot, q);
  if (p == "in-front-of") return Side(r, v, u, 0, q.near_distance_m, q.at_distance_m, false);
  if (p == "behind" || p == "in-back-of") {
    return Side(r, v, -1.0 * u, 0, q.near_distance_m, q.at_distance_m, false);
  }
  if (p == "beyond") {
    return Side(r, v, -1.0 * u, q.at_distance_m, q.beyond_distance_m + q.near_distance_m,
                q.beyond_distance_m, false);
  }
  if (p == "to-the-left-of") {
    return Side(r, v, v.left, 0, q.near_distance_m, q.at_distance_m, false);
  }
  if (p == "to-the-right-of") {
    return Side(r, v, -1.0 * v.left, 0, q.near_distance_m, q.at_distance_m, false);
  }
  // Either side will do (beside: close to it; to-the-side-of: within `near`); the point is
  // on the robot's left.
  if (p == "beside") return Side(r, v, v.left, 0, q.near_distance_m, q.at_distance_m, true);
  if (p == "to-the-side-of") {
    return Side(r, v, v.left, 0, q.near_distance_m, q.near_distance_m / 2, true);
  }
  if (p == "across") return AcrossFrom(r, v, robot, q);
  return InLineWith(r, v, robot, q);  // in-line-with: the last of the BNF's prepositions
}

// --- Direction bias (SPOTT III-B: "the role of specifying the direction is to bias the local
// path planning execution") ---

DirectionBias OrientationBias(const std::string& o) {
  DirectionBias b;
  // base_link (REP-103): x forward, y left. map: x east, y north.
  if (o == "forward" || o == "backward" || o == "left" || o == "right") {
    b.kind = DirectionBias::Kind::kRelativeHeading;
    b.angle = o == "forward" ? 0.0 : o == "backward" ? M_PI : o == "left" ? M_PI / 2 : -M_PI / 2;
  } else {
    b.kind = DirectionBias::Kind::kAbsoluteHeading;
    b.angle = o == "east" ? 0.0 : o == "north" ? M_PI / 2 : o == "west" ? M_PI : -M_PI / 2;
  }
  return b;
}

// `goal`: the goal point when there is a destination, else the path target's centre.
DirectionBias PathBias(const std::string& w, const TargetGeometry& pg, const GoalRegion* region,
                       Vec robot, const TaskInterpretationParameters& p) {
  const Vec t{pg.x, pg.y};
  const Vec goal = region ? Vec{region->goal_x, region->goal_y} : t;
  DirectionBias b;
  b.x = t.x;
  b.y = t.y;
  if (w == "to") {
    b.kind = DirectionBias::Kind::kAttract;
  } else if (w == "toward") {
    // A fixed heading: the direction to the target as seen from the start.
    b.kind = DirectionBias::Kind::kAbsoluteHeading;
    b.angle = std::atan2(t.y - robot.y, t.x - robot.x);
  } else if (w == "via") {
    b.kind = DirectionBias::Kind::kWaypoint;
    b.radius = p.goal_tolerance_m + Support(pg, Unit(robot - t, Vec{1, 0}));
  } else if (w == "from") {
    // The path runs as if it started at the target: heading from it to the goal.
    b.kind = DirectionBias::Kind::kAbsoluteHeading;
    const Vec d = goal - t;
    b.angle = Norm(d) > 1e-9 ? std::atan2(d.y, d.x) : std::atan2(robot.y - t.y, robot.x - t.x);
  } else if (w == "away-from") {
    b.kind = DirectionBias::Kind::kRepel;
  } else if (w == "along") {
    // Parallel to the target's long axis, in the sense that makes progress to the goal.
    const Vec toward = region ? goal - robot : t - robot;
    b.kind = DirectionBias::Kind::kAbsoluteHeading;
    b.angle = Dot(toward, Axis(pg)) >= 0 ? pg.theta : pg.theta + M_PI;
    b.angle = std::atan2(std::sin(b.angle), std::cos(b.angle));
  } else if (w == "around") {
    // Circulate about the target, the shorter way to the goal (sign of the cross product).
    const Vec r0 = robot - t, g0 = goal - t;
    b.kind = DirectionBias::Kind::kCirculate;
    b.sense = r0.x * g0.y - r0.y * g0.x >= 0 ? 1.0 : -1.0;
    b.radius = Support(pg, Unit(r0, Vec{1, 0})) + p.at_distance_m;
  }
  return b;
}

// Decision: a `go` with no destination goes to the target of `to` and `via` (at it); other path
// words only bias the robot (tele-operation guided by the bias).
GoalRegion PathGoalRegion(const TargetGeometry& pg, Vec robot,
                          const TaskInterpretationParameters& p) {
  GoalRegion r;
  r.target = pg;
  r.tolerance = p.goal_tolerance_m;
  View v = ViewOf(pg, robot);
  v.toward_robot = Unit(robot - v.center, Vec{1, 0});
  return Band(r, v, 0, p.at_distance_m, AtOffset(pg, p));
}

// --- The whole command ---------------------------------------------------------------------------

// Fits goal regions into the map's free space, built at the first goal (TaskMap).
class GoalFitter {
 public:
  // A database without rooms (no a priori map: SPOTT's Fig. 12) has no free space to fit into:
  // the goal is the geometry's, as without a map; sensed obstacles are the planners' to avoid.
  GoalFitter(const TaskMap* map, Vec robot, const TaskInterpretationParameters& p, Reporter& rep)
      : map_(map && map->database && !map->database->graph().rooms().empty() ? map : nullptr),
        robot_(robot),
        params_(p),
        rep_(rep) {}

  bool Fit(GoalRegion& r, const Target& t, const std::string& preposition, Location robot_where) {
    if (!map_) return true;
    const spott_map::MapDatabase& db = *map_->database;
    if (!space_) {
      space_.emplace(db, map_->padding_m, params_.free_space_resolution_m);
      flood_ok_ = space_->FloodFrom(spott_map::Vec2(robot_.x, robot_.y), kSeedRadiusM);
    }
    if (!flood_ok_) {
      rep_.Error(robot_where, "the robot at (" + Number(robot_.x) + ", " + Number(robot_.y) +
                                  ") has no free space within " + Number(kSeedRadiusM) +
                                  " m of it (in a room, clear of obstacles by the padding " +
                                  Number(map_->padding_m) + " m): no goal can be reached");
      return false;
    }
    const std::vector<int> rooms =
        internal::RightRooms(t, r.target, preposition, db, params_.near_distance_m);
    std::string why;
    const std::string what =
        "the goal region " + (preposition.empty() ? std::string("at") : preposition) + " " + t.word;
    if (internal::FitGoalToFreeSpace(r, rooms, *space_, db, what, &why)) return true;
    rep_.Error(t.where, why);
    return false;
  }

 private:
  static constexpr double kSeedRadiusM = 1.0;
  const TaskMap* map_;
  Vec robot_;
  const TaskInterpretationParameters& params_;
  Reporter& rep_;
  std::optional<internal::FreeSpace> space_;
  bool flood_ok_ = false;
};

TaskInterpretResult Interpret(const TaskCommand& c, double rx, double ry,
                              const TaskInterpretationParameters& params, const TaskMap* map,
                              const PlaceResolver& resolve, const std::string& source) {
  TaskInterpretResult result;
  Reporter rep{source, result.diagnostics};
  if (!NamesAGoal(c, rep)) return result;
  const Vec robot{rx, ry};
  GoalFitter fitter(map, robot, params, rep);
  TaskInterpretation in;
  in.speed_fraction = SpeedFraction(c.speed, params);

  // Goal region from the destination. For `find` the destination is the object sought; the
  // location its attributes give, with the preposition (near when none), is where to look.
  if (c.verb == Verb::kFind) {
    in.mode = TaskInterpretation::Mode::kSearch;
    in.sought = c.destination;
  }
  if (c.destination) {
    std::optional<TargetGeometry> g;
    if (c.verb == Verb::kGo || !c.destination->name.empty()) {
      g = Footprint(*c.destination, params, resolve, rep);
      if (!g) return result;
    } else {
      g = GeometryFromAttributes(*c.destination, params);
    }
    if (g) {
      const std::string p =
          c.verb == Verb::kFind && c.preposition.empty() ? std::string("near") : c.preposition;
      GoalRegion r = DestinationRegion(p, *c.destination, *g, robot, params);
      if (!fitter.Fit(r, *c.destination, p, c.where)) return result;
      in.goal = std::move(r);
    }
  }

  // Direction bias, from the goal point once it is fitted to the map.
  if (!c.orientation.empty()) {
    in.bias = OrientationBias(c.orientation);
  } else if (!c.path.empty()) {
    const auto pg = Footprint(*c.path_target, params, resolve, rep);
    if (!pg) return result;
    if (c.verb == Verb::kGo && !in.goal && (c.path == "to" || c.path == "via")) {
      GoalRegion r = PathGoalRegion(*pg, robot, params);
      if (!fitter.Fit(r, *c.path_target, "at", c.where)) return result;
      in.bias = PathBias(c.path, *pg, nullptr, robot, params);
      in.goal = std::move(r);
    } else {
      in.bias = PathBias(c.path, *pg, in.goal ? &*in.goal : nullptr, robot, params);
    }
  }
  if (c.verb == Verb::kGo) {
    in.mode = in.goal ? TaskInterpretation::Mode::kGoTo : TaskInterpretation::Mode::kTeleoperate;
  }
  result.interpretation = std::move(in);
  return result;
}

}  // namespace

TaskInterpretResult InterpretTask(
    const TaskCommand& c, double rx, double ry,
    double /*ryaw: relative directions are resolved later, DirectionBias::At*/,
    const TaskInterpretationParameters& params, const PlaceResolver& resolve,
    const std::string& source) {
  return Interpret(c, rx, ry, params, nullptr, resolve, source);
}

TaskInterpretResult InterpretTask(const TaskCommand& c, double rx, double ry, double /*ryaw*/,
                                  const TaskInterpretationParameters& params, const TaskMap& map,
                                  const PlaceResolver& resolve, const std::string& source) {
  return Interpret(c, rx, ry, params, &map, resolve, source);
}

std::string TaskInterpretation::ToString() const {
  std::string s;
  switch (mode) {
    case Mode::kGoTo:
      s = "go to";
      break;
    case Mode::kSearch:
      s = "search for " + (sought ? sought->word : std::string("?"));
      break;
    case Mode::kTeleoperate:
      s = "tele-operate";
      break;
  }
  if (goal) {
    static const char* kinds[] = {"within",    "beyond", "inside", "outside",
                                  "alongside", "disc",   "side"};
    s += "; goal region " + std::string(kinds[static_cast<int>(goal->kind)]) + " of target at (" +
         Number(goal->target.x) + ", " + Number(goal->target.y) + ")";
    if (goal->kind == GoalRegion::Kind::kWithin || goal->kind == GoalRegion::Kind::kOutside ||
        goal->kind == GoalRegion::Kind::kAlongside) {
      s += " [" + Number(goal->min_distance) + ", " + Number(goal->max_distance) + "] m";
    } else if (goal->kind == GoalRegion::Kind::kBeyond) {
      s += " >= " + Number(goal->min_distance) + " m";
    }
    s += ", goal point (" + Number(goal->goal_x) + ", " + Number(goal->goal_y) + ")";
    if (!goal->rooms.empty()) {
      s += " in";
      for (size_t i = 0; i < goal->rooms.size(); ++i) s += (i ? ", " : " ") + goal->rooms[i];
      s += " (" + Number(goal->free_area_m2) + " m^2 free and reachable)";
    }
  }
  static const char* bias_kinds[] = {"none",  "relative heading", "absolute heading", "attract",
                                     "repel", "waypoint",         "circulate"};
  s += "; bias " + std::string(bias_kinds[static_cast<int>(bias.kind)]);
  if (bias.kind == DirectionBias::Kind::kRelativeHeading ||
      bias.kind == DirectionBias::Kind::kAbsoluteHeading) {
    s += " " + Number(bias.angle) + " rad";
  } else if (bias.kind != DirectionBias::Kind::kNone) {
    s += " (" + Number(bias.x) + ", " + Number(bias.y) + ")";
  }
  s += "; speed " + Number(speed_fraction) + " of maximum";
  return s;
}

}  // namespace spott_tr_plus
