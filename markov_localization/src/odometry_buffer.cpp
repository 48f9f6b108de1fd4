#include "markov_localization/odometry_buffer.h"

#include <algorithm>

namespace markov_localization {

void OdometryBuffer::Add(double time_s, const spott_map::Pose2& pose) {
  if (!poses_.empty() && time_s < poses_.back().first) poses_.clear();
  poses_.emplace_back(time_s, pose);
  while (poses_.size() > 2 && poses_.front().first < time_s - keep_s_) poses_.pop_front();
}

std::optional<spott_map::Pose2> OdometryBuffer::Newest() const {
  if (poses_.empty()) return std::nullopt;
  return poses_.back().second;
}

std::optional<spott_map::Pose2> OdometryBuffer::At(double time_s, double max_lag_s) const {
  if (poses_.empty() || time_s > poses_.back().first + max_lag_s) return std::nullopt;
  return At(time_s);
}

std::optional<spott_map::Pose2> OdometryBuffer::At(double time_s) const {
  if (poses_.empty()) return std::nullopt;
  if (time_s <= poses_.front().first) return poses_.front().second;
  if (time_s >= poses_.back().first) return poses_.back().second;
  const auto after = std::lower_bound(
      poses_.begin(), poses_.end(), time_s,
      [](const std::pair<double, spott_map::Pose2>& p, double t) { return p.first < t; });
  const auto before = after - 1;
  const double span = after->first - before->first;
  const double f = span > 0.0 ? (time_s - before->first) / span : 1.0;
  const spott_map::Pose2& a = before->second;
  const spott_map::Pose2& b = after->second;
  return spott_map::Pose2{
      a.x + f * (b.x - a.x), a.y + f * (b.y - a.y),
      spott_map::NormalizeAngle(a.yaw + f * spott_map::NormalizeAngle(b.yaw - a.yaw))};
}

}  // namespace markov_localization
