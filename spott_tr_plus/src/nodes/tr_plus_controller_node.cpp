// tr_plus_controller: SPOTT's behavioural controller on the robot (Zelek and Levine III-C,
// Figs. 3-13): the TR+ navigation program run by the interpreter with its conditions and
// actions bound in C++ (controller/navigation_controller.h). Glue only: reads and validates the
// parameters, converts messages for the ROS-free core, and carries out what it asks.
//
// Action /task (spott_msgs/Task): a task command; a malformed one is rejected with its column,
// a new one preempts the running one (the robot stops first). Service ~parse_task: interprets a
// command from the robot's real pose without running it.
// Subscribes: room_door_graph, map_features, world_places (world_server, latched), sonar,
// infrared (spott_msgs/RangeRing), bumper, range_profile (QUADRIS), odom, localization_status.
// tf: map -> base_link (the localization's estimate), base_link -> the QUADRIS heads.
// Publishes: map_updates (spott_msgs/MapUpdate: the sensed features, door states), cmd_vel/reflex,
// cmd_vel/teleop, cmd_vel/executive (the arbiter's inputs), range_profile/point_head (the heads'
// scanning pattern), turret/command (std_msgs/Float64: the dense sonar scan's turret angle), ~state
// (spott_msgs/TRProgramState, latched, on change), ~tree_dot (the live TR trees as DOT, latched, on
// change), ~firing_rule_marker (rviz text over the robot). Calls: cmd_vel_arbiter/take_wheels,
// release_wheels; harmonic_planner/navigate (Navigate).
#include <actionlib/client/simple_action_client.h>
#include <actionlib/server/action_server.h>
#include <geometry_msgs/Twist.h>
#include <message_filters/subscriber.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <spott_msgs/ActiveLocalizeAction.h>
#include <spott_msgs/BumperRing.h>
#include <spott_msgs/LocalizationStatus.h>
#include <spott_msgs/MapFeatureArray.h>
#include <spott_msgs/MapUpdate.h>
#include <spott_msgs/NavigateAction.h>
#include <spott_msgs/ParseTask.h>
#include <spott_msgs/RangeProfile.h>
#include <spott_msgs/RangeRing.h>
#include <spott_msgs/ReleaseWheels.h>
#include <spott_msgs/RoomDoorGraph.h>
#include <spott_msgs/TakeWheels.h>
#include <spott_msgs/TaskAction.h>
#include <spott_msgs/WorldPlaces.h>
#include <std_msgs/Float64.h>
#include <std_msgs/String.h>
#include <tf2_ros/message_filter.h>
#include <tf2_ros/transform_listener.h>
#include <visualization_msgs/Marker.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <optional>

#include "spott_map/ros/conversions.h"
#include "spott_ros/goal_resend.h"
#include "spott_ros/input_refusals.h"
#include "spott_ros/parameter_reader.h"
#include "spott_ros/pose_conversions.h"
#include "spott_ros/range_readings.h"
#include "spott_ros/robot_geometry.h"
#include "spott_ros/robot_pose.h"
#include "spott_tr_plus/checker.h"
#include "spott_tr_plus/controller/navigation_controller.h"
#include "spott_tr_plus/dot_export.h"
#include "spott_tr_plus/parser.h"
#include "spott_tr_plus/ros/conversions.h"
#include "spott_tr_plus/ros/parameters.h"
#include "spott_tr_plus/ros/sensor_conversions.h"

