// Thin ROS layer over the markov_localization core: reads and validates parameters, builds the
// map from a world file, turns /odom into motions and each sonar ring into a sensor update, and
// publishes tf map->odom (REP-105), the pose, the modes and the status. /initialpose sets a
// Gaussian belief; the global_localization service a uniform one.
#include <geometry_msgs/PoseArray.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <spott_msgs/LocalizationStatus.h>
#include <spott_msgs/RangeRing.h>
#include <std_srvs/Empty.h>
#include <tf2/LinearMath/Quaternion.h>
#include <tf2/utils.h>
#include <tf2_ros/transform_broadcaster.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <optional>

#include "markov_localization/certainty.h"
#include "markov_localization/markov_grid.h"
#include "spott_map/world_loader.h"

namespace ml = markov_localization;

namespace {

struct NodeParameters {
  std::string world_file;
  std::string ring_topic = "sonar";
  double transform_tolerance_s = 0.2;
  double initial_sigma_xy_m = 0.3;
  double initial_sigma_theta_rad = 0.2;
  bool start_uniform = true;
  ml::MapModelParameters map;
  ml::MarkovGridParameters grid;
  ml::SensorModelParameters sensor;
  ml::CertaintyParameters certainty;
  ml::ModeParameters modes;
  double angular_resolution_deg = 2.0;
};

std::vector<std::string> Read(ros::NodeHandle& pnh, NodeParameters& p) {
  std::vector<std::string> errors;
  pnh.param("world_file", p.world_file, p.world_file);
  if (p.world_file.empty()) errors.push_back("world_file must name a world file");
  pnh.param("ring_topic", p.ring_topic, p.ring_topic);
  pnh.param("transform_tolerance_s", p.transform_tolerance_s, p.transform_tolerance_s);
  if (!(p.transform_tolerance_s >= 0)) errors.push_back("transform_tolerance_s must be >= 0");
  pnh.param("start_uniform", p.start_uniform, p.start_uniform);
  pnh.param("map/resolution_m", p.map.resolution_m, p.map.resolution_m);
  pnh.param("map/state_clearance_m", p.map.state_clearance_m, p.map.state_clearance_m);
  pnh.param("grid/angular_resolution_deg", p.angular_resolution_deg, p.angular_resolution_deg);
  p.grid.angular_resolution_rad = p.angular_resolution_deg * M_PI / 180.0;
  pnh.param("grid/selective_update", p.grid.selective_update, p.grid.selective_update);
  pnh.param("grid/threshold_fraction", p.grid.threshold_fraction, p.grid.threshold_fraction);
  pnh.param("motion/sigma_xy_per_m", p.grid.motion.sigma_xy_per_m, p.grid.motion.sigma_xy_per_m);
  pnh.param("motion/sigma_theta_per_rad", p.grid.motion.sigma_theta_per_rad,
            p.grid.motion.sigma_theta_per_rad);
  pnh.param("sensor/sigma_hit_m", p.sensor.sigma_hit_m, p.sensor.sigma_hit_m);
  pnh.param("sensor/range_bin_m", p.sensor.range_bin_m, p.sensor.range_bin_m);
  // Sonar physics: the cone comes from the ring message unless set; specular reflection.
  p.sensor.critical_angle_rad = 0.35;
  pnh.param("sensor/critical_angle_rad", p.sensor.critical_angle_rad,
            p.sensor.critical_angle_rad);
  p.sensor.beam_width_rad = -1.0;
  pnh.param("sensor/beam_width_rad", p.sensor.beam_width_rad, p.sensor.beam_width_rad);
  pnh.param("certainty/threshold", p.certainty.threshold, p.certainty.threshold);
  auto& lost = p.grid.lost;
  pnh.param("lost/enabled", lost.enabled, lost.enabled);
  pnh.param("lost/fast_rate", lost.fast_rate, lost.fast_rate);
  pnh.param("lost/slow_rate", lost.slow_rate, lost.slow_rate);
  pnh.param("lost/lost_ratio", lost.lost_ratio, lost.lost_ratio);
  pnh.param("lost/hold_scans", lost.hold_scans, lost.hold_scans);
  pnh.param("lost/relocalization_mass", lost.relocalization_mass, lost.relocalization_mass);
  for (const auto& e : ml::ValidateParameters(p.map)) errors.push_back("map/" + e);
  for (auto e : ml::ValidateParameters(p.grid)) {
    // The core names nested parameters "motion.x" / "lost.x"; the node's are "motion/x".
    const bool nested = e.rfind("motion.", 0) == 0 || e.rfind("lost.", 0) == 0;
    if (nested) e[e.find('.')] = '/';
    errors.push_back(nested ? e : "grid/" + e);
  }
  for (const auto& e : ml::ValidateParameters(p.certainty)) errors.push_back("certainty/" + e);
  return errors;
}

spott_map::Pose2 PoseOf(const geometry_msgs::Pose& pose) {
  return spott_map::Pose2{pose.position.x, pose.position.y, tf2::getYaw(pose.orientation)};
}

class LocalizationNode {
 public:
  LocalizationNode(ros::NodeHandle& nh, const NodeParameters& params, spott_map::World world)
      : params_(params) {
    map_ = ml::MapModel::FromWorld(world, params.map);
    pose_pub_ = nh.advertise<geometry_msgs::PoseWithCovarianceStamped>("amcl_pose", 1, true);
    status_pub_ = nh.advertise<spott_msgs::LocalizationStatus>("localization_status", 1, true);
    modes_pub_ = nh.advertise<geometry_msgs::PoseArray>("localization_modes", 1, true);
    odom_sub_ = nh.subscribe("odom", 50, &LocalizationNode::OnOdom, this);
    ring_sub_ = nh.subscribe(params.ring_topic, 5, &LocalizationNode::OnRing, this);
    initial_sub_ = nh.subscribe("initialpose", 1, &LocalizationNode::OnInitialPose, this);
    global_srv_ = nh.advertiseService("global_localization", &LocalizationNode::OnGlobal, this);
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
    ROS_INFO("markov_localization: initial pose set");
  }

