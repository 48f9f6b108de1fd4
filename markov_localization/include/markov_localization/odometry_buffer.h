// The odometry pose at a reading's time. A ring or scan is handled some time after it was
// taken (at 4x real time in the demo, tens of simulated milliseconds), while odometry keeps
// coming; pairing a reading with the newest odometry pose turned the B21's / Nomad's scans by
// the turn made meanwhile (up to 19 degrees of heading error in the demo). AMCL looks the
// odometry up by the scan's time stamp; this keeps the last odometry poses and interpolates.
//
// ROS-free; times are the caller's (s, any epoch).
#pragma once

#include <deque>
#include <optional>
#include <utility>

#include "spott_map/world.h"

namespace markov_localization {

class OdometryBuffer {
 public:
  explicit OdometryBuffer(double keep_s = 2.0) : keep_s_(keep_s) {}

  /// A pose at `time_s`; poses older than keep_s before the newest are dropped. Out-of-order
  /// times (a clock reset) clear the buffer first.
  void Add(double time_s, const spott_map::Pose2& pose);
  /// The pose at `time_s`: interpolated between the poses around it (heading the short way),
  /// the oldest before it, the newest after it; nullopt when empty.
  std::optional<spott_map::Pose2> At(double time_s) const;
  /// As At, but nullopt for a reading taken more than max_lag_s after the newest pose: its
  /// odometry has not arrived yet (a node that was busy, e.g. building its models, reads its
  /// queued readings before its queued odometry). The newest pose would pair it with where the
  /// robot was seconds earlier (AMCL's tf message filter holds such a scan instead).
  std::optional<spott_map::Pose2> At(double time_s, double max_lag_s) const;
  std::optional<spott_map::Pose2> Newest() const;
  void Clear() { poses_.clear(); }

 private:
  double keep_s_;
  std::deque<std::pair<double, spott_map::Pose2>> poses_;
};

}  // namespace markov_localization