namespace spott_tr_plus::controller {
namespace {

namespace mconv = spott_map::ros_conversions;
namespace conv = spott_tr_plus::ros_conversions;
namespace tconv = spott_tr_plus::ros_conversions;

using TaskServer = actionlib::ActionServer<spott_msgs::TaskAction>;
using NavigateClient = actionlib::SimpleActionClient<spott_msgs::NavigateAction>;
using ActiveLocalizeClient = actionlib::SimpleActionClient<spott_msgs::ActiveLocalizeAction>;

class ControllerNode : public ControllerIo {
 public:
  ControllerNode(ros::NodeHandle& nh, ros::NodeHandle& pnh, NodeParameters params)
      : nh_(nh),
        params_(std::move(params)),
        tf_listener_(tf_),
        task_server_(nh, "task", false),
        navigate_(nh, params_.navigate_action, false) {
    if (!params_.active_localize_action.empty())
      active_ = std::make_unique<ActiveLocalizeClient>(nh, params_.active_localize_action, false);
    updates_pub_ = nh.advertise<spott_msgs::MapUpdate>("map_updates", 20);
    for (const char* source : {"reflex", "teleop", "executive"}) {
      cmd_pubs_[source] = nh.advertise<geometry_msgs::Twist>(std::string("cmd_vel/") + source, 5);
    }
    heads_pub_ = nh.advertise<sensor_msgs::JointState>("range_profile/point_head", 2);
    turret_pub_ = nh.advertise<std_msgs::Float64>("turret/command", 2);
    state_pub_ = pnh.advertise<spott_msgs::TRProgramState>("state", 1, true);
    dot_pub_ = pnh.advertise<std_msgs::String>("tree_dot", 1, true);
    marker_pub_ = pnh.advertise<visualization_msgs::Marker>("firing_rule_marker", 1, true);
    take_ = nh.serviceClient<spott_msgs::TakeWheels>(params_.arbiter + "/take_wheels", true);
    release_ =
        nh.serviceClient<spott_msgs::ReleaseWheels>(params_.arbiter + "/release_wheels", true);
  }

  bool Load(std::vector<Diagnostic>* diags) {
    const ParseResult parsed = ParseProgramFile(params_.program_file);
    diags->insert(diags->end(), parsed.diagnostics.begin(), parsed.diagnostics.end());
    if (!parsed.ok()) return false;
    core_ =
        NavigationController::Create(parsed.program, params_.controller, this, diags, params_.main);
    if (!core_) return false;
    const CheckReport report = CheckProgram(parsed.program);
    for (const ProgramVerdict& v : report.programs) parents_[v.program] = v.parent;
    verdict_ = report.Summary();
    return true;
  }

  void Start() {
    ros::NodeHandle& nh = nh_;
    refusals_ = std::make_unique<spott_ros::InputRefusals>(nh, "tr_plus_controller");
    graph_sub_ = nh.subscribe("room_door_graph", 1, &ControllerNode::OnGraph, this);
    features_sub_ = nh.subscribe("map_features", 1, &ControllerNode::OnFeatures, this);
    places_sub_ = nh.subscribe("world_places", 1, &ControllerNode::OnPlaces, this);
    ros::TransportHints hints = ros::TransportHints().tcpNoDelay();
    sonar_sub_ = nh.subscribe("sonar", 5, &ControllerNode::OnSonar, this, hints);
    infrared_sub_ = nh.subscribe("infrared", 5, &ControllerNode::OnInfrared, this, hints);
    bumper_sub_ = nh.subscribe("bumper", 10, &ControllerNode::OnBumper, this, hints);
    // A profile waits until tf has its head's pose at its stamp (the heads pan while it travels:
    // taken at the latest pose, points swing across doorways; phantoms beside d_meeting_lab and
    // d_202 shut them on a busy machine).
    profile_sub_.subscribe(nh, "range_profile", 5);
    profile_filter_ = std::make_unique<tf2_ros::MessageFilter<spott_msgs::RangeProfile>>(
        profile_sub_, tf_, ProfileFixedFrame(), 5, nh);
    profile_filter_->registerCallback(&ControllerNode::OnProfile, this);
    odom_sub_ = nh.subscribe("odom", 10, &ControllerNode::OnOdom, this);
    status_sub_ = nh.subscribe("localization_status", 5, &ControllerNode::OnStatus, this);
    parse_srv_ =
        ros::NodeHandle("~").advertiseService("parse_task", &ControllerNode::OnParse, this);
    task_server_.registerGoalCallback([this](TaskServer::GoalHandle g) { OnTask(g); });
    task_server_.registerCancelCallback([this](TaskServer::GoalHandle g) { OnCancel(g); });
    core_->Start(Now());
    task_server_.start();
    tick_ =
        nh.createTimer(ros::Duration(1.0 / params_.tick_rate_hz), &ControllerNode::OnTick, this);
    AfterEvent();
  }

  // --- ControllerIo ----------------------------------------------------------------------------

