#include "spott_tr_plus/ros/sensor_conversions.h"

#include <limits>

#include <Eigen/Geometry>
#include <cmath>

#include "spott_map/ros/conversions.h"
#include "spott_ros/range_profiles.h"
#include "spott_ros/range_readings.h"

namespace spott_tr_plus {
namespace ros_conversions {

using controller::Pose2;

std::optional<RangeRing> RingFromMsg(const spott_msgs::RangeRing& msg, std::string* problem,
                                     int* discarded) {
  *discarded = -1;
  *problem = spott_ros::RangeRingProblem(msg);
  if (!problem->empty()) return std::nullopt;
  RangeRing ring;
  for (const auto& m : msg.mounts) ring.mounts.push_back(Pose2{m.x, m.y, m.theta});
  ring.ranges.assign(msg.ranges.begin(), msg.ranges.end());
  ring.min_range_m = msg.min_range;
  ring.max_range_m = msg.max_range;
  ring.field_of_view_rad = msg.field_of_view;
  *discarded = spott_ros::DiscardImpossibleRanges(msg.max_range, &ring.ranges);
  return ring;
}

std::vector<double> PressedAngles(const spott_msgs::BumperRing& msg) {
  std::vector<double> pressed;
  for (std::size_t i = 0; i < msg.pressed.size() && i < msg.segment_angles.size(); ++i) {
    if (msg.pressed[i] && std::isfinite(msg.segment_angles[i]))
      pressed.push_back(msg.segment_angles[i]);
  }
  return pressed;
}

std::optional<std::vector<controller::ProfileSample>> ProfileSamples(
    const spott_msgs::RangeProfile& msg, const geometry_msgs::Transform& head,
    controller::Vec3* origin) {
  const auto pose = spott_ros::HeadPose(head);
  if (!pose) return std::nullopt;
  *origin = pose->translation();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<controller::ProfileSample> samples;
  samples.reserve(msg.points.size());
  for (std::size_t i = 0; i < msg.points.size(); ++i) {
    const Eigen::Vector3d p =
        *pose * Eigen::Vector3d(msg.points[i].x, msg.points[i].y, msg.points[i].z);
    const bool echo = i < msg.ranges.size() && msg.ranges[i] < msg.max_range - 1e-3;
    if (p.allFinite())
      samples.push_back({p, echo});
    else
      samples.push_back({Eigen::Vector3d(nan, nan, nan), false});
  }
  return samples;
}

std::optional<std::vector<Vec2>> ProfilePoints(const spott_msgs::RangeProfile& msg,
                                               const geometry_msgs::Transform& head,
                                               double min_height_m, double max_height_m,
                                               Vec2* origin) {
  controller::Vec3 from;
  auto points = spott_ros::ProfileEchoes(msg, head, min_height_m, max_height_m, &from);
  if (points) *origin = Vec2(from.x(), from.y());
  return points;
}

std::vector<spott_map::Place> PlacesFromMsg(const spott_msgs::WorldPlaces& msg) {
  std::vector<spott_map::Place> places;
  for (const auto& p : msg.places) {
    spott_map::Place place;
    place.name = p.name;
    place.kind = p.kind;
    place.pose = spott_map::ros_conversions::FromPose2D(p.pose);
    places.push_back(place);
  }
  return places;
}

}  // namespace ros_conversions
}  // namespace spott_tr_plus
