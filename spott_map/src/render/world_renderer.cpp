#include "spott_map/world_renderer.h"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <utility>
#include <vector>

namespace spott_map {

namespace {

struct Rgb {
  double r, g, b;
};

constexpr Rgb kRoomFill{0.86, 0.91, 0.97};
constexpr Rgb kHallwayFill{0.98, 0.95, 0.82};
constexpr Rgb kWall{0.1, 0.1, 0.1};
constexpr Rgb kDoorOpen{0.13, 0.62, 0.25};
constexpr Rgb kDoorClosed{0.84, 0.15, 0.15};
constexpr Rgb kDoorUnknown{0.95, 0.55, 0.05};
constexpr Rgb kOpening{0.55, 0.55, 0.55};
constexpr Rgb kObjectFill{0.62, 0.55, 0.47};
constexpr Rgb kPlace{0.2, 0.3, 0.85};
constexpr Rgb kPosition{0.7, 0.1, 0.6};
constexpr Rgb kRobot{0.85, 0.1, 0.1};
constexpr Rgb kText{0.15, 0.15, 0.15};
constexpr Rgb kZone{0.55, 0.2, 0.75};
constexpr Rgb kPath{0.1, 0.45, 0.45};

// Map metres to pixels: x right, y up (the image's y runs down).
class Canvas {
 public:
  Canvas(cairo_t* cr, const Box& bounds, double scale, double top_px)
      : cr_(cr), bounds_(bounds), scale_(scale), top_px_(top_px) {}

  double X(double x) const { return (x - bounds_.min.x()) * scale_; }
  double Y(double y) const { return top_px_ + (bounds_.max.y() - y) * scale_; }
  double Scale() const { return scale_; }
  cairo_t* cr() const { return cr_; }

  void Colour(const Rgb& c, double alpha = 1.0) const {
    cairo_set_source_rgba(cr_, c.r, c.g, c.b, alpha);
  }
  void PolygonPath(const Polygon& p) const {
    cairo_new_path(cr_);
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (i == 0) {
        cairo_move_to(cr_, X(p[i].x()), Y(p[i].y()));
      } else {
        cairo_line_to(cr_, X(p[i].x()), Y(p[i].y()));
      }
    }
    cairo_close_path(cr_);
  }
  void Line(const Segment& s, double width_px) const {
    cairo_set_line_width(cr_, width_px);
    cairo_move_to(cr_, X(s.a.x()), Y(s.a.y()));
    cairo_line_to(cr_, X(s.b.x()), Y(s.b.y()));
    cairo_stroke(cr_);
  }
  void Text(double px, double py, const std::string& text, double size, bool centred) const {
    cairo_select_font_face(cr_, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr_, size);
    cairo_text_extents_t e;
    cairo_text_extents(cr_, text.c_str(), &e);
    if (centred) {
      px -= e.width / 2 + e.x_bearing;
      py -= e.height / 2 + e.y_bearing;
    }
    cairo_move_to(cr_, px, py);
    cairo_show_text(cr_, text.c_str());
  }

