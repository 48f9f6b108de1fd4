// Plane geometry used by the map database: points, segments and simple polygons.
// All coordinates are metres in the map frame unless a comment says otherwise.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace spott_map {

using Vec2 = Eigen::Vector2d;

/// A straight segment from `a` to `b` (metres).
struct Segment {
  Vec2 a{0.0, 0.0};
  Vec2 b{0.0, 0.0};
  double Length() const { return (b - a).norm(); }
  Vec2 Direction() const;  ///< Unit vector from a to b; zero for a degenerate segment.
  Vec2 Midpoint() const { return 0.5 * (a + b); }
};

/// A polygon as its vertex list, without repeating the first vertex at the end.
using Polygon = std::vector<Vec2>;

/// An axis-aligned box [min, max] (metres).
struct Box {
  Vec2 min{0.0, 0.0};
  Vec2 max{0.0, 0.0};
  bool Contains(const Vec2& p) const;
  bool Intersects(const Box& other) const;
  Box Inflated(double margin) const;
};

/// The square window of `cells` x `cells` cells of `resolution_m` centred as near `centre` as the
/// global lattice of cells allows (its corner on multiples of the resolution), so that successive
/// windows share cells and the local and global planners place the same window. The one
/// window-snapping rule of the stack (LocalMap::Recentre, the global planner's WindowTracker).
Box LatticeWindow(const Vec2& centre, int cells, double resolution_m);

/// z component of the cross product (a x b).
double Cross(const Vec2& a, const Vec2& b);

/// Distance from `p` to the closest point of `s`.
double DistancePointSegment(const Vec2& p, const Segment& s);

/// Closest point of `s` to `p`.
Vec2 ClosestPointOnSegment(const Vec2& p, const Segment& s);

/// Smallest distance between two segments (0 when they touch or cross).
double DistanceSegmentSegment(const Segment& s, const Segment& t);

/// True when the segments share a point that is interior to both (a proper crossing).
/// Touching at an end point or overlapping collinearly is not a proper crossing.
bool SegmentsCrossProperly(const Segment& s, const Segment& t);

/// The intersection point of two segments, if they intersect in exactly one point.
std::optional<Vec2> SegmentIntersection(const Segment& s, const Segment& t);

/// Signed area (m^2): positive for counter-clockwise vertex order.
double SignedArea(const Polygon& polygon);

/// Area centroid of a simple polygon (falls back to the vertex mean for zero area).
Vec2 Centroid(const Polygon& polygon);

/// Bounding box of a non-empty point set.
Box BoundingBox(const Polygon& polygon);

/// Edge i of a polygon: vertex i to vertex i+1 (wrapping).
Segment PolygonEdge(const Polygon& polygon, std::size_t i);

/// The first pair of non-adjacent edges (i, j) that touch or cross, if any. A polygon without
/// such a pair (and with at least three vertices) is simple.
std::optional<std::pair<std::size_t, std::size_t>> FindSelfIntersection(const Polygon& polygon);

/// Even-odd point-in-polygon test; points on the boundary (within `boundary_tolerance`) count as
/// inside.
bool PointInPolygon(const Vec2& p, const Polygon& polygon, double boundary_tolerance = 1e-9);

/// Distance from `p` to the polygon's boundary.
double DistanceToBoundary(const Vec2& p, const Polygon& polygon);

/// True when the interiors of two simple polygons overlap by more than a sliver: an edge of one
/// properly crosses an edge of the other, or a vertex of one lies inside the other farther than
/// `tolerance` from its boundary. Polygons that only share edges do not overlap.
bool PolygonsOverlap(const Polygon& p, const Polygon& q, double tolerance);

/// Normalizes an angle to (-pi, pi].
double NormalizeAngle(double radians);

}  // namespace spott_map
