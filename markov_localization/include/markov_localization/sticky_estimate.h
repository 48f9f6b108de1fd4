// Which pose the node publishes (tf map -> odom, the pose) while the belief has several modes.
// Two half-turn twins of nearly equal mass swap the global maximum from one scan to the next;
// publishing the maximum would then make map -> odom jump across the building at every scan,
// and a planner driving by tf would chase both. The estimate therefore stays with the mode it
// followed (found where the last map -> odom and the odometry put the robot now) until another
// mode outweighs it by `switch_ratio`; a mode that is the global maximum gets the refined pose.
//
// ROS-free; no clock.
#pragma once

#include <optional>
#include <vector>

#include "markov_localization/certainty.h"
#include "spott_map/pose_algebra.h"

namespace markov_localization {

using spott_map::Compose;    // (map -> odom) * odom
using spott_map::MapToOdom;  // map -> odom such that (map -> odom) * odom = estimate (REP-105)

struct StickyEstimateParameters {
  double switch_ratio = 2.0;    ///< Another mode must be this much heavier to take over, >= 1.
  double match_radius_m = 1.0;  ///< The followed mode is the one whose mean is this close ...
  double match_rad = 0.5;       ///< ... in position and heading to the predicted pose.
};

class StickyEstimate {
 public:
  explicit StickyEstimate(const StickyEstimateParameters& params = {}) : params_(params) {}

  /// The pose to publish for the belief's `modes` (heaviest first), `refined` the
  /// POS-CERTAINTY estimate at the global maximum, `odom` the robot's odometry pose.
  /// `switched` (optional) says whether the estimate left the mode it followed.
  Pose2 Select(const std::vector<Mode>& modes, const Pose2& refined, const Pose2& odom,
               bool* switched = nullptr);
  /// Forget the followed mode (e.g. after a reset of the belief).
  void Reset() { map_to_odom_.reset(); }

 private:
  StickyEstimateParameters params_;
  std::optional<Pose2> map_to_odom_;
};

}  // namespace markov_localization
