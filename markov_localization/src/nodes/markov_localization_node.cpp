// Thin ROS layer over the markov_localization core: reads and validates every parameter
// (ros/parameters.cpp), builds the map from a world file, turns /odom into motions and each
// range ring into a sensor update, and publishes tf map->odom (REP-105), the pose, the modes,
// the status and (throttled) the belief's marginal for rviz. /initialpose sets a Gaussian
// belief; the global_localization service a uniform one; the active_localize action drives to
// the target points of active localization (ros/active_localize_server.cpp).
#include <geometry_msgs/PoseArray.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <spott_msgs/LocalizationStatus.h>
#include <spott_msgs/RangeRing.h>
#include <std_srvs/Empty.h>
#include <tf2/utils.h>
#include <tf2_ros/transform_broadcaster.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <optional>

#include "../ros/active_localize_server.h"
#include "markov_localization/certainty.h"
#include "markov_localization/markov_grid.h"
#include "markov_localization/ros/conversions.h"
#include "markov_localization/ros/parameters.h"
#include "markov_localization/sticky_estimate.h"
#include "spott_map/world_loader.h"

namespace ml = markov_localization;
namespace conv = markov_localization::ros_conversions;

namespace {

spott_map::Pose2 PoseOf(const geometry_msgs::Pose& pose) {
  return spott_map::Pose2{pose.position.x, pose.position.y, tf2::getYaw(pose.orientation)};
}

class LocalizationNode {
 public:
  LocalizationNode(ros::NodeHandle& nh, const ml::NodeParameters& params, spott_map::World world)
      : params_(params) {
    map_ = ml::MapModel::FromWorld(world, params.map);
    if (params.initial_pose_from_world) pending_initial_ = world.robot_start;
    pose_pub_ = nh.advertise<geometry_msgs::PoseWithCovarianceStamped>("amcl_pose", 1, true);
    status_pub_ = nh.advertise<spott_msgs::LocalizationStatus>("localization_status", 1, true);
    modes_pub_ = nh.advertise<geometry_msgs::PoseArray>("localization_modes", 1, true);
    belief_pub_ = nh.advertise<nav_msgs::OccupancyGrid>("belief", 1, true);
    odom_sub_ = nh.subscribe("odom", 50, &LocalizationNode::OnOdom, this);
    ring_sub_ = nh.subscribe(params.ring_topic, 5, &LocalizationNode::OnRing, this);
    initial_sub_ = nh.subscribe("initialpose", 1, &LocalizationNode::OnInitialPose, this);
    global_srv_ = nh.advertiseService("global_localization", &LocalizationNode::OnGlobal, this);
    sticky_ = ml::StickyEstimate(params_.sticky);
    action_ = std::make_unique<ml::ActiveLocalizeServer>(nh, params_, [this] { SetUniform(); });
    ROS_INFO("markov_localization: %dx%d cells of %.2f m, %zu state cells", map_.width(),
             map_.height(), map_.resolution(), map_.NumStateCells());
  }

 private:
  void OnOdom(const nav_msgs::Odometry& msg) { odom_ = PoseOf(msg.pose.pose); }

  void OnInitialPose(const geometry_msgs::PoseWithCovarianceStamped& msg) {
    if (!grid_) {
      pending_initial_ = PoseOf(msg.pose.pose);
      return;
    }
    grid_->SetGaussian(PoseOf(msg.pose.pose), params_.initial_sigma_xy_m,
                       params_.initial_sigma_theta_rad);
    sticky_.Reset();
    ROS_INFO("markov_localization: initial pose set");
  }

  void SetUniform() {
    if (grid_) grid_->SetUniform();
    sticky_.Reset();
    pending_initial_.reset();
    ROS_INFO("markov_localization: global localization (uniform belief)");
  }

  bool OnGlobal(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
    SetUniform();
    return true;
  }

