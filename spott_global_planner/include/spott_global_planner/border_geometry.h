// Plane geometry the goal projection needs and spott_map/geometry.h does not have: clipping a
// segment to a polygon, and the sides of an axis-aligned window and where a line crosses them.
// Metres in the map frame.
#pragma once

#include <array>
#include <optional>
#include <utility>
#include <vector>

#include "spott_map/geometry.h"

namespace spott_global_planner {

using spott_map::Box;
using spott_map::Polygon;
using spott_map::Segment;
using spott_map::Vec2;

/// Parameter interval [t0, t1] (0 <= t0 <= t1 <= 1) along a segment a + t (b - a).
using Interval = std::pair<double, double>;

/// The maximal parts of `s` that lie in the closed polygon (boundary included), in order of t.
/// A part that only touches the polygon in one point is left out.
std::vector<Interval> ClipSegmentToPolygon(const Segment& s, const Polygon& polygon);

/// The point of `s` at parameter t.
inline Vec2 PointAt(const Segment& s, double t) { return s.a + t * (s.b - s.a); }

/// The sub-segment of `s` over `interval`.
inline Segment SubSegment(const Segment& s, const Interval& interval) {
  return Segment{PointAt(s, interval.first), PointAt(s, interval.second)};
}

/// The four sides of a window, counter-clockwise: 0 bottom (y = min.y, +x), 1 right
/// (x = max.x, +y), 2 top (y = max.y, -x), 3 left (x = min.x, -y).
enum class WindowSide { kBottom = 0, kRight = 1, kTop = 2, kLeft = 3 };
std::array<Segment, 4> WindowSides(const Box& window);
const char* ToString(WindowSide side);

/// Sides whose segment holds `p` (within `tolerance` m): one for a point inside a side, two at
/// a corner, none off the border.
std::vector<WindowSide> SidesThrough(const Box& window, const Vec2& p, double tolerance = 1e-9);

/// Parameters [t_enter, t_exit] of the part of the infinite line from + t (to - from) inside
/// the closed box, or nullopt when the line misses it (or from == to).
std::optional<Interval> ClipLineToBox(const Vec2& from, const Vec2& to, const Box& box);

}  // namespace spott_global_planner
