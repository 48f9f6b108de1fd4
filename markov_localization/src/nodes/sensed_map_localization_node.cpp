// SPOTT's localization without an a priori map (Zelek and Levine, Fig. 4, Experiment 1): the
// thin ROS layer over SensedMapTracker (sensed_map_tracker.h). The robot starts at a known pose
// (~initial_pose or the world's robot_start); map -> odom follows odometry and every ~period_s
// the sonar echoes of the last ~window_s are matched to the line segments of the map the robot
// sensed (/map_features, which the TR+ controller's mapping fills) and map -> odom moves by the
// correction. With ~wall_lattice/enabled the heading is first turned by the rectilinear walls'
// lines in the horizontal range profiles (/range_profile, placed in odom by tf at their stamps).
// Publishes tf map -> odom (REP-105) with every odometry message and
// localization_status (TRACKING) with every ring; /initialpose restarts at a pose; a respawned
// node resumes from ~last_map_to_odom, which it keeps up to date.
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <message_filters/subscriber.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <spott_msgs/LocalizationStatus.h>
#include <spott_msgs/MapFeatureArray.h>
#include <spott_msgs/RangeProfile.h>
#include <spott_msgs/RangeRing.h>
#include <tf2_ros/message_filter.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include "markov_localization/odometry_buffer.h"
#include "markov_localization/ros/conversions.h"
#include "markov_localization/ros/pose_messages.h"
#include "markov_localization/ros/sensed_map_parameters.h"
#include "markov_localization/sensed_map_tracker.h"
#include "spott_map/pose_algebra.h"
#include "spott_map/ros/conversions.h"
#include "spott_map/world_loader.h"
#include "spott_ros/input_refusals.h"
#include "spott_ros/range_profiles.h"
#include "spott_ros/range_readings.h"

namespace ml = markov_localization;
namespace conv = markov_localization::ros_conversions;

namespace {

class SensedMapLocalizationNode {
 public:
  SensedMapLocalizationNode(ros::NodeHandle& nh, const ml::SensedMapNodeParameters& params,
                            const spott_map::Pose2& start)
      : params_(params),
        start_(start),
        tracker_(params.tracker, spott_map::Pose2{}),
        refusals_(nh, "sensed_map_localization"),
        tf_listener_(tf_buffer_) {
    status_pub_ = nh.advertise<spott_msgs::LocalizationStatus>("localization_status", 1, true);
    odom_sub_ = nh.subscribe("odom", 50, &SensedMapLocalizationNode::OnOdom, this);
    ring_sub_ = nh.subscribe(params.ring_topic, 5, &SensedMapLocalizationNode::OnRing, this);
    features_sub_ =
        nh.subscribe(params.features_topic, 1, &SensedMapLocalizationNode::OnFeatures, this);
    initial_sub_ = nh.subscribe("initialpose", 1, &SensedMapLocalizationNode::OnInitialPose, this);
    if (params.tracker.wall_lattice.enabled) {
      // A profile waits until tf has its head at its stamp (the heads pan while it travels).
      profile_sub_.subscribe(nh, params.profile_topic, 5);
      profile_filter_ = std::make_unique<tf2_ros::MessageFilter<spott_msgs::RangeProfile>>(
          profile_sub_, tf_buffer_, params.odom_frame, 5, nh);
      profile_filter_->registerCallback(&SensedMapLocalizationNode::OnProfile, this);
      ROS_INFO("sensed_map_localization: heading from rectilinear walls (axis %.1f deg) in '%s'",
               params.tracker.wall_lattice.axis_rad * 180.0 / M_PI, params.profile_topic.c_str());
    }
    ROS_INFO(
        "sensed_map_localization: starting at (%.2f, %.2f, %.0f deg); a fix every %.1f s on the "
        "sonar echoes of the last %.1f s against '%s'",
        start.x, start.y, start.yaw * 180.0 / M_PI, params.tracker.period_s,
        params.tracker.window_s, params.features_topic.c_str());
  }