  bool OnGlobal(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
    if (grid_) grid_->SetUniform();
    global_ = true;
    ROS_INFO("markov_localization: global localization (uniform belief)");
    return true;
  }

  void BuildModels(const spott_msgs::RangeRing& ring) {
    params_.sensor.beam_angles_rad.clear();
    double offset = 0.0;
    for (const auto& m : ring.mounts) {
      params_.sensor.beam_angles_rad.push_back(m.theta);
      offset += std::hypot(m.x, m.y);
    }
    params_.sensor.sensor_offset_m = ring.mounts.empty() ? 0.0 : offset / ring.mounts.size();
    params_.sensor.max_range_m = ring.max_range;
    if (params_.sensor.beam_width_rad < 0) params_.sensor.beam_width_rad = ring.field_of_view;
    if (ring.radiation_type == spott_msgs::RangeRing::INFRARED)
      params_.sensor.critical_angle_rad = M_PI / 2;  // infrared scatters off every surface
    const int nt = static_cast<int>(std::lround(2 * M_PI / params_.grid.angular_resolution_rad));
    sensor_ = std::make_unique<ml::SensorModel>(map_, nt, params_.sensor);
    grid_ = std::make_unique<ml::MarkovGrid>(map_, *sensor_, params_.grid);
    if (pending_initial_ && !params_.start_uniform) {
      grid_->SetGaussian(*pending_initial_, params_.initial_sigma_xy_m,
                         params_.initial_sigma_theta_rad);
      global_ = false;
    }
    ROS_INFO("markov_localization: sensor model for %zu beams built", ring.mounts.size());
  }

