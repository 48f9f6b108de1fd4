// The parameters of sensed_map_localization_node (SPOTT's localization on the map it sensed,
// sensed_map_tracker.h), read by name from the node's private namespace; unknown keys refused.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "markov_localization/sensed_map_tracker.h"
#include "spott_map/world.h"

namespace ros {
class NodeHandle;
}
namespace spott_ros {
class ParameterReader;
}

namespace markov_localization {

struct SensedMapNodeParameters {
  /// Where the robot starts: initial_pose ("x y yaw", map frame) if set, else the world file's
  /// robot_start; map -> odom starts there with the first odometry.
  std::string world_file;
  std::optional<spott_map::Pose2> initial_pose;
  /// map -> odom as the node last had it ("x y yaw"), written by the node at start and after each
  /// fix: a respawned node resumes there, not at the start (keep it unset in files).
  std::optional<spott_map::Pose2> last_map_to_odom;
  std::string map_frame = "map";
  std::string odom_frame = "odom";
  std::string ring_topic = "sonar";             ///< spott_msgs/RangeRing.
  std::string features_topic = "map_features";  ///< spott_msgs/MapFeatureArray (latched).
  /// spott_msgs/RangeProfile (QUADRIS): horizontal profiles feed tracker.wall_lattice when on.
  std::string profile_topic = "range_profile";
  /// Profile samples outside this height band above the base are left out (m): the floor.
  double profile_min_height_m = 0.05;
  double profile_max_height_m = 2.5;
  /// Only segments whose "sensor" attribute is one of these are matched (empty: every segment).
  /// The sonar's own: QUADRIS's are profiles at other heights (a desk's top, a partition's edge)
  /// that the sonar ring heard 0.06-0.15 m elsewhere on average (cim_office's lab).
  std::vector<std::string> segment_sensors{"sonar"};
  double transform_tolerance_s = 0.2;  ///< map -> odom is stamped this far ahead (s), [0, 1].
  double odometry_max_lag_s = 0.25;    ///< A ring newer than the odometry by more is dropped (s).
  SensedMapTrackerParameters tracker;
};

void ReadParameters(spott_ros::ParameterReader& r, SensedMapNodeParameters& p);
/// Every violation and unknown key by name; empty when all is well.
std::vector<std::string> ReadParameters(const ros::NodeHandle& pnh, SensedMapNodeParameters& p);

}  // namespace markov_localization