 private:
  void OnOdom(const nav_msgs::Odometry& msg) {
    const auto pose = conv::PoseOf(msg.pose.pose);
    if (!pose) {
      refusals_.Refuse("odom", "pose.pose", "not finite or no yaw in the quaternion");
      return;
    }
    const double t = msg.header.stamp.toSec();
    odometry_.Add(t, *pose);
    if (!started_) {  // map -> odom puts the first odometry pose at the start
      if (params_.last_map_to_odom) {
        tracker_.Reset(*params_.last_map_to_odom, t);
        ROS_WARN("sensed_map_localization: resumed from ~last_map_to_odom (respawned)");
      } else {
        tracker_.Reset(spott_map::MapToOdom(start_, *pose), t);
      }
      started_ = true;
      SaveMapToOdom();
    }
    if (tracker_.LatticeDue(t)) {
      const ml::WallLatticeCorrection turn = tracker_.TurnToLattice(t, *pose);
      if (turn.applied) {
        SaveMapToOdom();
        ROS_DEBUG("sensed_map_localization: turned %.2f deg on %d of %d wall lines (%.1f m)",
                  turn.dyaw * 180.0 / M_PI, turn.agreeing, turn.lines, turn.length_m);
      }
    }
    if (tracker_.Due(t)) {
      const ml::SensedMapFix fix = tracker_.Localize(t, *pose);
      ++fixes_;
      if (fix.applied) {
        SaveMapToOdom();
        ROS_INFO(
            "sensed_map_localization: fix %d: moved (%.3f, %.3f) m, %.2f deg on %d of %d echoes "
            "(%d directions), residual %.3f -> %.3f m",
            fixes_, fix.dx, fix.dy, fix.dyaw * 180.0 / M_PI, fix.matched, fix.echoes,
            fix.constrained, fix.rms_before_m, fix.rms_after_m);
      } else {
        ROS_DEBUG("sensed_map_localization: fix %d not applied: %s (%d echoes)", fixes_,
                  fix.why.c_str(), fix.echoes);
      }
    }
    // Only newer stamps (tf2 refuses a repeated one in every listener); a clock that went back
    // (a bag played again) starts over.
    const ros::Time stamp = msg.header.stamp + ros::Duration(params_.transform_tolerance_s);
    if (last_tf_stamp_.toSec() > stamp.toSec() + 1.0) last_tf_stamp_ = ros::Time();
    if (stamp > last_tf_stamp_) {
      tf_.sendTransform(
          conv::ToTransform(tracker_.map_to_odom(), params_.map_frame, params_.odom_frame, stamp));
      last_tf_stamp_ = stamp;
    }
  }

  void OnRing(const spott_msgs::RangeRing& ring) {
    if (const std::string problem = spott_ros::RangeRingProblem(ring); !problem.empty()) {
      refusals_.RefuseProblem(params_.ring_topic, problem);
      return;
    }
    if (!started_) return;
    const auto at = odometry_.At(ring.header.stamp.toSec(), params_.odometry_max_lag_s);
    if (!at) return;  // taken before the odometry came: dropped (the window has plenty)
    std::vector<double> ranges(ring.ranges.begin(), ring.ranges.end());
    if (const int i = spott_ros::DiscardImpossibleRanges(ring.max_range, &ranges); i >= 0) {
      refusals_.Refuse(params_.ring_topic, "ranges",
                       spott_ros::DiscardedReadingWhy(i, ring.ranges[i]));
    }
    mounts_.clear();
    for (const auto& m : ring.mounts) mounts_.push_back({m.x, m.y, m.theta});
    tracker_.AddRing(ring.header.stamp.toSec(), *at, mounts_, ranges, ring.min_range,
                     ring.max_range, ring.field_of_view);
    PublishStatus(ring.header.stamp, *at);
  }

  void OnProfile(const spott_msgs::RangeProfileConstPtr& profile) {
    const spott_msgs::RangeProfile& msg = *profile;
    if (!started_ || msg.orientation != spott_msgs::RangeProfile::HORIZONTAL) return;
    geometry_msgs::TransformStamped head;
    try {
      head = tf_buffer_.lookupTransform(params_.odom_frame, msg.header.frame_id, msg.header.stamp);
    } catch (const tf2::TransformException& e) {
      ROS_WARN_THROTTLE(10.0, "sensed_map_localization: range profile frame: %s", e.what());
      return;
    }
    Eigen::Vector3d origin;
    const auto points = spott_ros::ProfileEchoes(msg, head.transform, params_.profile_min_height_m,
                                                 params_.profile_max_height_m, &origin);
    if (!points) {
      refusals_.Refuse(params_.profile_topic, "header.frame_id",
                       "the head's pose in tf is not finite");
      return;
    }
    tracker_.AddProfile(msg.header.stamp.toSec(), *points);
  }