  void SendNavigate(const NavigateGoal& g) override {
    spott_msgs::NavigateGoal goal;
    goal.target = spott_ros::ToPoseStamped(spott_ros::MakePose2D(g.x, g.y, 0.0), params_.frame_id,
                                           ros::Time::now());
    goal.ignore_heading = true;
    goal.position_tolerance = g.tolerance_m;
    goal.speed_mode = static_cast<uint8_t>(g.speed_mode);
    goal.direction_bias = g.heading.value_or(std::numeric_limits<double>::quiet_NaN());
    switch (g.bias) {
      case NavigateGoal::Bias::kHeading:
        goal.bias_kind = spott_msgs::NavigateGoal::BIAS_HEADING;
        break;
      case NavigateGoal::Bias::kToward:
        goal.bias_kind = spott_msgs::NavigateGoal::BIAS_TOWARD;
        break;
      case NavigateGoal::Bias::kAway:
        goal.bias_kind = spott_msgs::NavigateGoal::BIAS_AWAY;
        break;
      case NavigateGoal::Bias::kVia:
        goal.bias_kind = spott_msgs::NavigateGoal::BIAS_VIA;
        break;
      case NavigateGoal::Bias::kAround:
        goal.bias_kind = spott_msgs::NavigateGoal::BIAS_AROUND;
        break;
    }
    goal.bias_point.x = g.bias_x;
    goal.bias_point.y = g.bias_y;
    goal.bias_radius = g.bias_radius;
    goal.bias_sense = g.bias_sense;
    if (!navigate_.isServerConnected()) {
      ROS_WARN_THROTTLE(5.0, "tr_plus_controller: %s is not connected yet; the goal is sent anyway",
                        params_.navigate_action.c_str());
    }
    navigate_goal_ = goal;
    navigate_seq_ = g.seq;
    PublishNavigate();
    ROS_INFO("tr_plus_controller: Navigate to (%.2f, %.2f) [goal %lu]", g.x, g.y,
             static_cast<unsigned long>(g.seq));
  }

  // Sends navigate_goal_ (again, when actionlib lost it: spott_ros/goal_ack_watch.h).
  void PublishNavigate() {
    const std::uint64_t seq = navigate_seq_;
    spott_ros::MarkGoalSent(ack_watch_);
    navigate_.sendGoal(
        navigate_goal_,
        [this, seq](const actionlib::SimpleClientGoalState&,
                    const spott_msgs::NavigateResultConstPtr& result) {
          pending_done_.push_back(
              {seq,
               result ? static_cast<NavigateOutcome>(result->outcome) : NavigateOutcome::kFailed,
               result ? result->reason : "no result"});
        },
        NavigateClient::SimpleActiveCallback(),
        [this, seq](const spott_msgs::NavigateFeedbackConstPtr& fb) {
          core_->NavigateFeedback(seq, fb->distance_remaining, Now());
        });
  }

  bool StartActiveLocalize(double timeout_s) override {
    if (!active_ || !active_->isServerConnected()) {
      ROS_WARN("tr_plus_controller: no active localization (%s)",
               active_ ? "not connected" : "active_localize_action is \"\"");
      return false;
    }
    spott_msgs::ActiveLocalizeGoal goal;
    goal.timeout = timeout_s;
    ROS_INFO(
        "tr_plus_controller: Navigate says not localized: localizing actively (at most %.0f s)",
        timeout_s);
    active_->sendGoal(goal, [this](const actionlib::SimpleClientGoalState& state,
                                   const spott_msgs::ActiveLocalizeResultConstPtr& result) {
      pending_active_.push_back(
          {result && result->success, result ? result->reason : "no result: " + state.toString()});
    });
    return true;
  }

  void CancelActiveLocalize() override {
    if (active_ && !active_->getState().isDone()) active_->cancelGoal();
  }

  void CancelNavigate() override {
    ack_watch_.Stop();
    if (navigate_.getState().isDone()) return;
    navigate_.cancelGoal();
  }

  void TakeWheels(const std::string& source) override {
    spott_msgs::TakeWheels srv;
    srv.request.source = source;
    if (!take_.isValid()) {
      take_ = nh_.serviceClient<spott_msgs::TakeWheels>(params_.arbiter + "/take_wheels", true);
    }
    if (!take_.call(srv) || !srv.response.success) {
      ROS_WARN("tr_plus_controller: take_wheels(%s) failed: %s", source.c_str(),
               srv.response.message.c_str());
    }
  }

