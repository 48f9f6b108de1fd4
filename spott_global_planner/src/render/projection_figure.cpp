// projection_figure: draws the cases of SPOTT's Fig. 14 as this package computes them, on the
// building of the unit tests (rooms A, B, C along hallway H), into one PNG for the README:
//   projection_figure spott_global_planner/doc/projection_cases.png
// Each panel: rooms (thin outlines), doors (green open, red closed), the window b_pf (grey), the
// global path through door centres (green), the robot (blue), the goal (dark green), and the
// projection: the border segment (thick orange, the thick line of Fig. 14) and p_k (yellow).
#include <cairo.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "spott_global_planner/goal_projection.h"

namespace {

using spott_global_planner::GlobalPlanner;
using spott_global_planner::ProjectedGoal;
using spott_map::Box;
using spott_map::Vec2;

spott_map::Room Rect(const std::string& id, double x0, double y0, double x1, double y1) {
  spott_map::Room r;
  r.id = id;
  r.polygon = {Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)};
  return r;
}

spott_map::Door MakeDoor(const std::string& id, const std::string& a, const std::string& b,
                         const Vec2& c, bool horizontal) {
  spott_map::Door d;
  d.id = id;
  d.room_a = a;
  d.room_b = b;
  d.center = c;
  d.width = 1.0;
  const Vec2 half = horizontal ? Vec2(0.5, 0.0) : Vec2(0.0, 0.5);
  d.opening = spott_map::Segment{c - half, c + half};
  return d;
}

spott_map::RoomDoorGraph Building() {
  return spott_map::RoomDoorGraph(
      {Rect("A", 0, 0, 4, 4), Rect("B", 4, 0, 8, 4), Rect("C", 8, 0, 12, 4),
       Rect("H", 0, 4, 12, 6)},
      {MakeDoor("dAB", "A", "B", Vec2(4, 2), false), MakeDoor("dBC", "B", "C", Vec2(8, 2), false),
       MakeDoor("dAH", "A", "H", Vec2(2, 4), true), MakeDoor("dBH", "B", "H", Vec2(6, 4), true),
       MakeDoor("dCH", "C", "H", Vec2(10, 4), true)});
}

struct Panel {
  std::string title;
  Vec2 robot;
  Vec2 goal;
  Box window;
  std::vector<std::string> closed_doors = {};
};

constexpr double kScale = 40.0;  // pixels per metre
constexpr double kPanelW = 13.0 * kScale, kPanelH = 8.2 * kScale;

