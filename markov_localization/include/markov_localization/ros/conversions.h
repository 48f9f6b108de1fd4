// Conversions between the markov_localization core and ROS messages (the node's only message
// code besides the node itself): the belief's marginal for rviz, the pose, the modes, the
// map -> odom transform and the Navigate goal of an active-localization target.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <geometry_msgs/PoseArray.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/time.h>
#include <sensor_msgs/LaserScan.h>
#include <spott_msgs/BeliefModes.h>
#include <spott_msgs/NavigateGoal.h>
#include <spott_msgs/RangeProfile.h>
#include <spott_msgs/RangeRing.h>

#include "markov_localization/certainty.h"
#include "markov_localization/occupancy_map.h"

namespace markov_localization::ros_conversions {

/// The marginal over theta, sum_k P(x, y, k), as an occupancy grid on the belief's cells (origin
/// and resolution of the belief), scaled so that its maximum is 100 (values rounded; 0 where the
/// marginal is below half a percent of the maximum). Cells that are no state (`state_mask[i]`
/// == 0, row-major like the map; empty: all are states) are -1 (unknown).
nav_msgs::OccupancyGrid BeliefGrid(const BeliefSnapshot& belief,
                                   const std::vector<std::uint8_t>& state_mask,
                                   const std::string& frame_id, const ros::Time& stamp);

geometry_msgs::Quaternion YawToQuaternion(double yaw);

/// The estimate with the covariance (x, y, yaw) of its mode (rows/columns 0, 1, 5 of the 6 x 6
/// matrix); `covariance` may be all zero.
geometry_msgs::PoseWithCovarianceStamped ToPoseWithCovariance(const Pose2& estimate,
                                                              const Eigen::Matrix3d& covariance,
                                                              const std::string& frame_id,
                                                              const ros::Time& stamp);

/// The means of the modes, heaviest first.
geometry_msgs::PoseArray ToPoseArray(const std::vector<Mode>& modes, const std::string& frame_id,
                                     const ros::Time& stamp);

/// The modes with their mass and spread (covariance over x, y, theta, row-major).
spott_msgs::BeliefModes ToBeliefModes(const std::vector<Mode>& modes, const std::string& frame_id,
                                      const ros::Time& stamp);

/// A /map message's content (origin pose's yaw from its quaternion). No check: MapModel
/// validates it.
OccupancyMap FromOccupancyGrid(const nav_msgs::OccupancyGrid& grid);

// A scan's check: spott_ros::LaserScanProblem.

/// The beams of a scan the laser model uses: AMCL's laser_max_beams subsampling, every
/// ((n - 1) / (max_beams - 1))-th reading from the first. Indices into msg.ranges.
std::vector<int> LaserBeams(int readings, int max_beams);
/// Angles (rad, relative to the laser's frame) of `beams` of `scan`.
std::vector<double> LaserBeamAngles(const sensor_msgs::LaserScan& scan,
                                    const std::vector<int>& beams);
/// The readings of `beams` (m); NaN, infinite, below range_min or at/above range_max: no echo
/// (+infinity).
std::vector<double> LaserRanges(const sensor_msgs::LaserScan& scan, const std::vector<int>& beams);

/// A horizontal range profile (QUADRIS, spott_msgs/RangeProfile) as the readings of the
/// profiler model: one beam from the robot's centre every 2 pi / `bins` (beam b at b 2 pi / bins
/// in the base frame). `to_base` takes the header frame to the base frame (the head's pan and
/// tilt included). Each sample goes to the beam nearest its direction as seen from the centre,
/// at its horizontal distance from it; a beam keeps its nearest sample. Samples whose height in
/// the base frame is outside [min_height_m, max_height_m] are left out (the floor, what is above
/// the walls). A sample without return (a non-finite range, or at max_range) makes its beam's
/// reading +infinity ("no echo") unless a return fell in it. Beams no sample fell in are NaN (no
/// reading: left out of the update). Empty when the message is not a usable horizontal profile
/// (`why` says why).
std::vector<double> ProfileReadings(const spott_msgs::RangeProfile& msg,
                                    const geometry_msgs::Transform& to_base, int bins,
                                    double min_height_m, double max_height_m, std::string* why);

/// How far a ring's transducers turned together from the sonar model's beams (rad, in
/// (-pi, pi]): every mount's axis off its beam by the same angle within `tolerance_rad` (the
/// Nomad's sonars ride on its turret: robot_sim's /turret/command, SPOTT's dense scan); 0 for a
/// ring without mounts (the configured geometry holds). nullopt when they did not turn together
/// or the ring has another number of mounts, with the reason in `why`: the model's tables, cast
/// for the beams' angles, cannot read it.
std::optional<double> RingTurn(const spott_msgs::RangeRing& ring,
                               const std::vector<double>& beam_angles_rad, double tolerance_rad,
                               std::string* why);

geometry_msgs::TransformStamped ToTransform(const Pose2& map_to_odom, const std::string& map_frame,
                                            const std::string& odom_frame, const ros::Time& stamp);

/// A Navigate goal to a target point (no heading: ignore_heading) at NORMAL speed, no direction
/// bias, success radius `tolerance_m`.
spott_msgs::NavigateGoal NavigateGoalTo(const Vec2& target, double tolerance_m,
                                        const std::string& frame_id, const ros::Time& stamp);

}  // namespace markov_localization::ros_conversions