  // The sensor model needs the ring's geometry: built from the first ring.
  bool BuildModels(const spott_msgs::RangeRing& ring) {
    if (params_.ring_geometry ? ring.mounts.size() != ring.ranges.size() || ring.ranges.empty()
                              : static_cast<int>(ring.ranges.size()) != params_.beams) {
      ROS_ERROR_THROTTLE(5,
                         "markov_localization: ~sensor/beams is %d but the ring on '%s' has %zu "
                         "readings and %zu mounts; rings ignored",
                         params_.beams, params_.ring_topic.c_str(), ring.ranges.size(),
                         ring.mounts.size());
      return false;
    }
    auto& sp = params_.sensor;
    if (params_.ring_geometry) {
      sp.beam_angles_rad.clear();
      double offset = 0.0;
      for (const auto& m : ring.mounts) {
        sp.beam_angles_rad.push_back(m.theta);
        offset += std::hypot(m.x, m.y);
      }
      sp.sensor_offset_m = offset / ring.mounts.size();
    }
    if (ring.max_range > 0 && ring.max_range < sp.max_range_m) sp.max_range_m = ring.max_range;
    if (sp.beam_width_rad < 0.0) sp.beam_width_rad = std::max(0.0f, ring.field_of_view);
    if (ring.radiation_type == spott_msgs::RangeRing::INFRARED)
      sp.critical_angle_rad = M_PI / 2;  // infrared scatters off every surface
    const int nt = static_cast<int>(std::lround(2 * M_PI / params_.grid.angular_resolution_rad));
    try {
      sensor_ = std::make_unique<ml::SensorModel>(map_, nt, sp);
      grid_ = std::make_unique<ml::MarkovGrid>(map_, *sensor_, params_.grid);
      localizer_ = std::make_unique<ml::ActiveLocalizer>(map_, *sensor_, params_.active);
    } catch (const std::exception& e) {
      ROS_ERROR_THROTTLE(5, "markov_localization: cannot use the ring: %s", e.what());
      sensor_.reset();
      grid_.reset();
      return false;
    }
    if (pending_initial_ && !params_.start_uniform) {
      grid_->SetGaussian(*pending_initial_, params_.initial_sigma_xy_m,
                         params_.initial_sigma_theta_rad);
    }
    ROS_INFO("markov_localization: sensor model for %zu beams (offset %.2f m, max range %.1f m)",
             sp.beam_angles_rad.size(), sp.sensor_offset_m, sp.max_range_m);
    return true;
  }

  void OnRing(const spott_msgs::RangeRing& ring) {
    if (!odom_) return;
    if (!grid_) {
      if (!BuildModels(ring)) return;
      last_odom_ = odom_;
    }
    if (static_cast<int>(ring.ranges.size()) != sensor_->num_beams()) {
      ROS_WARN_THROTTLE(5, "markov_localization: ring has %zu readings, expected %d; ignored",
                        ring.ranges.size(), sensor_->num_beams());
      return;
    }
    const auto start = std::chrono::steady_clock::now();
    const ml::Motion motion = ml::MotionBetween(*last_odom_, *odom_);
    if (std::hypot(motion.dx, motion.dy) > 1e-4 || std::abs(motion.dtheta) > 1e-4)
      grid_->MotionUpdate(motion);
    odom_distance_m_ += std::hypot(motion.dx, motion.dy);
    last_odom_ = odom_;
    ranges_.assign(ring.ranges.begin(), ring.ranges.end());
    const auto stats = grid_->SensorUpdate(ranges_);
    if (stats.lost_detected) {
      ROS_WARN("markov_localization: the scans no longer fit the belief: lost; relocalizing");
      sticky_.Reset();
    }
    const double compute_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    Publish(ring, stats, compute_s);
  }