void Draw(cairo_t* cr, double ox, double oy, const Panel& panel, GlobalPlanner& planner) {
  // Map (x right, y up) to the panel (origin at its top-left, 0.5 m margin).
  const auto X = [&](double x) { return ox + (x + 0.5) * kScale; };
  const auto Y = [&](double y) { return oy + kPanelH - (y + 0.7) * kScale; };
  for (int d = 0; d < planner.graph().door_count(); ++d) {
    planner.mutable_graph().SetDoorState(planner.graph().door(d).id,
                                         spott_map::DoorState::kUnknown);
  }
  for (const std::string& id : panel.closed_doors) {
    planner.mutable_graph().SetDoorState(id, spott_map::DoorState::kClosed);
  }
  const auto& graph = planner.graph();
  const auto result = planner.Plan(panel.robot, panel.goal);
  if (!result.ok()) return;
  const ProjectedGoal p = spott_global_planner::ProjectGoalOntoWindow(
      graph, *result.path, panel.robot, panel.goal, panel.window);

  cairo_set_source_rgb(cr, 0.85, 0.85, 0.85);  // the window b_pf, shaded as in Fig. 14
  cairo_rectangle(cr, X(panel.window.min.x()), Y(panel.window.max.y()),
                  (panel.window.max.x() - panel.window.min.x()) * kScale,
                  (panel.window.max.y() - panel.window.min.y()) * kScale);
  cairo_fill(cr);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);  // rooms: the thin wall lines
  cairo_set_line_width(cr, 1.5);
  for (int r = 0; r < graph.room_count(); ++r) {
    const auto& poly = graph.room(r).polygon;
    cairo_move_to(cr, X(poly[0].x()), Y(poly[0].y()));
    for (const Vec2& v : poly) cairo_line_to(cr, X(v.x()), Y(v.y()));
    cairo_close_path(cr);
    cairo_stroke(cr);
    const Vec2 c = graph.RoomCentre(r);
    cairo_move_to(cr, X(c.x()) - 5, Y(c.y()) + 5);
    cairo_show_text(cr, graph.room(r).id.c_str());
  }
  cairo_set_line_width(cr, 5.0);  // doors
  for (int d = 0; d < graph.door_count(); ++d) {
    const auto& s = graph.door(d).opening;
    if (graph.DoorPassable(d)) {
      cairo_set_source_rgb(cr, 0.2, 0.7, 0.2);
    } else {
      cairo_set_source_rgb(cr, 0.85, 0.1, 0.1);
    }
    cairo_move_to(cr, X(s.a.x()), Y(s.a.y()));
    cairo_line_to(cr, X(s.b.x()), Y(s.b.y()));
    cairo_stroke(cr);
  }
  cairo_set_source_rgba(cr, 0.1, 0.6, 0.2, 0.8);  // the global path
  cairo_set_line_width(cr, 2.0);
  const double dash[] = {6.0, 4.0};
  cairo_set_dash(cr, dash, 2, 0.0);
  const auto& w = result.path->waypoints;
  cairo_move_to(cr, X(w[0].x()), Y(w[0].y()));
  for (const Vec2& v : w) cairo_line_to(cr, X(v.x()), Y(v.y()));
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0.0);
  if (p.on_border) {  // the projection: the thick line of Fig. 14, and p_k
    cairo_set_source_rgb(cr, 1.0, 0.5, 0.0);
    cairo_set_line_width(cr, 8.0);
    cairo_move_to(cr, X(p.border.a.x()), Y(p.border.a.y()));
    cairo_line_to(cr, X(p.border.b.x()), Y(p.border.b.y()));
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.95, 0.85, 0.0);
    cairo_arc(cr, X(p.projected_point.x()), Y(p.projected_point.y()), 6, 0, 2 * M_PI);
    cairo_fill(cr);
  }
  cairo_set_source_rgb(cr, 0.1, 0.3, 0.9);  // robot
  cairo_arc(cr, X(panel.robot.x()), Y(panel.robot.y()), 7, 0, 2 * M_PI);
  cairo_fill(cr);
  cairo_set_source_rgb(cr, 0.0, 0.45, 0.1);  // goal
  cairo_rectangle(cr, X(panel.goal.x()) - 6, Y(panel.goal.y()) - 6, 12, 12);
  cairo_fill(cr);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_move_to(cr, ox + 8, oy + 18);
  cairo_show_text(cr, panel.title.c_str());
  std::string detail = std::string("case ") + spott_global_planner::ToString(p.projection_case);
  if (!p.edge_id.empty()) detail += ", e_k = " + p.edge_id;
  if (!p.node_id.empty()) detail += ", n = " + p.node_id;
  cairo_move_to(cr, ox + 8, oy + 36);
  cairo_show_text(cr, detail.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: projection_figure OUT.png\n");
    return 2;
  }
  GlobalPlanner planner(Building());
  const std::vector<Panel> panels = {
      {"(1) goal in b_pf and in n_r", Vec2(3, 5), Vec2(4, 5.5), Box{Vec2(1, 3), Vec2(5, 7)}},
      {"(2) goal in n_r outside b_pf", Vec2(3, 5), Vec2(10, 5), Box{Vec2(1, 3), Vec2(5, 7)}},
      {"(3) general: first edge outside b_pf", Vec2(3, 3), Vec2(10, 2),
       Box{Vec2(1, 1), Vec2(5, 5)}},
      {"(4) goal in b_pf, every edge inside", Vec2(3, 2), Vec2(4.5, 2),
       Box{Vec2(1, 0), Vec2(5, 4)}},
      {"(3) with dBC closed: replanned through H",
       Vec2(2, 2),
       Vec2(11, 1),
       Box{Vec2(0.5, 0.5), Vec2(3.5, 3.5)},
       {"dBC"}},
      {"(3) p_k at a window corner: the longer side in n_k", Vec2(6.5, 5.5), Vec2(11, 1),
       Box{Vec2(5, 4.5), Vec2(8, 7.5)}}};
  const int width = static_cast<int>(2 * kPanelW), height = static_cast<int>(3 * kPanelH);
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, 14);
  for (std::size_t i = 0; i < panels.size(); ++i) {
    Draw(cr, (i % 2) * kPanelW, (i / 2) * kPanelH, panels[i], planner);
  }
  cairo_destroy(cr);
  const cairo_status_t status = cairo_surface_write_to_png(surface, argv[1]);
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS) {
    std::fprintf(stderr, "projection_figure: cannot write %s: %s\n", argv[1],
                 cairo_status_to_string(status));
    return 1;
  }
  return 0;
}
