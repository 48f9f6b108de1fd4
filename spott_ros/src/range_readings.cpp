#include "spott_ros/range_readings.h"

#include <cmath>
#include <limits>

namespace spott_ros {

int DiscardImpossibleRanges(double max_range, std::vector<double>* ranges) {
  int first = -1;
  for (std::size_t i = 0; i < ranges->size(); ++i) {
    double& r = (*ranges)[i];
    if (std::isnan(r) || (r >= 0.0 && r <= max_range * 1.001)) continue;
    if (first < 0) first = static_cast<int>(i);
    r = std::numeric_limits<double>::quiet_NaN();
  }
  return first;
}

std::string RangeRingProblem(const spott_msgs::RangeRing& ring) {
  if (!(std::isfinite(ring.max_range) && ring.max_range > 0.0f && ring.max_range < 1000.0f))
    return "max_range: " + std::to_string(ring.max_range) + " is not in (0, 1000) m";
  if (!(ring.min_range >= 0.0f && ring.min_range < ring.max_range))
    return "min_range: " + std::to_string(ring.min_range) + " is not in [0, max_range)";
  if (!(ring.field_of_view > 0.0f && ring.field_of_view < M_PI))
    return "field_of_view: " + std::to_string(ring.field_of_view) + " is not in (0, pi) rad";
  if (ring.mounts.size() != ring.ranges.size())
    return "mounts: " + std::to_string(ring.mounts.size()) + " mounts for " +
           std::to_string(ring.ranges.size()) + " ranges";
  for (std::size_t i = 0; i < ring.mounts.size(); ++i) {
    const auto& m = ring.mounts[i];
    if (!(std::isfinite(m.theta) && std::abs(m.x) < 10.0 && std::abs(m.y) < 10.0))
      return "mounts[" + std::to_string(i) + "]: not finite or beyond 10 m of the base";
  }
  return "";
}

}  // namespace spott_ros