 private:
  cairo_t* cr_;
  Box bounds_;
  double scale_;
  double top_px_;
};

void DrawRooms(const Canvas& c, const World& w, bool labels) {
  for (const Room& room : w.rooms) {
    c.PolygonPath(room.polygon);
    c.Colour(room.kind == RoomKind::kHallway ? kHallwayFill : kRoomFill);
    cairo_fill_preserve(c.cr());
    c.Colour(kWall, 0.25);
    cairo_set_line_width(c.cr(), 1.0);
    cairo_stroke(c.cr());
  }
  if (!labels) return;
  for (const Room& room : w.rooms) {
    const Vec2 centre = Centroid(room.polygon);
    c.Colour(kText, 0.8);
    c.Text(c.X(centre.x()), c.Y(centre.y()), room.name, std::max(9.0, 0.3 * c.Scale()), true);
  }
}

void DrawWalls(const Canvas& c, const World& w) {
  c.Colour(kWall);
  cairo_set_line_cap(c.cr(), CAIRO_LINE_CAP_SQUARE);
  for (const Wall& wall : w.walls) c.Line(wall.segment, std::max(2.0, wall.thickness * c.Scale()));
}

void DrawDoors(const Canvas& c, const World& w) {
  cairo_set_line_cap(c.cr(), CAIRO_LINE_CAP_BUTT);
  for (const Door& door : w.doors) {
    if (door.kind == DoorKind::kOpening) {
      const double dash[] = {4.0, 4.0};
      cairo_set_dash(c.cr(), dash, 2, 0.0);
      c.Colour(kOpening);
      c.Line(door.opening, 1.5);
      cairo_set_dash(c.cr(), nullptr, 0, 0.0);
      continue;
    }
    const Rgb colour = door.state == DoorState::kOpen     ? kDoorOpen
                       : door.state == DoorState::kClosed ? kDoorClosed
                                                          : kDoorUnknown;
    c.Colour(colour);
    c.Line(door.opening, std::max(4.0, 0.12 * c.Scale()));
    if (door.state != DoorState::kClosed) {
      // The leaf swung open: a quarter circle from one jamb, as on architects' drawings.
      const Vec2 hinge = door.opening.a;
      const Vec2 along = door.opening.b - hinge;
      const double start = std::atan2(-along.y(), along.x());  // image y runs down
      cairo_set_line_width(c.cr(), 1.0);
      cairo_new_path(c.cr());
      cairo_arc_negative(c.cr(), c.X(hinge.x()), c.Y(hinge.y()), along.norm() * c.Scale(), start,
                         start - M_PI / 2);
      cairo_stroke(c.cr());
    }
  }
}

void DrawObjects(const Canvas& c, const World& w, bool labels) {
  for (const WorldObject& o : w.objects) {
    c.PolygonPath(o.Footprint());
    c.Colour(kObjectFill, 0.85);
    cairo_fill_preserve(c.cr());
    c.Colour(kWall, 0.8);
    cairo_set_line_width(c.cr(), 1.0);
    cairo_stroke(c.cr());
    if (labels) {
      c.Colour(kText);
      const std::string text = o.label.empty() ? o.id : o.label;
      c.Text(c.X(o.pose.x), c.Y(o.pose.y) - 0.5 * o.size_y * c.Scale() - 4, text,
             std::max(8.0, 0.22 * c.Scale()), true);
    }
  }
}

void DrawArrow(const Canvas& c, const Pose2& pose, double length_m, const Rgb& colour) {
  const double px = c.X(pose.x);
  const double py = c.Y(pose.y);
  const double l = length_m * c.Scale();
  const double a = -pose.yaw;  // image y runs down
  cairo_new_path(c.cr());
  cairo_move_to(c.cr(), px + l * std::cos(a), py + l * std::sin(a));
  cairo_line_to(c.cr(), px + 0.5 * l * std::cos(a + 2.4), py + 0.5 * l * std::sin(a + 2.4));
  cairo_line_to(c.cr(), px + 0.5 * l * std::cos(a - 2.4), py + 0.5 * l * std::sin(a - 2.4));
  cairo_close_path(c.cr());
  c.Colour(colour);
  cairo_fill(c.cr());
}

void DrawPlaces(const Canvas& c, const World& w, bool labels) {
  for (const Place& p : w.places) {
    const Rgb colour = p.kind == "position" ? kPosition : kPlace;
    c.Colour(colour);
    const double r = std::max(3.0, 0.12 * c.Scale());
    cairo_new_path(c.cr());
    if (p.kind == "localization") {  // a diamond
      cairo_move_to(c.cr(), c.X(p.pose.x), c.Y(p.pose.y) - r);
      cairo_line_to(c.cr(), c.X(p.pose.x) + r, c.Y(p.pose.y));
      cairo_line_to(c.cr(), c.X(p.pose.x), c.Y(p.pose.y) + r);
      cairo_line_to(c.cr(), c.X(p.pose.x) - r, c.Y(p.pose.y));
      cairo_close_path(c.cr());
    } else {
      cairo_arc(c.cr(), c.X(p.pose.x), c.Y(p.pose.y), r, 0, 2 * M_PI);
    }
    cairo_fill(c.cr());
    if (labels) {
      c.Text(c.X(p.pose.x) + r + 2, c.Y(p.pose.y) + r, p.name, std::max(8.0, 0.22 * c.Scale()),
             false);
    }
  }
  DrawArrow(c, w.robot_start, 0.6, kRobot);
}

void DrawZonesAndPaths(const Canvas& c, const World& w, bool labels) {
  for (const Zone& zone : w.zones) {
    c.PolygonPath(zone.polygon);
    c.Colour(kZone, 0.18);
    cairo_fill_preserve(c.cr());
    c.Colour(kZone, 0.9);
    const double dash[] = {6.0, 3.0};
    cairo_set_dash(c.cr(), dash, 2, 0.0);
    cairo_set_line_width(c.cr(), 1.5);
    cairo_stroke(c.cr());
    cairo_set_dash(c.cr(), nullptr, 0, 0.0);
    if (labels) {
      const Box b = BoundingBox(zone.polygon);
      c.Text(c.X(b.min.x()) + 3, c.Y(b.max.y()) + 14, zone.id, std::max(8.0, 0.22 * c.Scale()),
             false);
    }
  }
  for (const NamedPath& path : w.paths) {
    c.Colour(kPath);
    cairo_set_line_width(c.cr(), 2.0);
    cairo_new_path(c.cr());
    for (std::size_t i = 0; i < path.points.size(); ++i) {
      const Vec2& p = path.points[i];
      if (i == 0) {
        cairo_move_to(c.cr(), c.X(p.x()), c.Y(p.y()));
      } else {
        cairo_line_to(c.cr(), c.X(p.x()), c.Y(p.y()));
      }
    }
    cairo_stroke(c.cr());
    for (const Vec2& p : path.points) {
      cairo_arc(c.cr(), c.X(p.x()), c.Y(p.y()), 3.0, 0, 2 * M_PI);
      cairo_fill(c.cr());
    }
    if (path.final_yaw) {
      DrawArrow(c, Pose2{path.points.back().x(), path.points.back().y(), *path.final_yaw}, 0.35,
                kPath);
    }
    if (labels && !path.points.empty()) {
      c.Colour(kPath);
      c.Text(c.X(path.points[0].x()) + 4, c.Y(path.points[0].y()) - 4, path.id,
             std::max(8.0, 0.22 * c.Scale()), false);
    }
  }
}

// The legend's entries, and how many rows they need at `width_px` (entries wrap).
std::vector<std::pair<Rgb, std::string>> LegendEntries(const World& w) {
  std::vector<std::pair<Rgb, std::string>> e = {{kRoomFill, "room"},
                                                {kHallwayFill, "hallway"},
                                                {kDoorOpen, "door open"},
                                                {kDoorClosed, "door closed"},
                                                {kDoorUnknown, "door unknown"},
                                                {kObjectFill, "object (not in CAD map)"},
                                                {kPlace, "place"},
                                                {kRobot, "robot start"}};
  if (!w.zones.empty()) e.emplace_back(kZone, "zone");
  if (!w.paths.empty()) e.emplace_back(kPath, "path");
  return e;
}

double LegendEntryWidth(const std::string& text) { return 28 + 7.0 * text.size(); }

int LegendRows(const World& w, double width_px) {
  int rows = 1;
  double x = 10.0;
  for (const auto& [colour, text] : LegendEntries(w)) {
    if (x + LegendEntryWidth(text) > width_px && x > 10.0) {
      ++rows;
      x = 10.0;
    }
    x += LegendEntryWidth(text);
  }
  return rows;
}

constexpr double kLegendRowPx = 20.0;

void DrawLegendAndScale(const Canvas& c, const World& w, double width_px, double height_px) {
  const double size = 12.0;
  double x = 10.0;
  double y = height_px - LegendRows(w, width_px) * kLegendRowPx + 14.0;
  for (const auto& [colour, text] : LegendEntries(w)) {
    if (x + LegendEntryWidth(text) > width_px && x > 10.0) {
      x = 10.0;
      y += kLegendRowPx;
    }
    c.Colour(colour);
    cairo_rectangle(c.cr(), x, y - 9, 16, 9);
    cairo_fill(c.cr());
    c.Colour(kText);
    c.Text(x + 20, y, text, size, false);
    x += LegendEntryWidth(text);
  }
  const Box b = w.Bounds();
  char title[256];
  std::snprintf(title, sizeof(title), "%s  (%.1f x %.1f m, %zu rooms, %zu doors)", w.name.c_str(),
                b.max.x() - b.min.x(), b.max.y() - b.min.y(), w.rooms.size(), w.doors.size());
  c.Text(10, 20, title, 15, false);
  // A scale bar of a round number of metres: about a fifth of the width, right of the title.
  cairo_set_font_size(c.cr(), 15);
  cairo_text_extents_t title_extents;
  cairo_text_extents(c.cr(), title, &title_extents);
  const double room_for_bar =
      std::min(width_px / 5, width_px - 12 - (10 + title_extents.x_advance + 24));
  double metres = 1.0;
  for (double m : {1.0, 2.0, 5.0, 10.0, 20.0}) {
    if (m * c.Scale() <= room_for_bar) metres = m;
  }
  const double bar = metres * c.Scale();
  c.Colour(kText);
  cairo_set_line_width(c.cr(), 3.0);
  cairo_move_to(c.cr(), width_px - bar - 12, 22);
  cairo_line_to(c.cr(), width_px - 12, 22);
  cairo_stroke(c.cr());
  char text[32];
  std::snprintf(text, sizeof(text), "%g m", metres);
  c.Text(width_px - 12 - bar / 2, 12, text, size, true);
}

}  // namespace

