// Thin ROS layer over the markov_localization core: reads and validates every parameter
// (ros/parameters.cpp), gets the map (a spott_map world, a map_server file or a latched /map),
// builds the sensor models from the first sonar ring and laser scan, hands every reading to the
// core's Localizer (motion gate, updates, lost handling, estimate) and publishes tf map->odom
// (REP-105), the pose, the modes, the status and (throttled) the belief's marginal for rviz.
// Map changes (spott_msgs/MapUpdate on a world, a new /map) rebuild the models in a background
// thread; the belief carries over. /initialpose sets a Gaussian belief; the global_localization
// service a uniform one; the active_localize action drives to the targets of active
// localization (ros/active_localize_server.cpp).
#include <geometry_msgs/PoseArray.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <spott_msgs/BeliefModes.h>
#include <spott_msgs/LocalizationStatus.h>
#include <spott_msgs/MapUpdate.h>
#include <spott_msgs/RangeProfile.h>
#include <spott_msgs/RangeRing.h>
#include <std_srvs/Empty.h>
#include <std_srvs/SetBool.h>
#include <tf2/LinearMath/Matrix3x3.h>
#include <tf2/LinearMath/Quaternion.h>
#include <tf2/utils.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <future>
#include <limits>
#include <memory>
#include <optional>

#include "../ros/active_localize_server.h"
#include "markov_localization/certainty.h"
#include "markov_localization/localizer.h"
#include "markov_localization/odometry_buffer.h"
#include "markov_localization/resume_spread.h"
#include "markov_localization/ros/conversions.h"
#include "markov_localization/ros/parameters.h"
#include "markov_localization/ros/pose_messages.h"
#include "spott_map/ros/map_update.h"
#include "spott_map/world_loader.h"
#include "spott_ros/input_refusals.h"
#include "spott_ros/range_readings.h"

namespace ml = markov_localization;
namespace conv = markov_localization::ros_conversions;

namespace {

// A ring's transducers turned together when their axes are off the model's beams by the same
// angle within this (rad); the turret's step in SPOTT's dense scan is 2.5 degrees (0.044 rad).
constexpr double kMountToleranceRad = 0.01;

// Why a ring is refused (its limit is not a usable number), or "".
std::string RingProblem(const spott_msgs::RangeRing& ring) {
  if (!(std::isfinite(ring.max_range) && ring.max_range > 0.0f && ring.max_range < 1000.0f))
    return "max_range " + std::to_string(ring.max_range) + " is not in (0, 1000) m";
  return "";
}

class LocalizationNode {
 public:
  LocalizationNode(ros::NodeHandle& nh, const ml::NodeParameters& params,
                   std::optional<spott_map::World> world)
      : params_(params),
        world_(std::move(world)),
        tf_listener_(tf_buffer_),
        refusals_(nh, "markov_localization") {
    if (params.initial_pose)
      pending_initial_ = params.initial_pose;
    else if (world_ && params.initial_pose_from_world)
      pending_initial_ = world_->robot_start;
    // Which map (README "Maps"): the topic when asked for, else map_file, else the world.
    if (params.use_map_topic || (params.map_file.empty() && !world_)) {
      map_sub_ = nh.subscribe(params.map_topic, 1, &LocalizationNode::OnMap, this);
      ROS_INFO("markov_localization: waiting for the map on '%s'", params.map_topic.c_str());
    } else if (!params.map_file.empty()) {
      const ml::MapFileResult file = ml::LoadMapServerMap(params.map_file);
      if (!file.ok()) throw std::runtime_error(spott_map::FormatErrors(file.errors));
      map_ =
          std::make_shared<const ml::MapModel>(ml::MapModel::FromOccupancy(*file.map, params.map));
      ROS_INFO("markov_localization: map_server map %s (%d x %d cells of %.3f m)%s",
               params.map_file.c_str(), file.map->width, file.map->height, file.map->resolution_m,
               world_ ? "; world_file ignored for the map" : "");
    } else {
      db_ = spott_map::MapDatabase::FromWorld(*world_);
      map_ = std::make_shared<const ml::MapModel>(
          ml::MapModel::FromDatabase(*world_, *db_, params.map));
      if (!params.map_updates_topic.empty())
        updates_sub_ =
            nh.subscribe(params.map_updates_topic, 10, &LocalizationNode::OnMapUpdate, this);
    }
    if (map_) LogMap("map");
    pose_pub_ = nh.advertise<geometry_msgs::PoseWithCovarianceStamped>("amcl_pose", 1, true);
    status_pub_ = nh.advertise<spott_msgs::LocalizationStatus>("localization_status", 1, true);
    modes_pub_ = nh.advertise<geometry_msgs::PoseArray>("localization_modes", 1, true);
    belief_modes_pub_ = nh.advertise<spott_msgs::BeliefModes>("belief_modes", 1, true);
    belief_pub_ = nh.advertise<nav_msgs::OccupancyGrid>("belief", 1, true);
    odom_sub_ = nh.subscribe("odom", 50, &LocalizationNode::OnOdom, this);
    if (params.sonar_enabled)
      ring_sub_ = nh.subscribe(params.ring_topic, 5, &LocalizationNode::OnRing, this);
    if (params.laser.enabled)
      scan_sub_ = nh.subscribe(params.laser.topic, 5, &LocalizationNode::OnScan, this);
    if (params.profile.enabled)
      profile_sub_ = nh.subscribe(params.profile.topic, 10, &LocalizationNode::OnProfile, this);
    initial_sub_ = nh.subscribe("initialpose", 1, &LocalizationNode::OnInitialPose, this);
    global_srv_ = nh.advertiseService("global_localization", &LocalizationNode::OnGlobal, this);
    sonar_srv_ = nh.advertiseService("enable_sonar", &LocalizationNode::OnEnableSonar, this);
    action_ = std::make_unique<ml::ActiveLocalizeServer>(nh, params_, [this] { SetUniform(); });
    if (params_.save_pose_period_s > 0)
      save_timer_ = nh.createTimer(ros::Duration(params_.save_pose_period_s),
                                   &LocalizationNode::SavePose, this);
  }

