#include "markov_localization/sticky_estimate.h"

#include <cmath>
#include <limits>

namespace markov_localization {

Pose2 StickyEstimate::Select(const std::vector<Mode>& modes, const Pose2& refined,
                             const Pose2& odom, bool* switched) {
  Pose2 out = refined;
  bool left = map_to_odom_.has_value();
  if (map_to_odom_ && !modes.empty()) {
    const Pose2 predicted = Compose(*map_to_odom_, odom);
    std::size_t followed = modes.size();
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t m = 0; m < modes.size(); ++m) {
      const double d = std::hypot(modes[m].mean.x - predicted.x, modes[m].mean.y - predicted.y);
      const double dyaw = std::abs(std::remainder(modes[m].mean.yaw - predicted.yaw, 2 * M_PI));
      if (d <= params_.match_radius_m && dyaw <= params_.match_rad && d < best) {
        best = d;
        followed = m;
      }
    }
    const bool refined_in_0 =
        std::hypot(refined.x - modes[0].mean.x, refined.y - modes[0].mean.y) <=
            params_.match_radius_m &&
        std::abs(std::remainder(refined.yaw - modes[0].mean.yaw, 2 * M_PI)) <= params_.match_rad;
    if (followed == 0) {
      // The followed mode is the heaviest: its pose is the refined one when the global maximum
      // lies in it (a lighter, peakier twin can hold the maximum).
      if (!refined_in_0) out = modes[0].mean;
      left = false;
    } else if (followed < modes.size() &&
               modes[0].mass <= params_.switch_ratio * modes[followed].mass) {
      out = modes[followed].mean;  // hold on to it
      left = false;
    }
  }
  if (switched) *switched = left;
  map_to_odom_ = MapToOdom(out, odom);
  return out;
}

}  // namespace markov_localization