  void OnFeatures(const spott_msgs::MapFeatureArray& msg) {
    if (msg.features.empty() && have_features_) {  // features are removed with a MapUpdate
      refusals_.Refuse(params_.features_topic, "features",
                       "an empty array would remove every feature");
      return;
    }
    std::vector<spott_map::Segment> segments;
    for (const auto& f : msg.features) {
      std::string error;
      const auto feature = spott_map::ros_conversions::FromMsg(f, &error);
      if (!feature) {
        refusals_.Refuse(params_.features_topic, "features[]", error);
        continue;
      }
      if (feature->type != spott_map::FeatureType::kLineSegment || feature->points.size() != 2)
        continue;
      const auto sensor = feature->attributes.find("sensor");
      const std::string& by = sensor == feature->attributes.end() ? "" : sensor->second;
      const auto& wanted = params_.segment_sensors;
      if (!wanted.empty() && std::find(wanted.begin(), wanted.end(), by) == wanted.end()) continue;
      segments.push_back({feature->points[0], feature->points[1]});
    }
    have_features_ = have_features_ || !msg.features.empty();
    tracker_.SetSegments(segments);
  }

  void OnInitialPose(const geometry_msgs::PoseWithCovarianceStamped& msg) {
    std::string field, why;
    const auto pose = conv::InitialPoseOf(msg, params_.map_frame, &field, &why);
    if (!pose) {
      refusals_.Refuse("initialpose", field, why);
      return;
    }
    const auto odom = odometry_.Newest();
    start_ = *pose;
    if (!odom) return;  // taken with the first odometry
    tracker_.Reset(spott_map::MapToOdom(*pose, *odom), ros::Time::now().toSec());
    SaveMapToOdom();
    ROS_INFO("sensed_map_localization: restarted at (%.2f, %.2f, %.0f deg)", pose->x, pose->y,
             pose->yaw * 180.0 / M_PI);
  }

  // Where a respawned node resumes (AMCL's saved pose): map -> odom on the parameter server.
  void SaveMapToOdom() {
    const spott_map::Pose2& t = tracker_.map_to_odom();
    char text[96];
    std::snprintf(text, sizeof text, "%.4f %.4f %.5f", t.x, t.y, t.yaw);
    ros::NodeHandle("~").setParam("last_map_to_odom", std::string(text));
  }

  void PublishStatus(const ros::Time& stamp, const spott_map::Pose2& odom) {
    spott_msgs::LocalizationStatus s;
    s.header.frame_id = params_.map_frame;
    s.header.stamp = stamp;
    s.mode = spott_msgs::LocalizationStatus::TRACKING;
    s.certainty = 1.0;  // dead reckoning corrected on the sensed map: no belief to measure
    s.num_modes = 1;
    s.lost = false;
    const spott_map::Pose2 e = spott_map::Compose(tracker_.map_to_odom(), odom);
    s.estimate.x = e.x;
    s.estimate.y = e.y;
    s.estimate.theta = e.yaw;
    status_pub_.publish(s);
  }

  ml::SensedMapNodeParameters params_;
  spott_map::Pose2 start_;
  ml::SensedMapTracker tracker_;
  ml::OdometryBuffer odometry_{2.0};
  spott_ros::InputRefusals refusals_;
  tf2_ros::TransformBroadcaster tf_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  message_filters::Subscriber<spott_msgs::RangeProfile> profile_sub_;
  std::unique_ptr<tf2_ros::MessageFilter<spott_msgs::RangeProfile>> profile_filter_;
  ros::Publisher status_pub_;
  ros::Subscriber odom_sub_, ring_sub_, features_sub_, initial_sub_;
  std::vector<spott_map::Pose2> mounts_;
  ros::Time last_tf_stamp_;
  bool started_ = false;
  bool have_features_ = false;
  int fixes_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "sensed_map_localization");
  ros::NodeHandle nh, pnh("~");
  ml::SensedMapNodeParameters params;
  const auto errors = ml::ReadParameters(pnh, params);
  for (const auto& e : errors) ROS_FATAL("sensed_map_localization: parameter %s", e.c_str());
  if (!errors.empty()) return 1;
  std::optional<spott_map::Pose2> start = params.initial_pose;
  if (!start && !params.world_file.empty()) {
    const auto loaded = spott_map::LoadWorldFile(params.world_file);
    if (!loaded.ok()) {
      for (const auto& e : loaded.errors)
        ROS_FATAL("sensed_map_localization: %s", e.ToString().c_str());
      return 1;
    }
    start = loaded.world->robot_start;
  }
  if (!start) {
    ROS_FATAL("sensed_map_localization: no start: set ~initial_pose or ~world_file");
    return 1;
  }
  SensedMapLocalizationNode node(nh, params, *start);
  ros::spin();
  return 0;
}
