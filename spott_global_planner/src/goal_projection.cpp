#include "spott_global_planner/goal_projection.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace spott_global_planner {

namespace {

// Where a line meets the window border, and which rule of the header chose it.
struct Crossing {
  Vec2 point{0.0, 0.0};
  std::string rule;
};

double Tolerance(const Box& window) {
  return 1e-9 * std::max(1.0, (window.max - window.min).maxCoeff());
}

// The point of the border nearest `p` (for a window the robot has left).
Vec2 NearestBorderPoint(const Box& window, const Vec2& p) {
  Vec2 best = window.min;
  double best_d = std::numeric_limits<double>::infinity();
  for (const Segment& s : WindowSides(window)) {
    const Vec2 q = spott_map::ClosestPointOnSegment(p, s);
    const double d = (q - p).norm();
    if (d < best_d) {
      best_d = d;
      best = q;
    }
  }
  return best;
}

// Where the line through `from` (the centre of n_k) and `to` (the centre of e_k) meets the
// border (the paper's p_k). The paper speaks of a line, so the infinite line is clipped to the
// window; of its two crossings the one reached last when moving towards the edge is taken (the
// robot leaves the window there on its way to e_k), unless the edge's centre itself is inside
// the window while `from` is not, when the line enters the window on the node's side. A line
// that misses the window falls back to the line from the robot, then to the nearest point.
Crossing BorderCrossing(const Vec2& from, const Vec2& to, const Vec2& robot, const Box& window) {
  const double eps = 1e-12;
  const auto at = [&](double t) { return Vec2(from + t * (to - from)); };
  if (const auto clip = ClipLineToBox(from, to, window)) {
    const auto [t0, t1] = *clip;
    if (t1 <= 1.0 + eps) {
      if (t1 < -eps) {
        return {at(t1),
                "the window lies behind the node's centre: the crossing of the line nearer the "
                "edge"};
      }
      const bool two = t0 >= -eps && t1 - t0 > eps;
      return {at(t1), two ? "the line meets the border twice: the crossing nearer the edge" : ""};
    }
    // The edge's centre is inside the window (the edge is not wholly inside).
    if (t0 >= -eps) {
      return {at(t0), "the edge's centre is inside the window: where the line enters it"};
    }
    return {at(t1), "the line is extended past the edge's centre to the border"};
  }
  if (window.Contains(robot)) {
    const auto r = ClipLineToBox(robot, to, window);
    if (r) {
      return {robot + r->second * (to - robot),
              "the line from the node's centre misses the window: the line from the robot"};
    }
  }
  return {NearestBorderPoint(window, to), "the border point nearest the target"};
}

struct Portion {
  Segment segment;
  WindowSide side = WindowSide::kBottom;
  bool found = false;
};

// The portion of a window side holding `p` that lies in `polygon`; at a corner the side with
// the longer such portion (ties: the side facing `direction` more squarely, then side order).
// Falls back to the nearest portion of `polygon` on any side at least `min_length` long (any
// length when none is), then to the point itself.
Portion PortionThrough(const Box& window, const Vec2& p, const Polygon& polygon,
                       const Vec2& direction, double min_length, std::string& rule) {
  const auto sides = WindowSides(window);
  const double tol = Tolerance(window) * 1e3;
  const Vec2 outward[4] = {Vec2(0, -1), Vec2(1, 0), Vec2(0, 1), Vec2(-1, 0)};
  Portion best;
  double best_len = -1.0;
  double best_facing = -std::numeric_limits<double>::infinity();
  for (WindowSide side : SidesThrough(window, p, tol)) {
    const Segment& s = sides[static_cast<int>(side)];
    const double len = s.Length();
    const double tp = len > 0.0 ? (p - s.a).dot(s.b - s.a) / (len * len) : 0.0;
    for (const Interval& iv : ClipSegmentToPolygon(s, polygon)) {
      if (tp < iv.first - tol / std::max(len, 1e-12) ||
          tp > iv.second + tol / std::max(len, 1e-12)) {
        continue;
      }
      const Segment part = SubSegment(s, iv);
      const double facing = outward[static_cast<int>(side)].dot(direction);
      const double plen = part.Length();
      if (plen > best_len + tol || (std::abs(plen - best_len) <= tol && facing > best_facing)) {
        best = Portion{part, side, true};
        best_len = plen;
        best_facing = facing;
      }
    }
  }
  if (best.found) return best;
  double best_d = std::numeric_limits<double>::infinity();
  bool best_fits = false;
  for (int i = 0; i < 4; ++i) {
    for (const Interval& iv : ClipSegmentToPolygon(sides[i], polygon)) {
      const Segment part = SubSegment(sides[i], iv);
      const double d = spott_map::DistancePointSegment(p, part);
      const bool fits = part.Length() >= min_length;
      if ((fits && !best_fits) || (fits == best_fits && d < best_d - tol)) {
        best_d = d;
        best_fits = fits;
        best = Portion{part, static_cast<WindowSide>(i), true};
      }
    }
  }
  if (best.found) {
    rule += std::string(rule.empty() ? "" : "; ") +
            "no portion of the node holds the crossing: the node's nearest portion of the border";
    return best;
  }
  rule += std::string(rule.empty() ? "" : "; ") + "the node does not meet the border: the point";
  const auto through = SidesThrough(window, p, tol);
  return Portion{Segment{p, p}, through.empty() ? WindowSide::kBottom : through.front(), true};
}

}  // namespace

