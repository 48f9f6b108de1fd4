#include "markov_localization/ros/conversions.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "markov_localization/sticky_estimate.h"
#include "spott_map/ros/conversions.h"
#include "spott_ros/range_profiles.h"

namespace markov_localization::ros_conversions {

nav_msgs::OccupancyGrid BeliefGrid(const BeliefSnapshot& b,
                                   const std::vector<std::uint8_t>& state_mask,
                                   const std::string& frame_id, const ros::Time& stamp) {
  nav_msgs::OccupancyGrid grid =
      spott_map::ros_conversions::MakeGrid(b.origin, b.nx, b.ny, b.resolution, frame_id, stamp);
  const std::size_t cells = static_cast<std::size_t>(b.nx) * static_cast<std::size_t>(b.ny);
  std::vector<double> marginal(cells, 0.0);
  for (int k = 0; k < b.nt; ++k) {
    const float* layer = b.p.data() + static_cast<std::size_t>(k) * cells;
    for (std::size_t i = 0; i < cells; ++i) marginal[i] += layer[i];
  }
  const double peak = cells ? *std::max_element(marginal.begin(), marginal.end()) : 0.0;
  const bool masked = state_mask.size() == cells;
  for (std::size_t i = 0; i < cells; ++i) {
    if (masked && !state_mask[i]) continue;  // stays -1
    grid.data[i] =
        peak > 0.0 ? static_cast<std::int8_t>(std::lround(100.0 * marginal[i] / peak)) : 0;
  }
  return grid;
}

geometry_msgs::Quaternion YawToQuaternion(double yaw) {
  geometry_msgs::Quaternion q;
  q.z = std::sin(yaw / 2.0);
  q.w = std::cos(yaw / 2.0);
  return q;
}

geometry_msgs::PoseWithCovarianceStamped ToPoseWithCovariance(const Pose2& e,
                                                              const Eigen::Matrix3d& cov,
                                                              const std::string& frame_id,
                                                              const ros::Time& stamp) {
  geometry_msgs::PoseWithCovarianceStamped pose;
  pose.header.frame_id = frame_id;
  pose.header.stamp = stamp;
  pose.pose.pose.position.x = e.x;
  pose.pose.pose.position.y = e.y;
  pose.pose.pose.orientation = YawToQuaternion(e.yaw);
  const int idx[3] = {0, 1, 5};
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) pose.pose.covariance[idx[r] * 6 + idx[k]] = cov(r, k);
  return pose;
}

geometry_msgs::PoseArray ToPoseArray(const std::vector<Mode>& modes, const std::string& frame_id,
                                     const ros::Time& stamp) {
  geometry_msgs::PoseArray pa;
  pa.header.frame_id = frame_id;
  pa.header.stamp = stamp;
  for (const auto& m : modes) {
    geometry_msgs::Pose p;
    p.position.x = m.mean.x;
    p.position.y = m.mean.y;
    p.orientation = YawToQuaternion(m.mean.yaw);
    pa.poses.push_back(p);
  }
  return pa;
}

geometry_msgs::TransformStamped ToTransform(const Pose2& t, const std::string& map_frame,
                                            const std::string& odom_frame, const ros::Time& stamp) {
  geometry_msgs::TransformStamped msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = map_frame;
  msg.child_frame_id = odom_frame;
  msg.transform.translation.x = t.x;
  msg.transform.translation.y = t.y;
  msg.transform.rotation = YawToQuaternion(t.yaw);
  return msg;
}

spott_msgs::NavigateGoal NavigateGoalTo(const Vec2& target, double tolerance_m,
                                        const std::string& frame_id, const ros::Time& stamp) {
  spott_msgs::NavigateGoal goal;
  goal.target.header.frame_id = frame_id;
  goal.target.header.stamp = stamp;
  goal.target.pose.position.x = target.x();
  goal.target.pose.position.y = target.y();
  goal.target.pose.orientation.w = 1.0;
  goal.speed_mode = spott_msgs::NavigateGoal::NORMAL;
  goal.direction_bias = std::numeric_limits<double>::quiet_NaN();
  goal.position_tolerance = tolerance_m;
  goal.ignore_heading = true;
  return goal;
}

spott_msgs::BeliefModes ToBeliefModes(const std::vector<Mode>& modes, const std::string& frame_id,
                                      const ros::Time& stamp) {
  spott_msgs::BeliefModes msg;
  msg.header.frame_id = frame_id;
  msg.header.stamp = stamp;
  for (const Mode& m : modes) {
    spott_msgs::BeliefMode b;
    b.mean.x = m.mean.x;
    b.mean.y = m.mean.y;
    b.mean.theta = m.mean.yaw;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) b.covariance[3 * r + c] = m.covariance(r, c);
    b.mass = m.mass;
    msg.modes.push_back(b);
  }
  return msg;
}

OccupancyMap FromOccupancyGrid(const nav_msgs::OccupancyGrid& grid) {
  OccupancyMap m;
  const auto& o = grid.info.origin;
  m.origin = Vec2(o.position.x, o.position.y);
  const auto& q = o.orientation;
  m.origin_yaw = std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
  m.resolution_m = grid.info.resolution;
  m.width = static_cast<int>(grid.info.width);
  m.height = static_cast<int>(grid.info.height);
  m.data = grid.data;
  return m;
}

std::vector<int> LaserBeams(int readings, int max_beams) {
  std::vector<int> beams;
  if (readings <= 0) return beams;
  const int step = max_beams >= 2 ? std::max(1, (readings - 1) / (max_beams - 1)) : 1;
  for (int i = 0; i < readings; i += step) beams.push_back(i);
  return beams;
}

