#include "rpl_executive/noreils_chatila/geometry.h"

#include <algorithm>
#include <cmath>

namespace rpl_executive::noreils_chatila {

double WrapAngle(double angle) {
  if (!std::isfinite(angle)) return angle;
  angle = std::fmod(angle, 2.0 * kPi);
  if (angle <= -kPi) angle += 2.0 * kPi;
  if (angle > kPi) angle -= 2.0 * kPi;
  return angle;
}

namespace {

bool OnSegment(const Point2& p, const Point2& a, const Point2& b) {
  const double cross = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
  const double length = std::hypot(b.x - a.x, b.y - a.y);
  if (std::fabs(cross) > 1e-9 * (length + 1.0)) return false;
  return p.x >= std::fmin(a.x, b.x) - 1e-12 && p.x <= std::fmax(a.x, b.x) + 1e-12 &&
         p.y >= std::fmin(a.y, b.y) - 1e-12 && p.y <= std::fmax(a.y, b.y) + 1e-12;
}

}  // namespace

bool PointInPolygon(const Point2& p, const std::vector<Point2>& polygon) {
  const size_t n = polygon.size();
  if (n < 3) return false;
  bool inside = false;
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point2& a = polygon[i];
    const Point2& b = polygon[j];
    if (OnSegment(p, a, b)) return true;
    if ((a.y > p.y) != (b.y > p.y)) {
      const double x_cross = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (p.x < x_cross) inside = !inside;
    }
  }
  return inside;
}

double SignedDistanceToLine(const Point2& p, const Point2& origin, double direction) {
  const double dx = p.x - origin.x;
  const double dy = p.y - origin.y;
  return std::cos(direction) * dy - std::sin(direction) * dx;
}

double DistanceToSegment(const Point2& p, const Point2& a, const Point2& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  const double t =
      len2 > 0.0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

}  // namespace rpl_executive::noreils_chatila