 private:
  void LogMap(const char* what) {
    ROS_INFO("markov_localization: %s: %dx%d cells of %.2f m, %zu state cells", what, map_->width(),
             map_->height(), map_->resolution(), map_->NumStateCells());
  }

  void OnOdom(const nav_msgs::Odometry& msg) {
    const auto pose = conv::PoseOf(msg.pose.pose);
    if (!pose) {
      refusals_.Refuse("odom", "pose.pose", "not finite or no yaw in the quaternion");
      return;
    }
    odom_ = pose;
    odometry_.Add(msg.header.stamp.toSec(), *odom_);
    if (localizer_) ReleaseHeld();
  }

  void OnInitialPose(const geometry_msgs::PoseWithCovarianceStamped& msg) {
    std::string field, why;
    const auto pose = conv::InitialPoseOf(msg, params_.map_frame, &field, &why);
    if (!pose) {
      refusals_.Refuse("initialpose", field, why);
      return;
    }
    if (!localizer_) {
      pending_initial_ = pose;
      return;
    }
    localizer_->SetGaussian(*pose, params_.initial_sigma_xy_m, params_.initial_sigma_theta_rad,
                            odom_);
    resume_after_.reset();  // the user's pose wins over the saved one
    resumed_ = true;
    ROS_INFO("markov_localization: initial pose set");
  }

  void SetUniform() {
    if (localizer_) localizer_->SetUniform();
    pending_initial_.reset();
    resume_after_.reset();
    resumed_ = true;
    ROS_INFO("markov_localization: global localization (uniform belief)");
  }

  bool OnGlobal(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
    SetUniform();
    return true;
  }

  // The travel mode "doorway" of Beetz et al. (section 3.1) switches the sonars off against
  // crosstalk: the ring's readings are then not used and the belief follows the odometry (its
  // motion is applied at the next update); tf and the status go on.
  bool OnEnableSonar(std_srvs::SetBool::Request& req, std_srvs::SetBool::Response& res) {
    res.success = params_.sonar_enabled;
    if (!params_.sonar_enabled) {
      res.message = "the node does not localize on sonar (sonar_enabled false)";
      return true;
    }
    if (sonar_on_ != req.data)
      ROS_INFO("markov_localization: sonar readings %s", req.data ? "used again" : "not used");
    sonar_on_ = req.data;
    sonar_off_since_ = ros::Time::now();
    res.message = sonar_on_ ? "sonar readings used" : "sonar readings not used";
    return true;
  }

  // ---- maps
  void OnMap(const nav_msgs::OccupancyGrid& msg) {
    const ml::OccupancyMap grid = conv::FromOccupancyGrid(msg);
    try {
      auto map =
          std::make_shared<const ml::MapModel>(ml::MapModel::FromOccupancy(grid, params_.map));
      ROS_INFO("markov_localization: map from '%s' (%d x %d cells of %.3f m)",
               params_.map_topic.c_str(), grid.width, grid.height, grid.resolution_m);
      NewMap(std::move(map));
    } catch (const std::exception& e) {
      ROS_ERROR("markov_localization: refusing the map on '%s': %s (keeping the current one)",
                params_.map_topic.c_str(), e.what());
    }
  }

