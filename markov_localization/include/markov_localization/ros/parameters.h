// The node's parameters: every key of config/markov_localization.yaml (private namespace), read
// and validated by name at start-up. Unknown keys under the private namespace are refused too,
// so that a misspelt name does not silently keep its default.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <ros/node_handle.h>

#include "markov_localization/active_localization.h"
#include "markov_localization/active_run.h"
#include "markov_localization/certainty.h"
#include "markov_localization/localizer.h"
#include "markov_localization/map_model.h"
#include "markov_localization/markov_grid.h"
#include "markov_localization/pose_refinement.h"
#include "markov_localization/sensor_model.h"
#include "markov_localization/sticky_estimate.h"
#include "markov_localization/wander.h"
#include "spott_map/world.h"
#include "spott_ros/parameter_reader.h"

namespace markov_localization {

/// The laser model's settings (sensor_msgs/LaserScan on `topic`).
struct LaserParameters {
  bool enabled = false;
  std::string topic = "scan";
  /// AMCL's laser_max_beams: every ((n - 1) / (max_beams - 1))-th beam of the scan, >= 2.
  int max_beams = 30;
  std::string base_frame = "base_link";  ///< The laser's mount is looked up in this frame (tf).
  /// Model max range (m), capped by the scan's range_max: the SICK's 25 m sees a corridor's
  /// far end (at 12 m the estimate slipped along cim_office's 30 m hallway).
  SensorModelParameters model;
};

/// A pan-tilt range profiler (the Nomad 200's QUADRIS heads, spott_msgs/RangeProfile on
/// `topic`, about 1 Hz per head): an addition to the paper's sensors. Each horizontal profile is
/// a reading of a beam at every heading bin from the robot's centre
/// (ros_conversions::ProfileReadings); gate/join_s lets an update wait for it; the lost
/// detector does not judge it (LocalizerParameters::unjudged_sensors).
struct ProfileParameters {
  bool enabled = false;
  std::string topic = "range_profile";
  std::string base_frame =
      "base_link";  ///< Profiles are taken to this frame (tf, the heads' joints).
  /// Samples lower (the floor) or higher (above the walls) in the base frame are left out (m).
  double min_height_m = 0.1;
  double max_height_m = 2.0;
  /// Model (single diffuse ray, as a laser's); max range capped by the profile's max_range.
  SensorModelParameters model;
};

struct NodeParameters {
  /// The map (README "Maps"): map_file (map_server YAML) if set, else world_file (spott_map
  /// world, the default of the stack) if set, else the latched /map topic; use_map_topic makes
  /// the topic win over both files.
  std::string world_file;
  std::string map_file;
  bool use_map_topic = false;
  std::string map_topic = "map";
  std::string map_updates_topic = "map_updates";  ///< spott_msgs/MapUpdate ("" = none).
  /// Whether a MapUpdate's added, removed and relabelled features change the map, besides its
  /// door states. false in the stack: the TR+ controller places what it senses with this
  /// node's own estimate, so a feature mapped while the estimate was off sits beside the real
  /// object; in the map it made the true place fit worse than its twin (office_201 and 202 are
  /// alike 5 m apart), and the estimate moved there.
  bool map_update_features = false;
  bool sonar_enabled = true;  ///< Localize on the RangeRing of ring_topic.
  /// enable_sonar false lasts at most this long (s): readings are used again after it, in case
  /// the caller that switched them off (a doorway's travel mode) is gone. (0, 600].
  double sonar_off_max_s = 20.0;
  std::string ring_topic = "sonar";
  LaserParameters laser;
  ProfileParameters profile;
  MotionGateParameters gate;
  PoseRefinementParameters refine;
  std::string map_frame = "map";
  std::string odom_frame = "odom";
  double transform_tolerance_s = 0.2;  ///< map->odom is future-dated by this (s), >= 0.
  /// A reading taken more than this after the newest odometry waits for its odometry (s),
  /// (0, 10] (odometry_buffer.h; the node holds the 10 newest).
  double odometry_max_lag_s = 0.25;
  bool start_uniform = true;  ///< Uniform belief at start (else ~initialpose waits).
  /// With start_uniform false: start from the world file's robot_start.
  bool initial_pose_from_world = false;
  /// With start_uniform false: start here ("x y yaw" in the map frame; wins over the world's
  /// robot_start). The stack passes the simulator's start_pose, so that the belief starts where
  /// the robot is instead of being corrected by /initialpose after the controller began mapping.
  std::optional<spott_map::Pose2> initial_pose;
  /// Written by the node itself every save_pose_period_s: its map -> odom ("x y yaw") while it
  /// is not lost (AMCL's save_pose_rate). A node respawned after a crash finds it and resumes
  /// at that transform composed with the odometry of the moment, whatever start_uniform says,
  /// with the saved spread grown over the odometry since (resume_spread.h; the initial sigmas
  /// when last_odom or the spread was not saved). A new launch resets it from the YAML ("").
  std::optional<spott_map::Pose2> last_map_to_odom;
  /// Written with it: the odometry pose then ("x y yaw") and the estimate's spread (0: unknown).
  std::optional<spott_map::Pose2> last_odom;
  double last_sigma_xy_m = 0.0;
  double last_sigma_theta_rad = 0.0;
  double save_pose_period_s = 2.0;  ///< [0, 60] s; 0: never saved.
  double initial_sigma_xy_m = 0.3;  ///< Spread of the belief set by /initialpose.
  double initial_sigma_theta_rad = 0.2;
  double belief_rate_hz = 1.0;  ///< Rate of the `belief` grid (it touches every state), > 0.

  MapModelParameters map;
  MarkovGridParameters grid;
  SensorModelParameters sensor;  ///< beam_angles_rad: `beams` evenly spaced (or the ring's).
  int beams = 24;  ///< Readings per ring when !ring_geometry (else the ring's mounts decide).
  bool ring_geometry = true;  ///< Beam axes and offset from the ring's mounts.
  CertaintyParameters certainty;
  ModeParameters modes;
  ActiveLocalizationParameters active;

  ActiveRunParameters run;
  WanderParameters wander;
  double position_tolerance_m = 0.4;  ///< Navigate goal's success radius (m), > 0.
  /// a* is moved to the nearest point this far from obstacles (the planner's padding), within
  /// target_search_m (m).
  double target_clearance_m = 0.4;
  double target_search_m = 0.75;
  StickyEstimateParameters sticky;
  std::string navigate_action = "harmonic_planner/navigate";
  std::string cmd_vel_topic = "cmd_vel/wander";  ///< The random motion's commands (arbiter input).
  int seed = 1;                                  ///< Seeds the random motion, >= 0.
};

/// A pose given as text "x y yaw" under `key` ("" = none); a bad text is a violation naming it.
/// The localization nodes' start and saved poses.
void GetPoseText(spott_ros::ParameterReader& r, const std::string& key,
                 std::optional<spott_map::Pose2>& pose);

/// Reads every parameter of the reader (the node's private namespace) into `p` and records each
/// violation in `r`, naming its parameter ("~grid/threshold_fraction must be in (0, 1)");
/// r.Finish() then adds the unknown keys.
void ReadParameters(spott_ros::ParameterReader& r, NodeParameters& p);

/// Reads every parameter from `pnh` (private namespace) into `p`; returns each violation
/// naming its parameter; empty when valid.
std::vector<std::string> ReadParameters(const ros::NodeHandle& pnh, NodeParameters& p);

}  // namespace markov_localization
