#include "spott_global_planner/ros/conversions.h"

#include <cmath>

#include "spott_map/ros/conversions.h"

namespace spott_global_planner::ros_conversions {

namespace {

geometry_msgs::Point P(const Vec2& v, double z = 0.0) {
  return spott_map::ros_conversions::ToPoint(v, z);
}

using spott_map::ros_conversions::Colour;

visualization_msgs::Marker Base(const std::string& ns, int id, int type,
                                const std::string& frame_id, const ros::Time& stamp) {
  return spott_map::ros_conversions::MakeMarker(ns, id, type, frame_id, stamp);
}

visualization_msgs::Marker Delete(const std::string& ns, int id, const std::string& frame_id,
                                  const ros::Time& stamp) {
  visualization_msgs::Marker m = Base(ns, id, visualization_msgs::Marker::SPHERE, frame_id, stamp);
  m.action = visualization_msgs::Marker::DELETE;
  return m;
}

}  // namespace

spott_msgs::GlobalPath ToMsg(const GlobalPath& path, const std::string& frame_id,
                             const ros::Time& stamp) {
  spott_msgs::GlobalPath msg;
  msg.header.frame_id = frame_id;
  msg.header.stamp = stamp;
  msg.rooms = path.rooms;
  msg.doors = path.doors;
  for (const Vec2& w : path.waypoints) msg.waypoints.push_back(P(w));
  msg.cost = path.cost;
  return msg;
}

std::string PathSummary(const GlobalPath& path) {
  std::string text;
  for (std::size_t i = 0; i < path.rooms.size(); ++i) {
    text += (i == 0 ? "" : " -> ") + path.rooms[i];
    if (i < path.doors.size()) text += " -> " + path.doors[i];
  }
  return text;
}

geometry_msgs::Polygon WindowToPolygon(const spott_map::Box& w) {
  geometry_msgs::Polygon poly;
  const Vec2 corners[4] = {w.min, Vec2(w.max.x(), w.min.y()), w.max, Vec2(w.min.x(), w.max.y())};
  for (const Vec2& c : corners) {
    geometry_msgs::Point32 p;
    p.x = static_cast<float>(c.x());
    p.y = static_cast<float>(c.y());
    poly.points.push_back(p);
  }
  return poly;
}

std::optional<spott_map::Box> WindowFromPolygon(const geometry_msgs::Polygon& polygon) {
  if (polygon.points.empty()) return std::nullopt;
  spott_map::Box box{Vec2(polygon.points[0].x, polygon.points[0].y),
                     Vec2(polygon.points[0].x, polygon.points[0].y)};
  for (const auto& p : polygon.points) {
    const Vec2 v(p.x, p.y);
    if (!v.allFinite()) return std::nullopt;
    box.min = box.min.cwiseMin(v);
    box.max = box.max.cwiseMax(v);
  }
  return box;
}

spott_msgs::ProjectedGoal ToMsg(const ProjectedGoal& goal, const std::string& frame_id,
                                const ros::Time& stamp) {
  spott_msgs::ProjectedGoal msg;
  msg.header.frame_id = frame_id;
  msg.header.stamp = stamp;
  msg.projection_case = static_cast<std::uint8_t>(goal.projection_case);
  msg.goal = P(goal.goal);
  msg.on_border = goal.on_border;
  if (goal.on_border) {
    msg.border_start = P(goal.border.a);
    msg.border_end = P(goal.border.b);
    msg.projected_point = P(goal.projected_point);
  } else {
    msg.border_start = msg.border_end = msg.projected_point = P(goal.goal);
  }
  msg.edge_id = goal.edge_id;
  msg.node_id = goal.node_id;
  msg.window = WindowToPolygon(goal.window);
  return msg;
}

visualization_msgs::MarkerArray ToMarkers(const PlanningGraph& graph, const GlobalPath* path,
                                          const ProjectedGoal* projection,
                                          const std::string& frame_id, const ros::Time& stamp) {
  using visualization_msgs::Marker;
  visualization_msgs::MarkerArray out;
  // The graph: node centres, and each door as centre -> door -> centre.
  Marker nodes = Base("graph_nodes", 0, Marker::SPHERE_LIST, frame_id, stamp);
  nodes.scale.x = nodes.scale.y = nodes.scale.z = 0.25;
  nodes.color = Colour(0.2f, 0.4f, 1.0f, 0.8f);
  for (int r = 0; r < graph.room_count(); ++r) nodes.points.push_back(P(graph.RoomCentre(r), 0.05));
  out.markers.push_back(nodes);
  Marker open = Base("graph_edges", 0, Marker::LINE_LIST, frame_id, stamp);
  open.scale.x = 0.04;
  open.color = Colour(0.2f, 0.4f, 1.0f, 0.6f);
  Marker closed = Base("graph_edges", 1, Marker::LINE_LIST, frame_id, stamp);
  closed.scale.x = 0.06;
  closed.color = Colour(0.9f, 0.1f, 0.1f, 0.9f);
  for (int d = 0; d < graph.door_count(); ++d) {
    const auto [a, b] = graph.DoorRooms(d);
    Marker& m = graph.DoorPassable(d) ? open : closed;
    for (const Vec2& p :
         {graph.RoomCentre(a), graph.DoorCentre(d), graph.DoorCentre(d), graph.RoomCentre(b)}) {
      m.points.push_back(P(p, 0.05));
    }
  }
  // A blocked passage: its two doors joined through the node's centre, in magenta.
  Marker blocked = Base("graph_edges", 2, Marker::LINE_LIST, frame_id, stamp);
  blocked.scale.x = 0.08;
  blocked.color = Colour(0.9f, 0.0f, 0.9f, 0.9f);
  for (const BlockedPassage& p : graph.BlockedPassages()) {
    const int r = *graph.FindRoom(p.room);
    const Vec2 a = graph.DoorCentre(*graph.FindDoor(p.door_a));
    const Vec2 b = graph.DoorCentre(*graph.FindDoor(p.door_b));
    for (const Vec2& q : {a, graph.RoomCentre(r), graph.RoomCentre(r), b}) {
      blocked.points.push_back(P(q, 0.07));
    }
  }
  // rviz refuses an empty LINE_LIST: delete it instead.
  for (Marker* m : {&open, &closed, &blocked}) {
    out.markers.push_back(m->points.empty() ? Delete(m->ns, m->id, frame_id, stamp) : *m);
  }

  if (path && path->waypoints.size() >= 2) {
    Marker line = Base("path", 0, Marker::LINE_STRIP, frame_id, stamp);
    line.scale.x = 0.1;
    line.color = Colour(0.1f, 0.8f, 0.2f, 0.9f);
    for (const Vec2& w : path->waypoints) line.points.push_back(P(w, 0.1));
    out.markers.push_back(line);
  } else {
    out.markers.push_back(Delete("path", 0, frame_id, stamp));
  }

  if (projection) {
    Marker window = Base("window", 0, Marker::LINE_STRIP, frame_id, stamp);
    window.scale.x = 0.05;
    window.color = Colour(0.6f, 0.6f, 0.6f, 0.9f);
    const auto& w = projection->window;
    for (const Vec2& c :
         {w.min, Vec2(w.max.x(), w.min.y()), w.max, Vec2(w.min.x(), w.max.y()), w.min}) {
      window.points.push_back(P(c, 0.02));
    }
    out.markers.push_back(window);
    if (projection->on_border) {
      Marker border = Base("border", 0, Marker::LINE_LIST, frame_id, stamp);
      border.scale.x = 0.2;  // the thick line of Fig. 14
      border.color = Colour(1.0f, 0.55f, 0.0f, 1.0f);
      border.points = {P(projection->border.a, 0.12), P(projection->border.b, 0.12)};
      out.markers.push_back(border);
    } else {
      out.markers.push_back(Delete("border", 0, frame_id, stamp));
    }
    Marker point = Base("projected_goal", 0, Marker::SPHERE, frame_id, stamp);
    point.scale.x = point.scale.y = point.scale.z = 0.3;
    point.color = Colour(1.0f, 0.85f, 0.0f, 1.0f);
    point.pose.position =
        P(projection->on_border ? projection->projected_point : projection->goal, 0.15);
    out.markers.push_back(point);
    Marker goal = Base("projected_goal", 1, Marker::CYLINDER, frame_id, stamp);
    goal.scale.x = goal.scale.y = 0.3;
    goal.scale.z = 0.02;
    goal.color = Colour(0.1f, 0.8f, 0.2f, 0.9f);
    goal.pose.position = P(projection->goal, 0.01);
    out.markers.push_back(goal);
    Marker text = Base("projection_case", 0, Marker::TEXT_VIEW_FACING, frame_id, stamp);
    text.scale.z = 0.35;
    text.color = Colour(1, 1, 1);
    text.pose.position = P(Vec2(w.min.x(), w.max.y() + 0.4), 0.2);
    text.text = std::string("case ") + ToString(projection->projection_case) +
                (projection->edge_id.empty() ? "" : "  e_k=" + projection->edge_id) +
                (projection->node_id.empty() ? "" : "  n=" + projection->node_id) +
                (projection->rule.empty() ? "" : "\n" + projection->rule);
    out.markers.push_back(text);
  } else {
    for (const char* ns : {"window", "border", "projected_goal", "projection_case"}) {
      out.markers.push_back(Delete(ns, 0, frame_id, stamp));
    }
    out.markers.push_back(Delete("projected_goal", 1, frame_id, stamp));
  }
  return out;
}

}  // namespace spott_global_planner::ros_conversions