  void ReleaseWheels(const std::string& source) override {
    spott_msgs::ReleaseWheels srv;
    srv.request.source = source;
    if (!release_.isValid()) {
      release_ =
          nh_.serviceClient<spott_msgs::ReleaseWheels>(params_.arbiter + "/release_wheels", true);
    }
    if (!release_.call(srv) || !srv.response.success) {
      ROS_WARN("tr_plus_controller: release_wheels(%s) failed: %s", source.c_str(),
               srv.response.message.c_str());
    }
  }

  void Drive(const std::string& source, const Velocity& v) override {
    auto it = cmd_pubs_.find(source);
    if (it == cmd_pubs_.end()) return;
    geometry_msgs::Twist t;
    t.linear.x = v.linear_mps;
    t.angular.z = v.angular_rps;
    it->second.publish(t);
  }

  void SendMapUpdate(const MapChange& change) override {
    spott_msgs::MapUpdate u;
    u.header.frame_id = params_.frame_id;
    u.header.stamp = ros::Time::now();
    for (const spott_map::MapFeature& f : change.added) u.added.push_back(mconv::ToMsg(f));
    u.removed = change.removed;
    if (change.retraction && !change.removed.empty()) {
      ROS_WARN("tr_plus_controller: the estimate jumped: %zu sensed features taken back (%s%s)",
               change.removed.size(), change.removed.front().c_str(),
               change.removed.size() > 1 ? ", ..." : "");
    } else if (!change.removed.empty()) {  // refined by a grown cluster, or cleared for a retry
      ROS_INFO("tr_plus_controller: %zu sensed features removed from the map (%s%s)",
               change.removed.size(), change.removed.front().c_str(),
               change.removed.size() > 1 ? ", ..." : "");
    }
    for (const auto& [id, state] : change.doors) {
      spott_msgs::DoorState d;
      d.door_id = id;
      d.state = mconv::ToMsg(state);
      u.doors.push_back(d);
      ROS_INFO("tr_plus_controller: door %s %s in the map (%s)", id.c_str(),
               spott_map::ToString(state),
               change.retraction ? "the sensed state taken back" : "sensed");
    }
    if (!change.added.empty()) {
      ROS_INFO("tr_plus_controller: %zu sensed features added to the map (%s%s)",
               change.added.size(), change.added.front().id.c_str(),
               change.added.size() > 1 ? ", ..." : "");
    }
    updates_pub_.publish(u);
  }

  void SetPtuPattern(const std::string& pattern) override { ptu_pattern_ = pattern; }

  void PointTurret(double yaw) override {
    std_msgs::Float64 m;
    m.data = yaw;
    turret_pub_.publish(m);
    if (yaw == 0.0)
      ROS_DEBUG("tr_plus_controller: turret home (%d dense sonar scans)", core_->sonar_scans());
  }

  void PublishTaskFeedback(const TaskFeedback& f) override {
    auto it = goals_.find(f.id);
    if (it == goals_.end()) return;
    spott_msgs::TaskFeedback fb;
    fb.state = f.state;
    fb.firing_rule = f.firing_rule;
    fb.distance_remaining = f.distance_remaining;
    fb.current_pose = spott_ros::ToPoseStamped(
        spott_ros::MakePose2D(f.pose.x, f.pose.y, f.pose.yaw), params_.frame_id, ros::Time::now());
    it->second.publishFeedback(fb);
  }

