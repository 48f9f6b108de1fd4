#include "markov_localization/ros/conversions.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "markov_localization/sticky_estimate.h"
#include "spott_map/ros/conversions.h"

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

Pose2 MapToOdom(const Pose2& e, const Pose2& o) { return MapToOdomOf(e, o); }

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

}  // namespace markov_localization::ros_conversions
