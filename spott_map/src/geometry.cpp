#include "spott_map/geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace spott_map {

Vec2 Segment::Direction() const {
  const Vec2 d = b - a;
  const double n = d.norm();
  return n > 0.0 ? Vec2(d / n) : Vec2(0.0, 0.0);
}

bool Box::Contains(const Vec2& p) const {
  return p.x() >= min.x() && p.x() <= max.x() && p.y() >= min.y() && p.y() <= max.y();
}

bool Box::Intersects(const Box& other) const {
  return min.x() <= other.max.x() && other.min.x() <= max.x() && min.y() <= other.max.y() &&
         other.min.y() <= max.y();
}

Box Box::Inflated(double margin) const {
  return Box{min - Vec2(margin, margin), max + Vec2(margin, margin)};
}

Box LatticeWindow(const Vec2& centre, int cells, double resolution_m) {
  const double side = cells * resolution_m;
  const Vec2 corner = centre - Vec2(0.5 * side, 0.5 * side);
  const Vec2 origin(std::round(corner.x() / resolution_m) * resolution_m,
                    std::round(corner.y() / resolution_m) * resolution_m);
  return Box{origin, origin + Vec2(side, side)};
}

double Cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

Vec2 ClosestPointOnSegment(const Vec2& p, const Segment& s) {
  const Vec2 d = s.b - s.a;
  const double len2 = d.squaredNorm();
  if (len2 <= 0.0) return s.a;
  const double t = std::clamp((p - s.a).dot(d) / len2, 0.0, 1.0);
  return s.a + t * d;
}

double DistancePointSegment(const Vec2& p, const Segment& s) {
  return (p - ClosestPointOnSegment(p, s)).norm();
}

namespace {

// Orientation of the triple (a, b, c): +1 counter-clockwise, -1 clockwise, 0 collinear.
int Orientation(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double v = Cross(b - a, c - a);
  const double scale = std::max({(b - a).norm() * (c - a).norm(), 1e-300});
  if (std::abs(v) <= 1e-12 * scale) return 0;
  return v > 0 ? 1 : -1;
}

bool OnSegment(const Vec2& p, const Segment& s) {
  return DistancePointSegment(p, s) <= 1e-12 * std::max(1.0, s.Length());
}

}  // namespace

bool SegmentsCrossProperly(const Segment& s, const Segment& t) {
  const int o1 = Orientation(s.a, s.b, t.a);
  const int o2 = Orientation(s.a, s.b, t.b);
  const int o3 = Orientation(t.a, t.b, s.a);
  const int o4 = Orientation(t.a, t.b, s.b);
  return o1 * o2 < 0 && o3 * o4 < 0;
}

double DistanceSegmentSegment(const Segment& s, const Segment& t) {
  if (SegmentsCrossProperly(s, t)) return 0.0;
  return std::min({DistancePointSegment(s.a, t), DistancePointSegment(s.b, t),
                   DistancePointSegment(t.a, s), DistancePointSegment(t.b, s)});
}

std::optional<Vec2> SegmentIntersection(const Segment& s, const Segment& t) {
  const Vec2 r = s.b - s.a;
  const Vec2 q = t.b - t.a;
  const double denom = Cross(r, q);
  if (std::abs(denom) <= 1e-15 * std::max(1.0, r.norm() * q.norm())) {
    // Parallel. Only collinear segments that touch in a single point intersect "once".
    const double r2 = r.squaredNorm();
    if (r2 <= 0.0) return OnSegment(s.a, t) ? std::optional<Vec2>(s.a) : std::nullopt;
    if (Orientation(s.a, s.b, t.a) != 0 || Orientation(s.a, s.b, t.b) != 0) return std::nullopt;
    const double u0 = (t.a - s.a).dot(r) / r2;
    const double u1 = (t.b - s.a).dot(r) / r2;
    const double lo = std::max(0.0, std::min(u0, u1));
    const double hi = std::min(1.0, std::max(u0, u1));
    if (hi < lo - 1e-12 || hi - lo > 1e-12) return std::nullopt;
    return Vec2(s.a + lo * r);
  }
  const double u = Cross(t.a - s.a, q) / denom;
  const double v = Cross(t.a - s.a, r) / denom;
  const double eps = 1e-12;
  if (u < -eps || u > 1.0 + eps || v < -eps || v > 1.0 + eps) return std::nullopt;
  return Vec2(s.a + std::clamp(u, 0.0, 1.0) * r);
}

double SignedArea(const Polygon& polygon) {
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    twice += Cross(polygon[i], polygon[(i + 1) % polygon.size()]);
  }
  return 0.5 * twice;
}

Vec2 Centroid(const Polygon& polygon) {
  if (polygon.empty()) return Vec2(0.0, 0.0);
  const double area = SignedArea(polygon);
  Vec2 mean(0.0, 0.0);
  for (const Vec2& p : polygon) mean += p;
  mean /= static_cast<double>(polygon.size());
  if (std::abs(area) < 1e-12) return mean;
  // Shift to the vertex mean first to keep the sums well conditioned.
  Vec2 c(0.0, 0.0);
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2 p = polygon[i] - mean;
    const Vec2 q = polygon[(i + 1) % polygon.size()] - mean;
    c += (p + q) * Cross(p, q);
  }
  return mean + c / (6.0 * area);
}