std::optional<std::string> RenderWorldToPng(const World& world, const std::string& png_path,
                                            const RenderOptions& options) {
  if (!(options.pixels_per_metre > 0.0) || !(options.margin_m >= 0.0)) {
    return "pixels_per_metre must be > 0 and margin_m >= 0";
  }
  const Box bounds = world.Bounds().Inflated(options.margin_m);
  const double title_px = 32.0;
  const double width = (bounds.max.x() - bounds.min.x()) * options.pixels_per_metre;
  const double legend_px = options.legend ? LegendRows(world, width) * kLegendRowPx + 6.0 : 0.0;
  const double height =
      (bounds.max.y() - bounds.min.y()) * options.pixels_per_metre + title_px + legend_px;
  if (!(width >= 1.0 && height >= 1.0) || width > 20000 || height > 20000) {
    return "picture would be " + std::to_string(static_cast<long>(width)) + " x " +
           std::to_string(static_cast<long>(height)) + " pixels; choose another pixels_per_metre";
  }
  std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
      cairo_image_surface_create(CAIRO_FORMAT_ARGB32, static_cast<int>(std::ceil(width)),
                                 static_cast<int>(std::ceil(height))),
      cairo_surface_destroy);
  std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr(cairo_create(surface.get()), cairo_destroy);
  cairo_set_source_rgb(cr.get(), 1, 1, 1);
  cairo_paint(cr.get());
  const Canvas canvas(cr.get(), bounds, options.pixels_per_metre, title_px);
  DrawRooms(canvas, world, options.labels);
  DrawObjects(canvas, world, options.labels);
  DrawWalls(canvas, world);
  DrawDoors(canvas, world);
  DrawZonesAndPaths(canvas, world, options.labels);
  DrawPlaces(canvas, world, options.labels);
  if (options.legend) DrawLegendAndScale(canvas, world, width, height);
  cairo_surface_flush(surface.get());
  const cairo_status_t status = cairo_surface_write_to_png(surface.get(), png_path.c_str());
  if (status != CAIRO_STATUS_SUCCESS) {
    return "cannot write " + png_path + ": " + cairo_status_to_string(status);
  }
  return std::nullopt;
}

}  // namespace spott_map