  void OnRing(const spott_msgs::RangeRing& ring) {
    if (!odom_) return;
    if (!grid_) {
      try {
        BuildModels(ring);
      } catch (const std::exception& e) {
        ROS_ERROR_THROTTLE(5, "markov_localization: cannot use ring: %s", e.what());
        return;
      }
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
    last_odom_ = odom_;
    std::vector<double> ranges(ring.ranges.begin(), ring.ranges.end());
    const auto stats = grid_->SensorUpdate(ranges);
    ROS_DEBUG("markov_localization: fit per beam %.3f (fast %.3f, slow %.3f)",
              std::exp(stats.log_likelihood_per_beam), grid_->lost_detector().fast(),
              grid_->lost_detector().slow());
    if (stats.lost_detected) {
      ROS_WARN(
          "markov_localization: the scans no longer fit the belief (fit %.2f of the usual): "
          "lost; relocalizing",
          grid_->lost_detector().fast() / grid_->lost_detector().slow());
      global_ = true;
    }
    const double compute_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    Publish(ring.header.stamp, stats, compute_s);
  }

  void Publish(const ros::Time& stamp, const ml::SensorUpdateStats& stats, double compute_s) {
    const ml::BeliefSnapshot b = ml::BeliefSnapshot::Of(*grid_);
    const auto c = ml::PosCertainty(b, params_.certainty);
    const auto modes = ml::ExtractModes(b, params_.modes);
    if (c.certainty > params_.certainty.threshold) global_ = false;
    // map->odom = (map->base) * (odom->base)^-1
    const auto& e = c.estimate;
    const auto& o = *odom_;
    const double dyaw = e.yaw - o.yaw;
    const double tx = e.x - (std::cos(dyaw) * o.x - std::sin(dyaw) * o.y);
    const double ty = e.y - (std::sin(dyaw) * o.x + std::cos(dyaw) * o.y);
    geometry_msgs::TransformStamped t;
    t.header.stamp = stamp + ros::Duration(params_.transform_tolerance_s);
    t.header.frame_id = "map";
    t.child_frame_id = "odom";
    t.transform.translation.x = tx;
    t.transform.translation.y = ty;
    tf2::Quaternion q;
    q.setRPY(0, 0, dyaw);
    t.transform.rotation.x = q.x();
    t.transform.rotation.y = q.y();
    t.transform.rotation.z = q.z();
    t.transform.rotation.w = q.w();
    tf_.sendTransform(t);

    geometry_msgs::PoseWithCovarianceStamped pose;
    pose.header.stamp = stamp;
    pose.header.frame_id = "map";
    pose.pose.pose.position.x = e.x;
    pose.pose.pose.position.y = e.y;
    q.setRPY(0, 0, e.yaw);
    pose.pose.pose.orientation.x = q.x();
    pose.pose.pose.orientation.y = q.y();
    pose.pose.pose.orientation.z = q.z();
    pose.pose.pose.orientation.w = q.w();
    if (!modes.empty()) {
      const auto& cov = modes.front().covariance;
      const int idx[3] = {0, 1, 5};
      for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k) pose.pose.covariance[idx[r] * 6 + idx[k]] = cov(r, k);
    }
    pose_pub_.publish(pose);

    geometry_msgs::PoseArray pa;
    pa.header = pose.header;
    for (const auto& m : modes) {
      geometry_msgs::Pose p;
      p.position.x = m.mean.x;
      p.position.y = m.mean.y;
      q.setRPY(0, 0, m.mean.yaw);
      p.orientation.x = q.x();
      p.orientation.y = q.y();
      p.orientation.z = q.z();
      p.orientation.w = q.w();
      pa.poses.push_back(p);
    }
    modes_pub_.publish(pa);

    spott_msgs::LocalizationStatus s;
    s.header = pose.header;
    s.mode =
        global_ ? spott_msgs::LocalizationStatus::GLOBAL : spott_msgs::LocalizationStatus::TRACKING;
    s.certainty = c.certainty;
    s.entropy = ml::Entropy(b);
    s.max_entropy = std::log(static_cast<double>(grid_->NumStates()));
    s.num_modes = modes.size();
    s.lost = c.certainty < params_.certainty.threshold || grid_->lost();
    s.estimate.x = e.x;
    s.estimate.y = e.y;
    s.estimate.theta = e.yaw;
    s.update_time = compute_s;
    s.active_states = stats.states_evaluated;
    status_pub_.publish(s);
  }

  NodeParameters params_;
  ml::MapModel map_;
  std::unique_ptr<ml::SensorModel> sensor_;
  std::unique_ptr<ml::MarkovGrid> grid_;
  std::optional<spott_map::Pose2> odom_, last_odom_, pending_initial_;
  bool global_ = true;
  ros::Publisher pose_pub_, status_pub_, modes_pub_;
  ros::Subscriber odom_sub_, ring_sub_, initial_sub_;
  ros::ServiceServer global_srv_;
  tf2_ros::TransformBroadcaster tf_;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "markov_localization");
  ros::NodeHandle nh, pnh("~");
  NodeParameters params;
  const auto errors = Read(pnh, params);
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