  void OnMapUpdate(const spott_msgs::MapUpdate& msg) {
    const auto before = db_->revision();
    spott_msgs::MapUpdate update = msg;
    if (!params_.map_update_features) {  // door states only (NodeParameters::map_update_features)
      update.added.clear();
      update.removed.clear();
      update.relabelled.clear();
    }
    for (const std::string& problem : spott_map::ros_conversions::ApplyMapUpdate(update, 0.1, *db_))
      refusals_.Refuse(params_.map_updates_topic, "update", problem);
    if (db_->revision() == before) return;
    try {
      NewMap(std::make_shared<const ml::MapModel>(
          ml::MapModel::FromDatabase(*world_, *db_, params_.map)));
      ROS_INFO("markov_localization: map update (%zu doors, %zu added features): rebuilding",
               update.doors.size(), update.added.size());
    } catch (const std::exception& e) {
      ROS_ERROR("markov_localization: map update not applied: %s", e.what());
    }
  }

  // A new map: before the models exist it is simply the map; afterwards the models are rebuilt
  // in the background (the ray-cast tables take seconds) and swapped in when ready.
  void NewMap(std::shared_ptr<const ml::MapModel> map) {
    if (!localizer_) {
      map_ = std::move(map);
      LogMap("map");
      TryStart();
      return;
    }
    queued_map_ = std::move(map);
    StartRebuild();
  }

  void StartRebuild() {
    if (rebuild_.valid() || !queued_map_) return;
    auto map = std::move(queued_map_);
    queued_map_.reset();
    const auto sensors = sensor_params_;
    const int nt = models_->num_headings;
    // From the current models: a door's change casts only the rays that can reach it.
    std::shared_ptr<const ml::LocalizationModels> previous = models_;
    rebuild_ = std::async(std::launch::async, [map, sensors, nt, previous] {
      return ml::LocalizationModels::Build(map, sensors, nt, previous);
    });
  }