std::vector<double> LaserBeamAngles(const sensor_msgs::LaserScan& scan,
                                    const std::vector<int>& beams) {
  std::vector<double> angles;
  for (int i : beams)
    angles.push_back(scan.angle_min + i * static_cast<double>(scan.angle_increment));
  return angles;
}

std::vector<double> LaserRanges(const sensor_msgs::LaserScan& scan, const std::vector<int>& beams) {
  std::vector<double> ranges;
  for (int i : beams) {
    const double r = i < static_cast<int>(scan.ranges.size()) ? scan.ranges[i] : NAN;
    const bool echo = std::isfinite(r) && r >= scan.range_min && r < scan.range_max;
    // REP 117: NaN is an erroneous reading, left out like a dropped sonar; +-inf and readings
    // outside [range_min, range_max) count as no echo.
    ranges.push_back(std::isnan(r) ? r : echo ? r : std::numeric_limits<double>::infinity());
  }
  return ranges;
}

std::vector<double> ProfileReadings(const spott_msgs::RangeProfile& msg,
                                    const geometry_msgs::Transform& to_base, int bins,
                                    double min_height_m, double max_height_m, std::string* why) {
  const auto refuse = [why](const std::string& text) {
    *why = text;
    return std::vector<double>{};
  };
  if (msg.orientation != spott_msgs::RangeProfile::HORIZONTAL) return refuse("not horizontal");
  if (bins < 4) return refuse("fewer than 4 beams");
  if (msg.angles.size() != msg.ranges.size() || msg.points.size() != msg.ranges.size())
    return refuse("angles, ranges and points differ in size");
  if (!(std::isfinite(msg.max_range) && msg.max_range > 0.0f && msg.max_range < 1000.0f))
    return refuse("max_range is not in (0, 1000) m");
  const auto head = spott_ros::HeadPose(to_base);
  if (!head) return refuse("the head's transform is not finite");
  const Eigen::Vector3d origin = head->translation();
  const Eigen::Matrix3d r = head->linear();
  const double step = 2.0 * M_PI / bins;
  const auto bin_of = [&](double x, double y) {
    const int b = static_cast<int>(std::lround(std::atan2(y, x) / step));
    return ((b % bins) + bins) % bins;
  };
  std::vector<double> z(bins, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t i = 0; i < msg.ranges.size(); ++i) {
    const double range = msg.ranges[i];
    const double a = msg.angles[i];
    if (!std::isfinite(a)) continue;
    const bool ret = std::isfinite(range) && range > 0.0 && range < 0.999 * msg.max_range;
    if (!ret) {  // no return: nothing along the sample's direction (from the head's height)
      const Eigen::Vector3d d = r * Eigen::Vector3d(std::cos(a), std::sin(a), 0.0);
      if (std::abs(d.z()) > 0.05 || origin.z() < min_height_m || origin.z() > max_height_m)
        continue;
      double& zb = z[bin_of(d.x(), d.y())];
      if (std::isnan(zb)) zb = std::numeric_limits<double>::infinity();
      continue;
    }
    const auto& pt = msg.points[i];
    const Eigen::Vector3d p = origin + r * Eigen::Vector3d(pt.x, pt.y, pt.z);
    if (!p.allFinite() || p.z() < min_height_m || p.z() > max_height_m) continue;
    double& zb = z[bin_of(p.x(), p.y())];
    const double h = std::hypot(p.x(), p.y());
    if (!(zb <= h)) zb = h;  // NaN, +infinity or farther: the nearest return wins
  }
  return z;
}

std::optional<double> RingTurn(const spott_msgs::RangeRing& ring,
                               const std::vector<double>& beam_angles_rad, double tolerance_rad,
                               std::string* why) {
  if (ring.mounts.empty()) return 0.0;
  if (ring.mounts.size() != beam_angles_rad.size()) {
    *why = std::to_string(ring.mounts.size()) + " mounts, the model has " +
           std::to_string(beam_angles_rad.size()) + " beams";
    return std::nullopt;
  }
  // Angles beyond a turn either way are no transducer's (and their difference would lose the
  // angle to rounding: a beam of -1.5e308 rad, found by sensor_messages_fuzz).
  const auto no_angle = [why](const char* what, std::size_t i, double a) {
    if (std::abs(a) <= 2.0 * M_PI) return false;
    std::ostringstream out;
    out << what << " " << i << " is " << a << " rad, not an angle in [-2 pi, 2 pi]";
    *why = out.str();
    return true;
  };
  for (std::size_t i = 0; i < ring.mounts.size(); ++i)
    if (no_angle("mounts[].theta", i, ring.mounts[i].theta) ||
        no_angle("the model's beam", i, beam_angles_rad[i]))
      return std::nullopt;
  const auto off = [&](std::size_t i) {
    return spott_map::NormalizeAngle(ring.mounts[i].theta - beam_angles_rad[i]);
  };
  const double turn = off(0);
  for (std::size_t i = 0; i < ring.mounts.size(); ++i) {
    const double apart = spott_map::NormalizeAngle(off(i) - turn);
    if (!(std::abs(apart) <= tolerance_rad)) {
      std::ostringstream out;
      out.precision(3);
      out << "mount " << i << " points " << off(i) << " rad off the model's beam, mount 0 " << turn
          << " rad: the transducers did not turn together";
      *why = out.str();
      return std::nullopt;
    }
  }
  return turn;
}

}  // namespace markov_localization::ros_conversions
