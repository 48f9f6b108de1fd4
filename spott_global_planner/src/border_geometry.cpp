#include "spott_global_planner/border_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace spott_global_planner {

namespace {

constexpr double kParamEps = 1e-12;

// Parameters along s where it meets edge e: one for a crossing, two (both ends of the overlap)
// when they are collinear and overlap.
void AddMeetings(const Segment& s, const Segment& e, std::vector<double>& ts) {
  const Vec2 r = s.b - s.a;
  const Vec2 q = e.b - e.a;
  const double denom = spott_map::Cross(r, q);
  const double scale = std::max(1.0, r.norm() * q.norm());
  if (std::abs(denom) <= 1e-14 * scale) {
    // Parallel: only collinear overlaps matter.
    if (std::abs(spott_map::Cross(e.a - s.a, r)) > 1e-12 * std::max(1.0, r.norm())) return;
    const double r2 = r.squaredNorm();
    if (r2 <= 0.0) return;
    ts.push_back((e.a - s.a).dot(r) / r2);
    ts.push_back((e.b - s.a).dot(r) / r2);
    return;
  }
  const double u = spott_map::Cross(e.a - s.a, q) / denom;
  const double v = spott_map::Cross(e.a - s.a, r) / denom;
  if (v < -1e-12 || v > 1.0 + 1e-12) return;
  ts.push_back(u);
}

}  // namespace

std::vector<Interval> ClipSegmentToPolygon(const Segment& s, const Polygon& polygon) {
  std::vector<Interval> parts;
  if (polygon.size() < 3 || s.Length() <= 0.0) return parts;
  std::vector<double> ts{0.0, 1.0};
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    AddMeetings(s, spott_map::PolygonEdge(polygon, i), ts);
  }
  for (double& t : ts) t = std::clamp(t, 0.0, 1.0);
  std::sort(ts.begin(), ts.end());
  ts.erase(std::unique(ts.begin(), ts.end(),
                       [](double a, double b) { return std::abs(a - b) <= kParamEps; }),
           ts.end());
  // Between two consecutive meetings the segment is wholly inside or wholly outside: test the
  // middle of each piece and merge inside pieces that touch.
  const double tolerance = 1e-9 * std::max(1.0, s.Length());
  for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
    const double mid = 0.5 * (ts[i] + ts[i + 1]);
    if (!spott_map::PointInPolygon(PointAt(s, mid), polygon, tolerance)) continue;
    if (!parts.empty() && std::abs(parts.back().second - ts[i]) <= kParamEps) {
      parts.back().second = ts[i + 1];
    } else {
      parts.emplace_back(ts[i], ts[i + 1]);
    }
  }
  return parts;
}

std::array<Segment, 4> WindowSides(const Box& w) {
  const Vec2 bl = w.min;
  const Vec2 br(w.max.x(), w.min.y());
  const Vec2 tr = w.max;
  const Vec2 tl(w.min.x(), w.max.y());
  return {Segment{bl, br}, Segment{br, tr}, Segment{tr, tl}, Segment{tl, bl}};
}

const char* ToString(WindowSide side) {
  switch (side) {
    case WindowSide::kBottom:
      return "bottom";
    case WindowSide::kRight:
      return "right";
    case WindowSide::kTop:
      return "top";
    case WindowSide::kLeft:
      return "left";
  }
  return "?";
}

std::vector<WindowSide> SidesThrough(const Box& window, const Vec2& p, double tolerance) {
  std::vector<WindowSide> sides;
  const auto sides_segments = WindowSides(window);
  for (int i = 0; i < 4; ++i) {
    if (spott_map::DistancePointSegment(p, sides_segments[i]) <= tolerance) {
      sides.push_back(static_cast<WindowSide>(i));
    }
  }
  return sides;
}

std::optional<Interval> ClipLineToBox(const Vec2& from, const Vec2& to, const Box& box) {
  const Vec2 d = to - from;
  if (d.squaredNorm() <= 0.0) return std::nullopt;
  double t0 = -std::numeric_limits<double>::infinity();
  double t1 = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 2; ++k) {
    if (d[k] == 0.0) {
      if (from[k] < box.min[k] || from[k] > box.max[k]) return std::nullopt;
      continue;
    }
    double a = (box.min[k] - from[k]) / d[k];
    double b = (box.max[k] - from[k]) / d[k];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  if (t0 > t1) return std::nullopt;
  return Interval(t0, t1);
}

}  // namespace spott_global_planner
