#include "rpl_executive/noreils_chatila/sensor_data.h"

#include <cmath>

namespace rpl_executive::noreils_chatila {

SonarRing SonarRing::Circular(int count, double radius_m, double half_field_of_view_rad,
                              double max_range_m) {
  SonarRing ring;
  ring.half_field_of_view_rad = half_field_of_view_rad;
  ring.max_range_m = max_range_m;
  for (int i = 0; i < count; ++i) {
    const double yaw = 2.0 * kPi * i / count;
    ring.mounts.push_back(SonarMount{radius_m * std::cos(yaw), radius_m * std::sin(yaw), yaw});
  }
  return ring;
}

bool SonarRing::IsEcho(double range_m) const {
  return std::isfinite(range_m) && range_m < max_range_m && range_m >= min_range_m;
}

}  // namespace rpl_executive::noreils_chatila
