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

}  // namespace spott_ros