  void Publish(const spott_msgs::RangeRing& ring, const ml::SensorUpdateStats& stats,
               double compute_s) {
    const ros::Time& stamp = ring.header.stamp;
    // Certainty and modes over the states above theta when few (tracking: well under a
    // millisecond); the dense belief only at the belief grid's rate, for the grid and H_P.
    const bool belief_due = !last_belief_ ||
                            (stamp - *last_belief_).toSec() >= 1.0 / params_.belief_rate_hz ||
                            stamp < *last_belief_;
    const ml::BeliefSummary summary =
        ml::Summarize(*grid_, params_.certainty, params_.modes, /*with_entropy=*/false);
    const auto& c = summary.certainty;
    const auto& modes = summary.modes;
    if (!stats.lost_detected && grid_->ReportCertainty(c.certainty, params_.certainty.threshold)) {
      ROS_WARN(
          "markov_localization: certainty fell to %.2f as the scans stopped fitting: lost; "
          "relocalizing",
          c.certainty);
      sticky_.Reset();
    }
    // The published estimate stays with the mode it followed while twins swap the maximum.
    bool switched = false;
    const ml::Pose2 estimate = sticky_.Select(modes, c.estimate, *odom_, &switched);
    if (switched)
      ROS_INFO("markov_localization: estimate moves to (%.2f, %.2f, %.0f deg) (%zu modes)",
               estimate.x, estimate.y, estimate.yaw * 180.0 / M_PI, modes.size());
    const ml::Pose2 map_to_odom = conv::MapToOdom(estimate, *odom_);
    tf_.sendTransform(conv::ToTransform(map_to_odom, params_.map_frame, params_.odom_frame,
                                        stamp + ros::Duration(params_.transform_tolerance_s)));
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (const auto& m : modes)
      if (std::hypot(m.mean.x - estimate.x, m.mean.y - estimate.y) <
          params_.sticky.match_radius_m) {
        cov = m.covariance;
        break;
      }
    pose_pub_.publish(conv::ToPoseWithCovariance(estimate, cov, params_.map_frame, stamp));
    modes_pub_.publish(conv::ToPoseArray(modes, params_.map_frame, stamp));
    if (belief_due) {
      const ml::BeliefSnapshot b = ml::BeliefSnapshot::Of(*grid_);
      entropy_ = ml::Entropy(b);
      belief_pub_.publish(conv::BeliefGrid(b, map_.state_mask(), params_.map_frame, stamp));
      last_belief_ = stamp;
    }
    const double entropy = entropy_;

    ml::LocalizationUpdate u;
    u.stamp = stamp;
    u.certainty = c.certainty;
    u.entropy = entropy;
    u.estimate = estimate;
    u.best = c.estimate;
    u.map = &map_;
    u.map_to_odom = map_to_odom;
    u.odom = *odom_;
    u.odom_distance_m = odom_distance_m_;
    u.modes = &modes;
    u.localizer = localizer_.get();
    u.beam_angles_rad = &params_.sensor.beam_angles_rad;
    u.ranges_m = &ranges_;
    u.max_range_m = ring.max_range;
    action_->Update(u);

    const bool certain = c.certainty > params_.certainty.threshold;
    spott_msgs::LocalizationStatus s;
    s.header.frame_id = params_.map_frame;
    s.header.stamp = stamp;
    s.mode = action_->active() ? spott_msgs::LocalizationStatus::ACTIVE
             : certain         ? spott_msgs::LocalizationStatus::TRACKING
                               : spott_msgs::LocalizationStatus::GLOBAL;
    s.certainty = c.certainty;
    s.entropy = entropy;
    s.max_entropy = std::log(static_cast<double>(grid_->NumStates()));
    s.num_modes = modes.size();
    s.lost = !certain || grid_->lost();
    s.estimate.x = c.estimate.x;
    s.estimate.y = c.estimate.y;
    s.estimate.theta = c.estimate.yaw;
    s.update_time = compute_s;
    s.active_states = stats.states_evaluated;
    status_pub_.publish(s);
  }

  ml::NodeParameters params_;
  ml::MapModel map_;
  std::unique_ptr<ml::SensorModel> sensor_;
  std::unique_ptr<ml::MarkovGrid> grid_;
  std::unique_ptr<ml::ActiveLocalizer> localizer_;
  std::unique_ptr<ml::ActiveLocalizeServer> action_;
  std::optional<spott_map::Pose2> odom_, last_odom_, pending_initial_;
  std::optional<ros::Time> last_belief_;
  ml::StickyEstimate sticky_;
  double odom_distance_m_ = 0.0;
  double entropy_ = 0.0;  // H_P at the last belief grid (nats)
  std::vector<double> ranges_;
  ros::Publisher pose_pub_, status_pub_, modes_pub_, belief_pub_;
  ros::Subscriber odom_sub_, ring_sub_, initial_sub_;
  ros::ServiceServer global_srv_;
  tf2_ros::TransformBroadcaster tf_;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "markov_localization");
  ros::NodeHandle nh, pnh("~");
  ml::NodeParameters params;
  const auto errors = ml::ReadParameters(pnh, params);
  for (const auto& e : errors) ROS_FATAL("markov_localization: parameter %s", e.c_str());
  if (!errors.empty()) return 1;
  auto loaded = spott_map::LoadWorldFile(params.world_file);
  if (!loaded.ok()) {
    for (const auto& e : loaded.errors) ROS_FATAL("markov_localization: %s", e.ToString().c_str());
    return 1;
  }
  try {
    LocalizationNode node(nh, params, *loaded.world);
    ros::spin();
  } catch (const std::exception& e) {
    ROS_FATAL("markov_localization: %s", e.what());
    return 1;
  }
  return 0;
}