  void PollRebuild() {
    if (!rebuild_.valid() ||
        rebuild_.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
      return;
    try {
      auto models = rebuild_.get();
      localizer_->ReplaceModels(models);
      models_ = models;
      map_ = models->map;
      active_ = std::make_unique<ml::ActiveLocalizer>(*map_, *models_->sensors[0], params_.active);
      std::size_t cast = 0;
      for (const auto& sensor : models_->sensors) cast += sensor->rays_cast();
      const std::string what = "map replaced (belief carried over, " + std::to_string(cast) +
                               " rays cast for " + std::to_string(models_->sensors.size()) +
                               " sensors)";
      LogMap(what.c_str());
    } catch (const std::exception& e) {
      ROS_ERROR("markov_localization: the new map's models failed: %s (keeping the old)", e.what());
    }
    StartRebuild();
  }

  // ---- sensors: each model is set up from its first message, the localizer once all are.
  bool SonarGeometry(const spott_msgs::RangeRing& ring) {
    if (params_.ring_geometry ? ring.mounts.size() != ring.ranges.size() || ring.ranges.empty()
                              : static_cast<int>(ring.ranges.size()) != params_.beams) {
      ROS_ERROR_THROTTLE(5,
                         "markov_localization: ~sensor/beams is %d but the ring on '%s' has %zu "
                         "readings and %zu mounts; rings ignored",
                         params_.beams, params_.ring_topic.c_str(), ring.ranges.size(),
                         ring.mounts.size());
      return false;
    }
    ml::SensorModelParameters sp = params_.sensor;
    if (params_.ring_geometry) {
      sp.beam_angles_rad.clear();
      double offset = 0.0;
      for (const auto& m : ring.mounts) {
        sp.beam_angles_rad.push_back(m.theta);
        sp.beam_origins_m.push_back(ml::Vec2(m.x, m.y));
        offset += std::hypot(m.x, m.y);
      }
      sp.sensor_offset_m = offset / ring.mounts.size();
    }
    if (ring.max_range > 0 && ring.max_range < sp.max_range_m) sp.max_range_m = ring.max_range;
    if (sp.beam_width_rad < 0.0) sp.beam_width_rad = std::max(0.0f, ring.field_of_view);
    if (ring.radiation_type == spott_msgs::RangeRing::INFRARED)
      sp.critical_angle_rad = M_PI / 2;  // infrared scatters off every surface
    sonar_model_ = sp;
    return true;
  }

  bool LaserGeometry(const sensor_msgs::LaserScan& scan) {
    geometry_msgs::TransformStamped t;
    try {
      t = tf_buffer_.lookupTransform(params_.laser.base_frame, scan.header.frame_id, ros::Time(0),
                                     ros::Duration(0.5));
    } catch (const tf2::TransformException& e) {
      ROS_WARN_THROTTLE(5, "markov_localization: no tf %s -> %s yet: %s",
                        params_.laser.base_frame.c_str(), scan.header.frame_id.c_str(), e.what());
      return false;
    }
    laser_beams_ = conv::LaserBeams(static_cast<int>(scan.ranges.size()), params_.laser.max_beams);
    if (laser_beams_.size() < 2) {
      ROS_ERROR_THROTTLE(5, "markov_localization: the scan on '%s' has %zu readings; ignored",
                         params_.laser.topic.c_str(), scan.ranges.size());
      return false;
    }
    // Each beam's direction in the base frame (a laser mounted upside down reverses them).
    const auto& q = t.transform.rotation;
    const tf2::Matrix3x3 rot(tf2::Quaternion(q.x, q.y, q.z, q.w));
    ml::SensorModelParameters lp = params_.laser.model;
    lp.beam_angles_rad.clear();
    lp.beam_origins_m.clear();
    for (double a : conv::LaserBeamAngles(scan, laser_beams_)) {
      const tf2::Vector3 d = rot * tf2::Vector3(std::cos(a), std::sin(a), 0.0);
      lp.beam_angles_rad.push_back(std::atan2(d.y(), d.x()));
      lp.beam_origins_m.push_back(ml::Vec2(t.transform.translation.x, t.transform.translation.y));
    }
    lp.sensor_offset_m = 0.0;
    lp.beam_width_rad = 0.0;
    if (scan.range_max > 0 && scan.range_max < lp.max_range_m) lp.max_range_m = scan.range_max;
    laser_model_ = lp;
    laser_readings_ = scan.ranges.size();
    ROS_INFO("markov_localization: laser '%s': %zu of %zu beams, at (%.2f, %.2f) in %s, max %.1f m",
             scan.header.frame_id.c_str(), laser_beams_.size(), scan.ranges.size(),
             t.transform.translation.x, t.transform.translation.y, params_.laser.base_frame.c_str(),
             lp.max_range_m);
    return true;
  }

  // Builds the models and the localizer once the map and every enabled sensor's geometry are
  // known.
  void TryStart() {
    if (localizer_ || !map_ || !odom_) return;
    if (params_.sonar_enabled && !sonar_model_) return;
    if (params_.laser.enabled && !laser_model_) return;
    sensor_params_.clear();
    sonar_index_ = laser_index_ = -1;
    if (sonar_model_) {
      sonar_index_ = static_cast<int>(sensor_params_.size());
      sensor_params_.push_back(*sonar_model_);
    }
    if (laser_model_) {
      laser_index_ = static_cast<int>(sensor_params_.size());
      sensor_params_.push_back(*laser_model_);
    }
    const int nt = static_cast<int>(std::lround(2 * M_PI / params_.grid.angular_resolution_rad));
    profile_index_ = -1;
    if (params_.profile.enabled) {  // a beam at every heading bin from the centre
      ml::SensorModelParameters fp = params_.profile.model;
      fp.beam_angles_rad.clear();
      for (int b = 0; b < nt; ++b) fp.beam_angles_rad.push_back(2 * M_PI * b / nt);
      fp.beam_origins_m.clear();
      fp.sensor_offset_m = 0.0;
      fp.beam_width_rad = 0.0;
      profile_index_ = static_cast<int>(sensor_params_.size());
      sensor_params_.push_back(fp);
    }
    ml::LocalizerParameters lp;
    lp.grid = params_.grid;
    lp.gate = params_.gate;
    lp.certainty = params_.certainty;
    lp.modes = params_.modes;
    lp.sticky = params_.sticky;
    lp.refine = params_.refine;
    if (profile_index_ >= 0) lp.unjudged_sensors = {profile_index_};
    try {
      const auto start = std::chrono::steady_clock::now();
      models_ = ml::LocalizationModels::Build(map_, sensor_params_, nt);
      localizer_ = std::make_unique<ml::Localizer>(models_, lp);
      active_ = std::make_unique<ml::ActiveLocalizer>(*map_, *models_->sensors[0], params_.active);
      ROS_INFO("markov_localization: models for %zu sensor(s) built in %.1f s",
               sensor_params_.size(),
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    } catch (const std::exception& e) {
      ROS_ERROR_THROTTLE(5, "markov_localization: cannot build the models: %s", e.what());
      localizer_.reset();
      return;
    }
    if (params_.last_map_to_odom && !resumed_) {
      // Respawned. The robot drove on while the models were built; the readings queued meanwhile
      // are of where it was. The belief starts at the first reading taken after this moment
      // (ResumeAt): started at the odometry of the build's start, the driven metres came in one
      // motion update whose noise spread it along the hallway (0.7-1.1 m off in node_kill.test).
      resume_after_ = ros::Time::now();
    } else if (pending_initial_ && !params_.start_uniform) {
      localizer_->SetGaussian(*pending_initial_, params_.initial_sigma_xy_m,
                              params_.initial_sigma_theta_rad);
    }
  }

  // The covariance of the mode the estimate follows; none when no mode is near it.
  std::optional<Eigen::Matrix3d> FollowedModeCovariance(const ml::Pose2& estimate) const {
    for (const auto& m : localizer_->summary().modes)
      if (std::hypot(m.mean.x - estimate.x, m.mean.y - estimate.y) < params_.sticky.match_radius_m)
        return m.covariance;
    return std::nullopt;
  }

  // AMCL's save_pose_rate: map -> odom on the parameter server while not lost, so that a node
  // respawned after a crash resumes from it (parameters.h, last_map_to_odom).
  void SavePose(const ros::TimerEvent&) {
    if (!localizer_ || !localizer_->has_estimate() || localizer_->lost()) return;
    const ml::Pose2 t = localizer_->map_to_odom();
    ros::NodeHandle pnh("~");
    char text[96];
    std::snprintf(text, sizeof text, "%.4f %.4f %.5f", t.x, t.y, t.yaw);
    pnh.setParam("last_map_to_odom", std::string(text));
    if (!odom_) return;
    std::snprintf(text, sizeof text, "%.4f %.4f %.5f", odom_->x, odom_->y, odom_->yaw);
    pnh.setParam("last_odom", std::string(text));
    // A mode of one cell has no spread of its own: ResumeSpread floors it at the grid's.
    const auto cov = FollowedModeCovariance(localizer_->Estimate(*odom_));
    const auto spread = cov ? ml::SpreadOf(*cov) : std::nullopt;
    pnh.setParam("last_sigma_xy_m", spread ? std::max(spread->xy_m, 1e-3) : 0.0);
    pnh.setParam("last_sigma_theta_deg",
                 spread ? std::max(spread->theta_rad, 1e-3) * 180.0 / M_PI : 0.0);
  }

  void OnRing(const spott_msgs::RangeRing& ring) {
    if (const std::string problem = RingProblem(ring); !problem.empty()) {
      refusals_.Refuse(params_.ring_topic, "ranges", problem);
      return;
    }
    if (!odom_) return;
    if (!sonar_model_ && !SonarGeometry(ring)) return;
    TryStart();
    if (!localizer_) return;
    if (static_cast<int>(ring.ranges.size()) != models_->sensors[sonar_index_]->num_beams()) {
      ROS_WARN_THROTTLE(5, "markov_localization: ring has %zu readings, expected %d; ignored",
                        ring.ranges.size(), models_->sensors[sonar_index_]->num_beams());
      return;
    }
    ranges_.assign(ring.ranges.begin(), ring.ranges.end());
    if (const int i = spott_ros::DiscardImpossibleRanges(ring.max_range, &ranges_); i >= 0) {
      refusals_.Refuse(params_.ring_topic, "ranges",
                       spott_ros::DiscardedReadingWhy(i, ring.ranges[i]));
    }
    if (!sonar_on_ && (ros::Time::now() - sonar_off_since_).toSec() > params_.sonar_off_max_s) {
      ROS_WARN("markov_localization: sonar readings used again: switched off for more than %.0f s",
               params_.sonar_off_max_s);
      sonar_on_ = true;
    }
    // No update, the estimate on odometry: switched off (enable_sonar), or read with the
    // transducers elsewhere than the model's beams and not turned together.
    const auto on_odometry = [&] {
      const auto at = ReadingOdometry(ring.header.stamp);
      if (!at) return;
      reading_odom_ = *at;
      Publish(ring.header.stamp, ml::LocalizerStep{}, sonar_model_->beam_angles_rad, ranges_,
              ring.max_range);
    };
    if (!sonar_on_) return on_odometry();
    double turn = 0.0;
    if (params_.ring_geometry) {
      // The turret turned (SPOTT's dense sonar scan): the ring reads as the model's from the
      // heading + turn (SensorReading::turn_rad).
      std::string why;
      const std::optional<double> turned = ml::ros_conversions::RingTurn(
          ring, sonar_model_->beam_angles_rad, kMountToleranceRad, &why);
      if (!turned) {
        ROS_WARN_THROTTLE(10,
                          "markov_localization: rings on '%s' whose transducers did not turn "
                          "together from the first ring's are skipped, the estimate follows "
                          "odometry: %s",
                          params_.ring_topic.c_str(), why.c_str());
        return on_odometry();
      }
      turn = *turned;
    }
    last_ring_max_range_ = ring.max_range;
    turned_angles_ = sonar_model_->beam_angles_rad;
    for (double& a : turned_angles_) a += turn;
    OnReading(sonar_index_, ranges_, ring.header.stamp, turned_angles_, ring.max_range,
              /*reactive_is_ring=*/false, turn);
  }

  void OnScan(const sensor_msgs::LaserScan& scan) {
    const std::string problem = spott_ros::LaserScanProblem(scan);
    if (!problem.empty()) {
      refusals_.RefuseProblem(params_.laser.topic, problem);
      return;
    }
    if (!odom_) return;
    if (!laser_model_ && !LaserGeometry(scan)) return;
    TryStart();
    if (!localizer_) return;
    if (scan.ranges.size() != laser_readings_) {
      ROS_WARN_THROTTLE(5, "markov_localization: scan has %zu readings, expected %zu; ignored",
                        scan.ranges.size(), laser_readings_);
      return;
    }
    laser_ranges_ = conv::LaserRanges(scan, laser_beams_);
    OnReading(laser_index_, laser_ranges_, scan.header.stamp, laser_model_->beam_angles_rad,
              laser_model_->max_range_m);
  }

  // A horizontal QUADRIS profile: its samples binned by direction (ProfileParameters), a reading
  // like the ring's (gate/join_s lets the update wait for it). The active-localization server
  // and the wanderer are still given the last ring (they steer on it).
  void OnProfile(const spott_msgs::RangeProfile& msg) {
    if (msg.orientation != spott_msgs::RangeProfile::HORIZONTAL) return;
    if (!odom_ || !localizer_ || profile_index_ < 0) return;
    geometry_msgs::TransformStamped t;
    try {
      t = tf_buffer_.lookupTransform(params_.profile.base_frame, msg.header.frame_id,
                                     msg.header.stamp, ros::Duration(0.05));
    } catch (const tf2::TransformException&) {
      try {  // the heads' joint states may lag the profile: their latest
        t = tf_buffer_.lookupTransform(params_.profile.base_frame, msg.header.frame_id,
                                       ros::Time(0));
      } catch (const tf2::TransformException& e) {
        ROS_WARN_THROTTLE(5, "markov_localization: no tf %s -> %s: %s",
                          params_.profile.base_frame.c_str(), msg.header.frame_id.c_str(),
                          e.what());
        return;
      }
    }
    std::string why;
    profile_ranges_ =
        conv::ProfileReadings(msg, t.transform, models_->num_headings, params_.profile.min_height_m,
                              params_.profile.max_height_m, &why);
    if (profile_ranges_.empty()) {
      refusals_.Refuse(params_.profile.topic, "ranges", why);
      return;
    }
    const auto& reactive = !sonar_model_            ? no_beams_
                           : turned_angles_.empty() ? sonar_model_->beam_angles_rad
                                                    : turned_angles_;
    OnReading(profile_index_, profile_ranges_, msg.header.stamp, reactive,
              sonar_model_ ? last_ring_max_range_ : 0.0, /*reactive_is_ring=*/true);
  }

  void OnReading(int sensor, const std::vector<double>& ranges, const ros::Time& stamp,
                 const std::vector<double>& beam_angles, double max_range,
                 bool reactive_is_ring = false, double turn_rad = 0.0) {
    PollRebuild();
    const auto at = ReadingOdometry(stamp);
    if (!at) {  // its odometry is still queued: processed when it comes (ReleaseHeld)
      held_.push_back(
          HeldReading{sensor, ranges, stamp, beam_angles, max_range, reactive_is_ring, turn_rad});
      if (held_.size() > kMaxHeld) held_.pop_front();
      return;
    }
    if (resume_after_ && !ResumeAt(stamp, *at)) return;
    reading_odom_ = *at;
    const auto start = std::chrono::steady_clock::now();
    const ml::LocalizerStep step =
        localizer_->OnReading(sensor, ranges, reading_odom_, stamp.toSec(), turn_rad);
    if (step.lost)
      ROS_WARN("markov_localization: lost: %s; relocalizing", step.lost_reason.c_str());
    if (step.switched) {
      const ml::Pose2 e = localizer_->Estimate(reading_odom_);
      ROS_INFO("markov_localization: estimate moves to (%.2f, %.2f, %.0f deg) (%zu modes)", e.x,
               e.y, e.yaw * 180.0 / M_PI, localizer_->summary().modes.size());
    }
    if (step.updated && !announced_) {
      announced_ = true;
      const ml::Pose2 e = localizer_->Estimate(reading_odom_);
      ROS_INFO("markov_localization: first estimate (%.2f, %.2f, %.0f deg), certainty %.2f", e.x,
               e.y, e.yaw * 180.0 / M_PI, localizer_->summary().certainty.certainty);
    }
    if (step.updated) {
      last_stats_ = step.stats;
      last_compute_s_ =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    Publish(stamp, step, beam_angles, reactive_is_ring ? ranges_ : ranges, max_range);
  }

  // A respawned node's belief: the saved map -> odom composed with the odometry of a reading
  // taken after the models were built; false for a reading queued before.
  bool ResumeAt(const ros::Time& stamp, const ml::Pose2& odom) {
    if (stamp < *resume_after_) return false;
    const ml::Pose2 at = ml::Compose(*params_.last_map_to_odom, odom);
    ml::Spread spread{params_.initial_sigma_xy_m, params_.initial_sigma_theta_rad};
    if (params_.last_odom && params_.last_sigma_xy_m > 0.0) {
      spread = ml::ResumeSpread(ml::Spread{params_.last_sigma_xy_m, params_.last_sigma_theta_rad},
                                *params_.last_odom, odom, localizer_->parameters().grid.motion,
                                localizer_->parameters().gate, map_->resolution(),
                                localizer_->grid().angular_resolution());
    }
    localizer_->SetGaussian(at, spread.xy_m, spread.theta_rad, odom);
    ROS_WARN(
        "markov_localization: resumed at (%.2f, %.2f, %.0f deg) from the saved map -> odom, "
        "spread %.2f m / %.1f deg",
        at.x, at.y, at.yaw * 180.0 / M_PI, spread.xy_m, spread.theta_rad * 180.0 / M_PI);
    resume_after_.reset();
    resumed_ = true;
    return true;
  }

  // The odometry when the reading was taken (odometry_buffer.h), not the newest; none for a
  // reading taken after the newest odometry by more than odometry_max_lag_s. After a long
  // update (the models' build, a full update after a kidnap) the readings queued meanwhile come
  // before the odometry queued with them: they wait for it (AMCL's tf message filter).
  std::optional<ml::Pose2> ReadingOdometry(const ros::Time& stamp) {
    const auto at = odometry_.At(stamp.toSec(), params_.odometry_max_lag_s);
    if (!at)
      ROS_DEBUG("markov_localization: a reading of %.2f s waits for its odometry", stamp.toSec());
    return at;
  }

  // The held readings whose odometry has come, oldest first.
  void ReleaseHeld() {
    while (!held_.empty() &&
           odometry_.At(held_.front().stamp.toSec(), params_.odometry_max_lag_s)) {
      const HeldReading r = std::move(held_.front());
      held_.pop_front();
      OnReading(r.sensor, r.ranges, r.stamp, r.beam_angles, r.max_range, r.reactive_is_ring,
                r.turn_rad);
    }
  }

  void Publish(const ros::Time& stamp, const ml::LocalizerStep& step,
               const std::vector<double>& beam_angles, const std::vector<double>& ranges,
               double max_range) {
    if (!localizer_->has_estimate()) return;
    const ml::BeliefSummary& summary = localizer_->summary();
    const auto& c = summary.certainty;
    const auto& modes = summary.modes;
    const ml::Pose2 estimate = localizer_->Estimate(reading_odom_);
    const ml::Pose2 map_to_odom = localizer_->map_to_odom();
    // Only newer stamps: the ring's and the profiles' readings interleave, and tf2 refuses (and
    // logs, TF_REPEATED_DATA) a second transform at a stamp it holds, in every listener. A clock
    // that went back (a bag replayed again) starts over.
    const ros::Time tf_stamp = stamp + ros::Duration(params_.transform_tolerance_s);
    if (last_tf_stamp_.toSec() > tf_stamp.toSec() + 1.0) last_tf_stamp_ = ros::Time();
    if (tf_stamp > last_tf_stamp_) {
      tf_.sendTransform(
          conv::ToTransform(map_to_odom, params_.map_frame, params_.odom_frame, tf_stamp));
      last_tf_stamp_ = tf_stamp;
    }
    if (step.updated) {
      pose_pub_.publish(conv::ToPoseWithCovariance(
          estimate, FollowedModeCovariance(estimate).value_or(Eigen::Matrix3d::Zero()),
          params_.map_frame, stamp));
      modes_pub_.publish(conv::ToPoseArray(modes, params_.map_frame, stamp));
      belief_modes_pub_.publish(conv::ToBeliefModes(modes, params_.map_frame, stamp));
    }
    const bool belief_due = !last_belief_ ||
                            (stamp - *last_belief_).toSec() >= 1.0 / params_.belief_rate_hz ||
                            stamp < *last_belief_;
    if (belief_due && step.updated) {
      const ml::BeliefSnapshot b = ml::BeliefSnapshot::Of(localizer_->grid());
      entropy_ = ml::Entropy(b);
      belief_pub_.publish(conv::BeliefGrid(b, map_->state_mask(), params_.map_frame, stamp));
      last_belief_ = stamp;
    }
    odom_distance_m_ +=
        last_odom_ ? std::hypot(odom_->x - last_odom_->x, odom_->y - last_odom_->y) : 0.0;
    last_odom_ = odom_;

    ml::LocalizationUpdate u;
    u.stamp = stamp;
    u.certainty = c.certainty;
    u.entropy = entropy_;
    u.estimate = estimate;
    u.best = localizer_->BestEstimate(reading_odom_);
    u.map = map_.get();
    u.map_to_odom = map_to_odom;
    u.odom = reading_odom_;
    u.odom_distance_m = odom_distance_m_;
    u.modes = &modes;
    u.localizer = active_.get();
    u.beam_angles_rad = &beam_angles;
    u.ranges_m = &ranges;
    u.max_range_m = max_range;
    action_->Update(u);

    const bool certain = localizer_->certain();
    spott_msgs::LocalizationStatus s;
    s.header.frame_id = params_.map_frame;
    s.header.stamp = stamp;
    s.mode = action_->active() ? spott_msgs::LocalizationStatus::ACTIVE
             : certain         ? spott_msgs::LocalizationStatus::TRACKING
                               : spott_msgs::LocalizationStatus::GLOBAL;
    s.certainty = c.certainty;
    s.entropy = entropy_;
    s.max_entropy = std::log(static_cast<double>(localizer_->grid().NumStates()));
    s.num_modes = modes.size();
    s.lost = !certain || localizer_->lost();
    // The global maximum's refined pose at the last update, moved by the odometry since (the
    // status comes at every reading, the update every 0.2 m / 30 degrees).
    const ml::Pose2 best = localizer_->BestEstimate(reading_odom_);
    s.estimate.x = best.x;
    s.estimate.y = best.y;
    s.estimate.theta = best.yaw;
    s.update_time = last_compute_s_;
    s.active_states = last_stats_.states_evaluated;
    status_pub_.publish(s);
  }

  ml::NodeParameters params_;
  std::optional<spott_map::World> world_;
  std::optional<spott_map::MapDatabase> db_;  // the world's map database (map updates)
  std::shared_ptr<const ml::MapModel> map_, queued_map_;
  std::optional<ml::SensorModelParameters> sonar_model_, laser_model_;
  std::vector<int> laser_beams_;
  std::size_t laser_readings_ = 0;
  std::vector<ml::SensorModelParameters> sensor_params_;
  int sonar_index_ = -1, laser_index_ = -1, profile_index_ = -1;
  std::vector<double> profile_ranges_;
  const std::vector<double> no_beams_;
  double last_ring_max_range_ = 0.0;
  std::shared_ptr<const ml::LocalizationModels> models_;
  std::future<std::shared_ptr<const ml::LocalizationModels>> rebuild_;
  std::unique_ptr<ml::Localizer> localizer_;
  std::unique_ptr<ml::ActiveLocalizer> active_;
  std::unique_ptr<ml::ActiveLocalizeServer> action_;
  std::optional<spott_map::Pose2> odom_, last_odom_, pending_initial_;
  ml::OdometryBuffer odometry_;
  spott_map::Pose2 reading_odom_;
  std::optional<ros::Time> last_belief_;
  ml::SensorUpdateStats last_stats_;
  double last_compute_s_ = 0.0;
  bool announced_ = false;
  double odom_distance_m_ = 0.0;
  double entropy_ = 0.0;  // H_P at the last belief grid (nats)
  std::vector<double> ranges_, laser_ranges_;
  std::vector<double> turned_angles_;  ///< The last ring's beams' angles (the turret's turn in).
  ros::Publisher pose_pub_, status_pub_, modes_pub_, belief_modes_pub_, belief_pub_;
  ros::Subscriber odom_sub_, ring_sub_, scan_sub_, profile_sub_, initial_sub_, map_sub_,
      updates_sub_;
  ros::ServiceServer global_srv_, sonar_srv_;
  bool sonar_on_ = true;  // enable_sonar
  ros::Time sonar_off_since_;
  tf2_ros::TransformBroadcaster tf_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  spott_ros::InputRefusals refusals_;
  ros::Timer save_timer_;
  ros::Time last_tf_stamp_;                ///< Of the last map -> odom sent.
  bool resumed_ = false;                   ///< Started from last_map_to_odom (once).
  std::optional<ros::Time> resume_after_;  ///< Models built, resume at a reading after this.
  struct HeldReading {  ///< A reading waiting for its odometry (ReadingOdometry).
    int sensor;
    std::vector<double> ranges;
    ros::Time stamp;
    std::vector<double> beam_angles;
    double max_range;
    bool reactive_is_ring;
    double turn_rad;
  };
  static constexpr std::size_t kMaxHeld = 10;  ///< The oldest beyond are left out.
  std::deque<HeldReading> held_;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "markov_localization");
  ros::NodeHandle nh, pnh("~");
  ml::NodeParameters params;
  const auto errors = ml::ReadParameters(pnh, params);
  for (const auto& e : errors) ROS_FATAL("markov_localization: parameter %s", e.c_str());
  if (!errors.empty()) return 1;
  std::optional<spott_map::World> world;
  if (!params.world_file.empty()) {
    auto loaded = spott_map::LoadWorldFile(params.world_file);
    if (!loaded.ok()) {
      for (const auto& e : loaded.errors)
        ROS_FATAL("markov_localization: %s", e.ToString().c_str());
      return 1;
    }
    world = std::move(*loaded.world);
  }
  try {
    LocalizationNode node(nh, params, std::move(world));
    ros::spin();
  } catch (const std::exception& e) {
    ROS_FATAL("markov_localization: %s", e.what());
    return 1;
  }
  return 0;
}