const char* ToString(ProjectionCase c) {
  switch (c) {
    case ProjectionCase::kSameNodeInWindow:
      return "1: goal in the window and in the robot's node";
    case ProjectionCase::kSameNodeOutsideWindow:
      return "2: goal in the robot's node, outside the window";
    case ProjectionCase::kGeneral:
      return "3: general";
    case ProjectionCase::kGoalInWindow:
      return "goal in the window, every path edge in the window";
  }
  return "?";
}

bool EdgeWithinWindow(const spott_map::Door& door, const Box& window) {
  return window.Contains(door.opening.a) && window.Contains(door.opening.b);
}

ProjectedGoal ProjectGoalOntoWindow(const PlanningGraph& graph, const GlobalPath& path,
                                    const Vec2& robot, const Vec2& goal, const Box& window,
                                    double min_portion_m) {
  if (path.room_indices.empty() || path.room_indices.size() != path.door_indices.size() + 1) {
    throw std::invalid_argument("ProjectGoalOntoWindow: malformed path");
  }
  ProjectedGoal out;
  out.goal = goal;
  out.window = window;
  const int n_r = path.room_indices.front();
  const int n_g = path.room_indices.back();
  const bool goal_in_window = window.Contains(goal);

  const auto project = [&](const Vec2& from, const Vec2& to, int node) {
    Crossing c = BorderCrossing(from, to, robot, window);
    out.rule = c.rule;
    out.projected_point = c.point;
    out.node = node;
    out.node_id = graph.room(node).id;
    const Portion p = PortionThrough(window, c.point, graph.room(node).polygon, to - from,
                                     min_portion_m, out.rule);
    out.on_border = true;
    out.border = p.segment;
    out.side = p.side;
  };

  // Cases 1 and 2 are for a goal reached inside the robot's node. A path that leaves the node
  // and comes back (an obstacle inside it separates robot and goal) is the general case.
  if (n_g == n_r && path.door_indices.empty()) {
    if (goal_in_window) {
      out.projection_case = ProjectionCase::kSameNodeInWindow;
      return out;
    }
    out.projection_case = ProjectionCase::kSameNodeOutsideWindow;
    project(robot, goal, n_r);
    return out;
  }
  // Case 3: the first edge of the path that is not completely within the window.
  for (std::size_t k = 0; k < path.door_indices.size(); ++k) {
    const int e_k = path.door_indices[k];
    if (EdgeWithinWindow(graph.door(e_k), window)) continue;
    const int n_k = path.room_indices[k];
    out.projection_case = ProjectionCase::kGeneral;
    out.edge = e_k;
    out.edge_id = graph.door(e_k).id;
    project(graph.RoomCentre(n_k), graph.DoorCentre(e_k), n_k);
    return out;
  }
  if (goal_in_window) {
    out.projection_case = ProjectionCase::kGoalInWindow;
    return out;
  }
  // Every edge is within the window but the goal is not: the goal stands in for e_k.
  out.projection_case = ProjectionCase::kGeneral;
  project(graph.RoomCentre(n_g), goal, n_g);
  out.rule = "every edge is within the window: the goal stands in for the edge" +
             std::string(out.rule.empty() ? "" : "; ") + out.rule;
  return out;
}

}  // namespace spott_global_planner