  void TaskFinished(const TaskResult& r) override {
    auto it = goals_.find(r.id);
    if (it == goals_.end()) return;
    spott_msgs::TaskResult result;
    result.success = r.success;
    result.outcome = r.outcome;
    result.message = r.message;
    result.final_pose = spott_ros::ToPoseStamped(
        spott_ros::MakePose2D(r.final_pose.x, r.final_pose.y, r.final_pose.yaw), params_.frame_id,
        ros::Time::now());
    result.interpretation = r.interpretation;
    result.goal.x = r.goal ? r.goal->x() : std::numeric_limits<double>::quiet_NaN();
    result.goal.y = r.goal ? r.goal->y() : std::numeric_limits<double>::quiet_NaN();
    result.trace = r.trace;
    result.features_added = core_->added_features();
    result.found_at.x = result.found_at.y = std::numeric_limits<double>::quiet_NaN();
    if (r.found) {
      result.found_id = r.found->id;
      result.found_label = r.found->label;
      result.found_at.x = r.found->pose.x;
      result.found_at.y = r.found->pose.y;
      result.found_at.z = r.found->size_z;
    }
    ROS_INFO("tr_plus_controller: task #%ld %s%s%s", static_cast<long>(r.id), r.outcome.c_str(),
             r.message.empty() ? "" : ": ", r.message.c_str());
    if (r.outcome == "preempted") {
      it->second.setCanceled(result, r.message);
    } else if (r.outcome == "rejected") {
      // Accepted, then refused by the interpretation (an unreachable goal region, ...).
      it->second.setAborted(result, r.message);
    } else if (r.success) {
      it->second.setSucceeded(result, r.message);
    } else {
      it->second.setAborted(result, r.message);
    }
    goals_.erase(it);
  }

 private:
  double Now() const { return ros::Time::now().toSec(); }

  // --- Task action ---------------------------------------------------------------------------

  void OnTask(TaskServer::GoalHandle goal) {
    const std::string command = goal.getGoal()->command;
    const std::int64_t id = ++task_count_;
    const NavigationController::Acceptance a = core_->StartTask(id, command, Now());
    if (!a.accepted) {
      spott_msgs::TaskResult result;
      result.success = false;
      result.outcome = "rejected";
      result.message = a.message;
      ROS_WARN("tr_plus_controller: task '%s' rejected: %s", command.c_str(), a.message.c_str());
      goal.setRejected(result, a.message);
      AfterEvent();
      return;
    }
    goal.setAccepted("task #" + std::to_string(id));
    goals_[id] = goal;
    ROS_INFO("tr_plus_controller: task #%ld '%s'", static_cast<long>(id), command.c_str());
    AfterEvent();
  }

  void OnCancel(TaskServer::GoalHandle goal) {
    for (auto& [id, g] : goals_) {
      if (g == goal) {
        core_->CancelTask(id, Now());
        break;
      }
    }
    AfterEvent();
  }

  bool OnParse(spott_msgs::ParseTask::Request& req, spott_msgs::ParseTask::Response& res) {
    res.success = core_->InterpretOnly(req.command, &res.interpretation, &res.message);
    return true;
  }

  // --- The map database ----------------------------------------------------------------------

  void OnGraph(const spott_msgs::RoomDoorGraph& msg) {
    std::string error;
    const auto graph = mconv::FromMsg(msg, &error);
    if (!graph) {
      refusals_->Refuse("room_door_graph", "rooms/doors", error);
      return;
    }
    if (graph->rooms().empty() && have_graph_) {
      refusals_->Refuse("room_door_graph", "rooms", "an empty graph would replace the building's");
      return;
    }
    have_graph_ = !graph->rooms().empty();
    core_->SetGraph(*graph, Now());
    AfterEvent();
  }

  void OnFeatures(const spott_msgs::MapFeatureArray& msg) {
    if (msg.features.empty() && have_features_) {  // features are removed with a MapUpdate
      refusals_->Refuse("map_features", "features", "an empty array would remove every feature");
      return;
    }
    std::vector<spott_map::MapFeature> features;
    for (const auto& f : msg.features) {
      std::string error;
      if (auto feature = mconv::FromMsg(f, &error)) {
        features.push_back(std::move(*feature));
      } else {
        refusals_->Refuse("map_features", "features[]", error);
      }
    }
    have_features_ = have_features_ || !features.empty();
    core_->SetFeatures(features, Now());
    AfterEvent();
  }

  void OnPlaces(const spott_msgs::WorldPlaces& msg) {
    if (const std::string problem = mconv::PlacesProblem(msg); !problem.empty()) {
      refusals_->RefuseProblem("world_places", problem);
      return;
    }
    core_->SetPlaces(conv::PlacesFromMsg(msg));
  }

  // --- Sensors -------------------------------------------------------------------------------

