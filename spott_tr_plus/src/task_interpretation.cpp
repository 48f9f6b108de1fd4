// Interpretation of SPOTT task commands (section III-B): prepositions modify the target
// location into a goal region, the direction biases the local planner's descent, the speed
// word scales the maximum speed. The definitions of every word are in the README ("Task
// commands"); the deictic prepositions are taken from the robot's point of view.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "spott_tr_plus/task_command.h"

namespace spott_tr_plus {

namespace {

struct Vec {
  double x = 0, y = 0;
};
Vec operator+(Vec a, Vec b) { return {a.x + b.x, a.y + b.y}; }
Vec operator-(Vec a, Vec b) { return {a.x - b.x, a.y - b.y}; }
Vec operator*(double s, Vec a) { return {s * a.x, s * a.y}; }
double Dot(Vec a, Vec b) { return a.x * b.x + a.y * b.y; }
double Norm(Vec a) { return std::hypot(a.x, a.y); }
Vec Unit(Vec a, Vec fallback) {
  const double n = Norm(a);
  return n > 1e-12 ? (1.0 / n) * a : fallback;
}

// The target's axes: e1 along its long axis, e2 across.
Vec Axis(const TargetGeometry& g) { return {std::cos(g.theta), std::sin(g.theta)}; }
Vec Across(const TargetGeometry& g) { return {-std::sin(g.theta), std::cos(g.theta)}; }

// Half-extent of the footprint in direction v (support function of the box).
double Support(const TargetGeometry& g, Vec v) {
  return g.half_length * std::fabs(Dot(v, Axis(g))) + g.half_width * std::fabs(Dot(v, Across(g)));
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

// Signed distance from (x, y) to the footprint: < 0 inside, 0 on the boundary.
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

std::string Number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.3g", v);
  return buf;
}

}  // namespace

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
      return std::hypot(x - goal_x, y - goal_y) <= tolerance ||
             (has_alternative && std::hypot(x - alt_x, y - alt_y) <= tolerance);
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

TaskInterpretResult InterpretTask(
    const TaskCommand& c, double rx, double ry,
    double /*ryaw: relative directions are resolved later, DirectionBias::At*/,
    const TaskInterpretationParameters& params, const PlaceResolver& resolve,
    const std::string& source) {
  TaskInterpretResult result;
  auto error = [&](Location where, const std::string& message) {
    result.diagnostics.push_back(Diagnostic{Diagnostic::Severity::kError, source, where, message});
  };
  auto geometry = [&](const Target& t) -> std::optional<TargetGeometry> {
    if (auto g = GeometryFromAttributes(t, params)) return g;
    if (resolve) {
      if (auto g = resolve(t)) return g;
    }
    error(t.where, t.name.empty() ? "'" + t.word +
                                        "' without attributes is not in the map: "
                                        "give its coordinates"
                                  : t.word + " '" + t.name + "' is not in the map");
    return std::nullopt;
  };

  TaskInterpretation in;
  in.speed_fraction = c.speed == Speed::kSlowly    ? params.slow_fraction
                      : c.speed == Speed::kQuickly ? params.quick_fraction
                                                   : params.normal_fraction;
  const Vec robot{rx, ry};

  // Goal region from the destination (SPOTT III-B: prepositions modify the target location).
  std::optional<TargetGeometry> dest;
  if (c.verb == Verb::kFind) {
    in.mode = TaskInterpretation::Mode::kSearch;
    in.sought = c.destination;
    // A sought object with a known location gives the region to look in.
    if (auto g = GeometryFromAttributes(*c.destination, params)) dest = g;
  } else if (c.destination) {
    dest = geometry(*c.destination);
    if (!dest) return result;
  }
  if (dest) {
    GoalRegion r;
    r.target = *dest;
    r.tolerance = params.goal_tolerance_m;
    const Vec center{dest->x, dest->y};
    const Vec e1 = Axis(*dest), e2 = Across(*dest);
    // u: from the target toward the robot (the viewer); left: the viewer's left facing it.
    const Vec u = Unit(robot - center, e2);
    const Vec left{u.y, -u.x};
    auto point_goal = [&](Vec dir, double offset) {
      r.kind = GoalRegion::Kind::kDisc;
      const Vec g = center + (Support(*dest, dir) + offset) * dir;
      r.goal_x = g.x;
      r.goal_y = g.y;
    };
    auto boundary_goal = [&](double offset) {  // the footprint's side facing the robot
      const Vec g = center + (Support(*dest, u) + offset) * u;
      r.goal_x = g.x;
      r.goal_y = g.y;
    };
    const std::string& p = c.verb == Verb::kFind ? std::string("near") : c.preposition;
    if (p.empty() || p == "at") {
      r.kind = GoalRegion::Kind::kWithin;
      r.max_distance = params.at_distance_m;
      boundary_goal(params.at_distance_m / 2);
    } else if (p == "against") {
      r.kind = GoalRegion::Kind::kWithin;
      r.max_distance = params.against_distance_m;
      boundary_goal(params.against_distance_m / 2);
    } else if (p == "near" || p == "by") {
      r.kind = GoalRegion::Kind::kWithin;
      r.max_distance = params.near_distance_m;
      boundary_goal(params.near_distance_m / 2);
    } else if (p == "around") {
      r.kind = GoalRegion::Kind::kWithin;
      r.min_distance = params.at_distance_m;
      r.max_distance = params.near_distance_m;
      boundary_goal((params.at_distance_m + params.near_distance_m) / 2);
    } else if (p == "far") {
      r.kind = GoalRegion::Kind::kBeyond;
      r.min_distance = params.far_distance_m;
      boundary_goal(params.far_distance_m + params.goal_tolerance_m);
    } else if (p == "in" || p == "inside") {
      r.kind = GoalRegion::Kind::kInside;
      r.goal_x = dest->x;
      r.goal_y = dest->y;
    } else if (p == "out" || p == "outside") {
      r.kind = GoalRegion::Kind::kOutside;
      r.max_distance = params.near_distance_m;
      boundary_goal(params.near_distance_m / 2);
    } else if (p == "along" || p == "alongside") {
      r.kind = GoalRegion::Kind::kAlongside;
      r.max_distance = params.near_distance_m;
      const Vec n = Dot(robot - center, e2) >= 0 ? e2 : -1.0 * e2;  // the robot's side
      const Vec g = center + (dest->half_width + params.at_distance_m) * n;
      r.goal_x = g.x;
      r.goal_y = g.y;
    } else if (p == "in-front-of") {
      point_goal(u, params.at_distance_m);
    } else if (p == "behind" || p == "in-back-of") {
      point_goal(-1.0 * u, params.at_distance_m);
    } else if (p == "beyond") {
      point_goal(-1.0 * u, params.beyond_distance_m);
    } else if (p == "to-the-left-of") {
      point_goal(left, params.at_distance_m);
    } else if (p == "to-the-right-of") {
      point_goal(-1.0 * left, params.at_distance_m);
    } else if (p == "beside" || p == "to-the-side-of") {
      // Either side (beside: close to it; to-the-side-of: within `near`); the goal point is
      // the robot's left, the alternative its right.
      const double off = p == "beside" ? params.at_distance_m : params.near_distance_m / 2;
      point_goal(-1.0 * left, off);
      r.has_alternative = true;
      r.alt_x = r.goal_x;
      r.alt_y = r.goal_y;
      point_goal(left, off);
    } else if (p == "across") {
      // The mirror image of the robot's position across the target's long axis.
      const double side = Dot(robot - center, e2);
      const double along = Dot(robot - center, e1);
      const double off = std::max(std::fabs(side), dest->half_width + params.at_distance_m);
      const Vec g = center + along * e1 - (side >= 0 ? off : -off) * e2;
      r.kind = GoalRegion::Kind::kDisc;
      r.goal_x = g.x;
      r.goal_y = g.y;
    } else if (p == "in-line-with") {
      // On the long axis, past the end nearer the robot.
      const Vec dir = Dot(robot - center, e1) >= 0 ? e1 : -1.0 * e1;
      const Vec g = center + (dest->half_length + params.near_distance_m) * dir;
      r.kind = GoalRegion::Kind::kDisc;
      r.goal_x = g.x;
      r.goal_y = g.y;
    }
    in.goal = r;
  }

  // Direction bias.
  if (!c.orientation.empty()) {
    const std::string& o = c.orientation;
    DirectionBias& b = in.bias;
    // base_link (REP-103): x forward, y left. map: x east, y north.
    if (o == "forward" || o == "backward" || o == "left" || o == "right") {
      b.kind = DirectionBias::Kind::kRelativeHeading;
      b.angle = o == "forward" ? 0.0 : o == "backward" ? M_PI : o == "left" ? M_PI / 2 : -M_PI / 2;
    } else {
      b.kind = DirectionBias::Kind::kAbsoluteHeading;
      b.angle = o == "east" ? 0.0 : o == "north" ? M_PI / 2 : o == "west" ? M_PI : -M_PI / 2;
    }
  } else if (!c.path.empty()) {
    const auto pg = geometry(*c.path_target);
    if (!pg) return result;
    const Vec t{pg->x, pg->y};
    const Vec goal = in.goal ? Vec{in.goal->goal_x, in.goal->goal_y} : t;
    DirectionBias& b = in.bias;
    b.x = t.x;
    b.y = t.y;
    const std::string& w = c.path;
    if (w == "to") {
      b.kind = DirectionBias::Kind::kAttract;
    } else if (w == "toward") {
      // A fixed heading: the direction to the target as seen from the start.
      b.kind = DirectionBias::Kind::kAbsoluteHeading;
      b.angle = std::atan2(t.y - ry, t.x - rx);
    } else if (w == "via") {
      b.kind = DirectionBias::Kind::kWaypoint;
      b.radius = params.goal_tolerance_m + Support(*pg, Unit(robot - t, Vec{1, 0}));
    } else if (w == "from") {
      // The path runs as if it started at the target: heading from it to the goal.
      b.kind = DirectionBias::Kind::kAbsoluteHeading;
      const Vec d = goal - t;
      b.angle = Norm(d) > 1e-9 ? std::atan2(d.y, d.x) : std::atan2(ry - t.y, rx - t.x);
    } else if (w == "away-from") {
      b.kind = DirectionBias::Kind::kRepel;
    } else if (w == "along") {
      // Parallel to the target's long axis, in the sense that makes progress to the goal.
      const Vec e1 = Axis(*pg);
      const Vec toward = in.goal ? goal - robot : t - robot;
      b.kind = DirectionBias::Kind::kAbsoluteHeading;
      b.angle = Dot(toward, e1) >= 0 ? pg->theta : pg->theta + M_PI;
      b.angle = std::atan2(std::sin(b.angle), std::cos(b.angle));
    } else if (w == "around") {
      // Circulate about the target, the shorter way to the goal (sign of the cross product).
      const Vec r0 = robot - t, g0 = goal - t;
      b.kind = DirectionBias::Kind::kCirculate;
      b.sense = r0.x * g0.y - r0.y * g0.x >= 0 ? 1.0 : -1.0;
      b.radius = Support(*pg, Unit(r0, Vec{1, 0})) + params.at_distance_m;
    }
    // Decision: a `go` with no destination goes to the target of `to` and `via`; other path
    // words only bias the robot (tele-operation guided by the bias).
    if (c.verb == Verb::kGo && !in.goal && (w == "to" || w == "via")) {
      GoalRegion r;
      r.kind = GoalRegion::Kind::kWithin;
      r.target = *pg;
      r.max_distance = params.at_distance_m;
      r.tolerance = params.goal_tolerance_m;
      const Vec u = Unit(robot - t, Vec{1, 0});
      const Vec g = t + (Support(*pg, u) + params.at_distance_m / 2) * u;
      r.goal_x = g.x;
      r.goal_y = g.y;
      in.goal = r;
    }
  }
  if (c.verb == Verb::kGo) {
    in.mode = in.goal ? TaskInterpretation::Mode::kGoTo : TaskInterpretation::Mode::kTeleoperate;
  }
  result.interpretation = std::move(in);
  return result;
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
    static const char* kinds[] = {"within", "beyond", "inside", "outside", "alongside", "disc"};
    s += "; goal region " + std::string(kinds[static_cast<int>(goal->kind)]) + " of target at (" +
         Number(goal->target.x) + ", " + Number(goal->target.y) + ")";
    if (goal->kind == GoalRegion::Kind::kWithin || goal->kind == GoalRegion::Kind::kOutside ||
        goal->kind == GoalRegion::Kind::kAlongside) {
      s += " [" + Number(goal->min_distance) + ", " + Number(goal->max_distance) + "] m";
    } else if (goal->kind == GoalRegion::Kind::kBeyond) {
      s += " >= " + Number(goal->min_distance) + " m";
    }
    s += ", goal point (" + Number(goal->goal_x) + ", " + Number(goal->goal_y) + ")";
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
