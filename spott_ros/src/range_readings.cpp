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

std::string DiscardedReadingWhy(int index, double value) {
  return "ranges[" + std::to_string(index) + "] = " + std::to_string(value) +
         " is outside [0, max_range]: discarded as dropped out";
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

std::string LaserScanProblem(const sensor_msgs::LaserScan& scan) {
  constexpr double kTurns = 2.0 * M_PI + 1e-3;  // some lasers count 0 .. 2 pi
  if (!(std::abs(scan.angle_min) <= kTurns))
    return "angle_min: " + std::to_string(scan.angle_min) + " is not finite or beyond a turn";
  if (!(std::abs(scan.angle_increment) <= M_PI) || scan.angle_increment == 0.0f)
    return "angle_increment: " + std::to_string(scan.angle_increment) +
           " is not finite, 0 or beyond half a turn";
  if (!(std::isfinite(scan.range_max) && scan.range_max > 0.0f && scan.range_max < 1000.0f))
    return "range_max: " + std::to_string(scan.range_max) + " is not in (0, 1000) m";
  if (!(scan.range_min >= 0.0f && scan.range_min < scan.range_max))
    return "range_min: " + std::to_string(scan.range_min) + " is not in [0, range_max)";
  if (scan.ranges.empty() || scan.ranges.size() > 100000)
    return "ranges: " + std::to_string(scan.ranges.size()) + " beams (1 to 100,000)";
  const double last = scan.angle_min + (static_cast<double>(scan.ranges.size()) - 1.0) *
                                           static_cast<double>(scan.angle_increment);
  if (!(std::abs(last) <= kTurns))
    return "angle_min/angle_increment: the last beam's angle " + std::to_string(last) +
           " is beyond [-2 pi, 2 pi]";
  return "";
}

}  // namespace spott_ros