  void UpdatePose() {
    try {
      const spott_ros::RobotPose r = spott_ros::LookupRobotPose(
          tf_, {params_.frame_id, params_.odom_frame, params_.base_frame});
      std::optional<Pose2> odom;
      if (r.odom) odom = Pose2{r.odom->x, r.odom->y, r.odom->theta};
      core_->SetPose(Pose2{r.pose.x, r.pose.y, r.pose.theta}, Now(), odom);
      have_pose_ = true;
    } catch (const tf2::TransformException& e) {
      ROS_WARN_THROTTLE(10.0, "tr_plus_controller: no pose yet (%s)", e.what());
    }
  }

  // A ring the mapper and the reflexes can use (issue 21: a ring without a usable max range
  // would map every reading as "no echo" and clear the sensed obstacles); impossible readings
  // dropped out. nullopt when refused.
  std::optional<RangeRing> CheckedRing(const std::string& topic, const spott_msgs::RangeRing& msg) {
    std::string problem;
    int discarded = -1;
    auto ring = conv::RingFromMsg(msg, &problem, &discarded);
    if (!ring) refusals_->RefuseProblem(topic, problem);
    if (discarded >= 0)
      refusals_->Refuse(topic, "ranges",
                        spott_ros::DiscardedReadingWhy(discarded, msg.ranges[discarded]));
    return ring;
  }

  void OnSonar(const spott_msgs::RangeRing& msg) {
    const auto ring = CheckedRing("sonar", msg);
    if (!ring) return;
    UpdatePose();
    core_->Sonar(*ring, Now());
    AfterEvent();
  }

  void OnInfrared(const spott_msgs::RangeRing& msg) {
    const auto ring = CheckedRing("infrared", msg);
    if (!ring) return;
    core_->Infrared(*ring, Now());
    AfterEvent();
  }

  void OnBumper(const spott_msgs::BumperRing& msg) {
    const std::vector<double> pressed = conv::PressedAngles(msg);
    core_->Bumper(pressed, Now());
    if (!pressed.empty()) AfterEvent();
  }

  // The frame that stays put while a profile travels: odometry's (smooth), else the map.
  std::string ProfileFixedFrame() const {
    return params_.odom_frame.empty() ? params_.frame_id : params_.odom_frame;
  }

  void OnProfile(const spott_msgs::RangeProfileConstPtr& profile) {
    const spott_msgs::RangeProfile& msg = *profile;
    geometry_msgs::TransformStamped t;
    try {
      // The head at the profile's stamp, into the robot's frame now (through the fixed frame):
      // the points are placed with the pose the controller holds now.
      t = tf_.lookupTransform(params_.base_frame, ros::Time(0), msg.header.frame_id,
                              msg.header.stamp, ProfileFixedFrame());
    } catch (const tf2::TransformException& e) {
      ROS_WARN_THROTTLE(10.0, "tr_plus_controller: range profile frame: %s", e.what());
      return;
    }
    // Both orientations name objects (a vertical profile sees a desk's top below the heads);
    // the horizontal ones map line segments too.
    const bool vertical = msg.orientation == spott_msgs::RangeProfile::VERTICAL;
    Vec3 head;
    if (const auto samples = conv::ProfileSamples(msg, t.transform, &head))
      core_->RecognitionProfile(head, *samples, vertical, Now());
    if (vertical) return;
    Vec2 origin;
    const auto points = conv::ProfilePoints(msg, t.transform, params_.ptu_min_height_m,
                                            params_.ptu_max_height_m, &origin);
    if (!points) return;
    core_->RangeProfile(origin, *points, Now());
  }

  void OnOdom(const nav_msgs::Odometry& msg) {
    const auto p = spott_ros::ToPose2D(msg.pose.pose);
    if (!p) {
      refusals_->Refuse("odom", "pose.pose", "not finite or no yaw in the quaternion");
      return;
    }
    core_->SetOdometry(Pose2{p->x, p->y, p->theta}, msg.twist.twist.linear.x,
                       msg.twist.twist.angular.z, Now());
  }

  void OnStatus(const spott_msgs::LocalizationStatus& msg) {
    core_->SetLocalization(!msg.lost && msg.mode == spott_msgs::LocalizationStatus::TRACKING,
                           Now());
  }

  // --- Time ----------------------------------------------------------------------------------

