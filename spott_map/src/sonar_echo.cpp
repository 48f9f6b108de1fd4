#include "spott_map/sonar_echo.h"

#include <algorithm>
#include <cmath>

namespace spott_map {

double ConeExcess(const SonarEcho& e, double toward, double* side) {
  const double alpha = std::remainder(toward - e.axis, 2.0 * M_PI);
  *side = alpha < 0 ? -1.0 : 1.0;
  return std::max(0.0, std::abs(alpha) - e.half_cone);
}

std::optional<PredictedEcho> PredictEcho(const SonarEcho& e, const Vec2& normal, double offset,
                                         double max_incidence_rad) {
  const double dist = normal.dot(e.from) - offset;
  if (!(dist > 1e-6)) return std::nullopt;
  double side;
  const double excess = ConeExcess(e, std::atan2(-normal.y(), -normal.x()), &side);
  if (excess <= 0.0) return PredictedEcho{dist, e.from - dist * normal, 0.0};
  if (excess > max_incidence_rad) return std::nullopt;
  // The cone's edge nearest the normal meets the wall first.
  const double ray = e.axis + side * e.half_cone;
  const double range = dist / std::cos(excess);
  return PredictedEcho{range, e.from + range * Vec2(std::cos(ray), std::sin(ray)), excess};
}

}  // namespace spott_map