Box BoundingBox(const Polygon& polygon) {
  Box box{polygon.front(), polygon.front()};
  for (const Vec2& p : polygon) {
    box.min = box.min.cwiseMin(p);
    box.max = box.max.cwiseMax(p);
  }
  return box;
}

Segment PolygonEdge(const Polygon& polygon, std::size_t i) {
  return Segment{polygon[i], polygon[(i + 1) % polygon.size()]};
}

std::optional<std::pair<std::size_t, std::size_t>> FindSelfIntersection(const Polygon& polygon) {
  const std::size_t n = polygon.size();
  if (n < 3) return std::nullopt;
  for (std::size_t i = 0; i < n; ++i) {
    const Segment e = PolygonEdge(polygon, i);
    for (std::size_t j = i + 1; j < n; ++j) {
      const bool adjacent = (j == i + 1) || (i == 0 && j == n - 1);
      const Segment f = PolygonEdge(polygon, j);
      if (adjacent) {
        // Adjacent edges share one vertex; they must not fold back onto each other.
        const Vec2 shared = (j == i + 1) ? e.b : e.a;
        const Vec2 e_other = (j == i + 1) ? e.a : e.b;
        const Vec2 f_other = (j == i + 1) ? f.b : f.a;
        const Vec2 u = e_other - shared;
        const Vec2 v = f_other - shared;
        const bool collinear = std::abs(Cross(u, v)) <= 1e-12 * u.norm() * v.norm();
        if (collinear && u.dot(v) > 0.0) return std::make_pair(i, j);
        continue;
      }
      if (DistanceSegmentSegment(e, f) <= 1e-9) return std::make_pair(i, j);
    }
  }
  return std::nullopt;
}

double DistanceToBoundary(const Vec2& p, const Polygon& polygon) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    best = std::min(best, DistancePointSegment(p, PolygonEdge(polygon, i)));
  }
  return best;
}

bool PointInPolygon(const Vec2& p, const Polygon& polygon, double boundary_tolerance) {
  if (polygon.size() < 3) return false;
  if (DistanceToBoundary(p, polygon) <= boundary_tolerance) return true;
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x) inside = !inside;
    }
  }
  return inside;
}

namespace {

// True when some piece of p's boundary runs through q's interior farther than `tolerance` from
// q's boundary. Each edge of p is cut where it meets q's boundary and the middle of every piece
// is tested, so crossings through vertices (T-junctions) are seen too.
bool BoundaryEntersInterior(const Polygon& p, const Polygon& q, double tolerance) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Segment e = PolygonEdge(p, i);
    const Vec2 d = e.b - e.a;
    const double len2 = d.squaredNorm();
    if (len2 <= 0.0) continue;
    std::vector<double> cuts{0.0, 1.0};
    for (std::size_t j = 0; j < q.size(); ++j) {
      const Segment f = PolygonEdge(q, j);
      if (auto x = SegmentIntersection(e, f)) cuts.push_back((*x - e.a).dot(d) / len2);
      // Collinear overlaps: cut at the other edge's ends where they lie on this edge.
      for (const Vec2& end : {f.a, f.b}) {
        if (DistancePointSegment(end, e) <= 1e-9) cuts.push_back((end - e.a).dot(d) / len2);
      }
    }
    std::sort(cuts.begin(), cuts.end());
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      if (cuts[k + 1] - cuts[k] <= 1e-12) continue;
      const Vec2 mid = e.a + 0.5 * (cuts[k] + cuts[k + 1]) * d;
      if (PointInPolygon(mid, q, 0.0) && DistanceToBoundary(mid, q) > tolerance) return true;
    }
  }
  return false;
}

// A point inside p, just to the inner side of the middle of its longest edge.
Vec2 PointJustInside(const Polygon& p, double offset) {
  std::size_t longest = 0;
  for (std::size_t i = 1; i < p.size(); ++i) {
    if (PolygonEdge(p, i).Length() > PolygonEdge(p, longest).Length()) longest = i;
  }
  const Segment e = PolygonEdge(p, longest);
  const Vec2 d = e.Direction();
  const Vec2 left(-d.y(), d.x());  // the interior of a counter-clockwise polygon is on the left
  return e.Midpoint() + (SignedArea(p) >= 0.0 ? offset : -offset) * left;
}

}  // namespace

bool PolygonsOverlap(const Polygon& p, const Polygon& q, double tolerance) {
  if (p.size() < 3 || q.size() < 3) return false;
  if (!BoundingBox(p).Inflated(-tolerance).Intersects(BoundingBox(q))) return false;
  if (BoundaryEntersInterior(p, q, tolerance) || BoundaryEntersInterior(q, p, tolerance)) {
    return true;
  }
  // Neither boundary enters the other's interior: the interiors overlap only if the polygons
  // coincide. Test a point just inside one of them.
  const Vec2 inside = PointJustInside(p, 2.0 * tolerance);
  return PointInPolygon(inside, p, 0.0) && PointInPolygon(inside, q, 0.0) &&
         DistanceToBoundary(inside, q) > tolerance;
}

double NormalizeAngle(double radians) {
  double a = std::fmod(radians + M_PI, 2.0 * M_PI);
  if (a <= 0.0) a += 2.0 * M_PI;
  return a - M_PI;
}

}  // namespace spott_map