  void OnTick(const ros::TimerEvent&) {
    const double now = Now();
    if (spott_ros::GoalLostInTransport(ack_watch_, navigate_, "tr_plus_controller",
                                       params_.navigate_action)) {
      PublishNavigate();
    }
    UpdatePose();
    if (params_.assume_localized) core_->SetLocalization(true, now);
    for (const auto& d : pending_done_) core_->NavigateDone(d.seq, d.outcome, d.reason, now);
    pending_done_.clear();
    for (const auto& [success, reason] : pending_active_)
      core_->ActiveLocalizeDone(success, reason, now);
    pending_active_.clear();
    core_->Tick(now);
    PointHeads(now);
    AfterEvent();
  }

  void OnWake(const ros::TimerEvent&) {
    core_->Advance(Now());
    AfterEvent();
  }

  void PointHeads(double now) {
    if (ptu_pattern_.empty() || params_.pan_joints.empty() || now - last_heads_s_ < 0.5) return;
    last_heads_s_ = now;
    sensor_msgs::JointState js;
    js.header.stamp = ros::Time::now();
    const auto look = core_->ObjectToLookAt();
    const std::optional<Vec2> look_at = look ? std::optional<Vec2>(look->at) : std::nullopt;
    const std::vector<double> pan = PanHeads(ptu_pattern_, params_.pan_joints.size(), now,
                                             core_->pose(), core_->map(), params_.ptu, look_at);
    // Head 0 tilts down onto a face below the heads that recognition looks at (a desk's).
    const double tilt0 = look && look->height && core_->pose() && ptu_pattern_ == "room"
                             ? TiltToward(*core_->pose(), look->at, *look->height, params_.ptu)
                             : 0.0;
    // The heads ride on the turret; the pattern's angles are from the base's heading.
    const double turret = core_->turret_target();
    for (std::size_t i = 0; i < params_.pan_joints.size(); ++i) {
      js.name.push_back(params_.pan_joints[i]);
      js.position.push_back(pan[i] - turret);
      js.name.push_back(params_.tilt_joints[i]);
      js.position.push_back(i == 0 ? tilt0 : 0.0);
    }
    heads_pub_.publish(js);
  }

  // The live state on change, the rviz text, and the interpreter's next wake-up.
  void AfterEvent() {
    const double wake = core_->NextWakeTime();
    if (std::isfinite(wake) && wake != scheduled_wake_) {
      scheduled_wake_ = wake;
      wake_ = nh_.createTimer(ros::Duration(std::max(wake - Now(), 1e-4)), &ControllerNode::OnWake,
                              this, true);
    }
    const InterpreterState s = core_->State();
    std::string signature;
    for (const FrameState& f : s.frames) {
      signature +=
          f.program + ":" + std::to_string(f.firing_rule) + (f.action_running ? "r" : "") + "/";
      for (bool v : f.rule_values) signature += v ? '1' : '0';
      signature += ";";
    }
    for (const ProcessState& p : s.processes) {
      signature += p.name + (p.value ? "1" : "0") + (p.active ? "a" : "") + ",";
    }
    if (signature != last_signature_) {
      last_signature_ = signature;
      state_pub_.publish(tconv::ToMsg(s, core_->program(), ros::Time::now()));
      std_msgs::String dot;
      for (const FrameState& f : s.frames) {
        const Program* p = core_->program().FindProgram(f.program);
        auto parent = parents_.find(f.program);
        if (!p || parent == parents_.end()) continue;
        DotLiveState live;
        live.rule_values = f.rule_values;
        live.firing_rule = f.firing_rule;
        dot.data += TrTreeDot(*p, parent->second, &live);
      }
      dot_pub_.publish(dot);
    }
    const double now = Now();
    if (core_->pose() && (core_->firing_rule() != marker_text_ || now - marker_s_ > 0.5)) {
      marker_text_ = core_->firing_rule();
      marker_s_ = now;
      visualization_msgs::Marker m =
          mconv::MakeMarker("tr_plus_firing_rule", 0, visualization_msgs::Marker::TEXT_VIEW_FACING,
                            params_.frame_id, ros::Time::now());
      m.pose.position.x = core_->pose()->x;
      m.pose.position.y = core_->pose()->y;
      m.pose.position.z = params_.marker_height_m;
      m.scale.z = 0.3;
      m.color = mconv::Colour(1.0f, 0.9f, 0.2f);
      m.text = marker_text_.empty() ? "(no rule fired yet)" : marker_text_;
      marker_pub_.publish(m);
    }
  }

