// Plane geometry for the Noreils-Chatila core (metres, radians, map frame unless said).
#pragma once

#include <cmath>
#include <vector>

namespace rpl_executive::noreils_chatila {

struct Point2 {
  double x = 0.0;
  double y = 0.0;
};

/// A robot posture: position (m) and heading (rad, counter-clockwise from x).
struct Pose2 {
  double x = 0.0;
  double y = 0.0;
  double yaw = 0.0;
};

constexpr double kPi = 3.14159265358979323846;

/// The angle in (-pi, pi].
double WrapAngle(double angle);

/// True when `p` is inside `polygon` or on its border (crossing-number test; the border counts
/// as inside so that a robot on the zone's edge has entered it). Polygons of fewer than three
/// points contain nothing.
bool PointInPolygon(const Point2& p, const std::vector<Point2>& polygon);

/// Signed distance of `p` from the straight line through `origin` with direction `direction`
/// (rad): positive on the left of the direction.
double SignedDistanceToLine(const Point2& p, const Point2& origin, double direction);

/// Distance of `p` from the segment from `a` to `b` (from `a` when they coincide).
double DistanceToSegment(const Point2& p, const Point2& a, const Point2& b);

inline double Distance(const Point2& a, const Point2& b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}

}  // namespace rpl_executive::noreils_chatila