  struct Done {
    std::uint64_t seq;
    NavigateOutcome outcome;
    std::string reason;
  };

  ros::NodeHandle nh_;
  NodeParameters params_;
  tf2_ros::Buffer tf_;
  tf2_ros::TransformListener tf_listener_;
  TaskServer task_server_;
  NavigateClient navigate_;
  spott_msgs::NavigateGoal navigate_goal_;  ///< The last goal sent, kept to send it again.
  std::uint64_t navigate_seq_ = 0;
  spott_ros::GoalAckWatch ack_watch_;
  std::unique_ptr<NavigationController> core_;
  std::map<std::string, std::vector<int>> parents_;
  std::string verdict_;
  std::map<std::int64_t, TaskServer::GoalHandle> goals_;
  std::int64_t task_count_ = 0;
  std::vector<Done> pending_done_;
  std::unique_ptr<ActiveLocalizeClient> active_;  ///< None when active_localize_action is "".
  std::vector<std::pair<bool, std::string>> pending_active_;  ///< Its ends (success, reason).
  bool have_pose_ = false;
  bool have_graph_ = false, have_features_ = false;  ///< Once the map came: emptiness is refused.
  std::unique_ptr<spott_ros::InputRefusals> refusals_;
  std::string ptu_pattern_;
  double last_heads_s_ = -1e300;
  std::string last_signature_, marker_text_;
  double marker_s_ = -1e300;
  double scheduled_wake_ = -1;
  ros::Publisher updates_pub_, heads_pub_, turret_pub_, state_pub_, dot_pub_, marker_pub_;
  std::map<std::string, ros::Publisher> cmd_pubs_;
  ros::Subscriber graph_sub_, features_sub_, places_sub_, sonar_sub_, infrared_sub_, bumper_sub_,
      odom_sub_, status_sub_;
  message_filters::Subscriber<spott_msgs::RangeProfile> profile_sub_;
  std::unique_ptr<tf2_ros::MessageFilter<spott_msgs::RangeProfile>> profile_filter_;
  ros::ServiceServer parse_srv_;
  ros::ServiceClient take_, release_;
  ros::Timer tick_, wake_;

 public:
  const std::string& verdict() const { return verdict_; }
};

}  // namespace
}  // namespace spott_tr_plus::controller

int main(int argc, char** argv) {
  ros::init(argc, argv, "tr_plus_controller");
  ros::NodeHandle nh, pnh("~");
  namespace c = spott_tr_plus::controller;
  spott_ros::ParameterReader reader = spott_ros::ParameterReader::FromNode(pnh);
  c::NodeParameters params;
  c::ReadParameters(reader, params);
  std::string error;  // the radius from the robot description, as every node takes it
  const auto radius = spott_ros::FootprintRadiusFromParameter(nh, params.robot_description,
                                                              params.base_frame, &error);
  if (!radius) reader.Fail("robot_description: " + error);
  params.controller.robot_radius_m = radius.value_or(0.2285);
  for (const auto& v : c::ValidateParameters(params.controller)) reader.Fail(v);
  const auto problems = reader.Finish();
  for (const auto& w : reader.Warnings()) ROS_WARN("tr_plus_controller: %s", w.c_str());
  if (!problems.empty()) {
    for (const auto& p : problems) ROS_FATAL("tr_plus_controller: parameter %s", p.c_str());
    return 1;
  }
  c::ControllerNode node(nh, pnh, params);
  std::vector<spott_tr_plus::Diagnostic> diags;
  if (!node.Load(&diags)) {
    ROS_FATAL("tr_plus_controller: cannot run %s:\n%s", params.program_file.c_str(),
              spott_tr_plus::FormatDiagnostics(diags).c_str());
    return 1;
  }
  if (!diags.empty()) ROS_WARN("%s", spott_tr_plus::FormatDiagnostics(diags).c_str());
  ROS_INFO("tr_plus_controller: running %s (robot radius %.4f m)\n%s", params.program_file.c_str(),
           *radius, node.verdict().c_str());
  node.Start();
  ros::spin();
  return 0;
}
