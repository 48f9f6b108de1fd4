#include "nc_binding.h"

#include <ros/package.h>
#include <spott_msgs/ReleaseWheels.h>
#include <spott_msgs/TakeWheels.h>
#include <tf2/exceptions.h>

#include <cmath>

#include "conversions.h"
#include "spott_map/ros/conversions.h"
#include "spott_ros/pose_conversions.h"
#include "spott_ros/range_readings.h"
#include "spott_ros/robot_geometry.h"

namespace rpl_executive {

namespace conv = ros_conversions;
namespace nc = noreils_chatila;

NcBinding::NcBinding(ros::NodeHandle& nh, const ros_parameters::NodeParameters& params,
                     spott_ros::InputRefusals* refusals, std::function<void()> changed)
    : params_(params), changed_(std::move(changed)), nh_(nh), refusals_(refusals), listener_(tf_) {
  const ros::TransportHints hints = ros::TransportHints().tcpNoDelay();
  sonar_sub_ = nh.subscribe(params.sonar_topic, 5, &NcBinding::OnSonar, this, hints);
  laser_sub_ = nh.subscribe(params.laser_topic, 2, &NcBinding::OnLaser, this, hints);
  battery_sub_ = nh.subscribe(params.battery_topic, 5, &NcBinding::OnBattery, this);
  places_sub_ = nh.subscribe("world_places", 1, &NcBinding::OnPlaces, this);
  arbiter_sub_ = nh.subscribe(params.arbiter + "/status", 5, &NcBinding::OnArbiter, this);
  cmd_pub_ = nh.advertise<geometry_msgs::Twist>("cmd_vel/" + params.wheels_source, 5);
  events_pub_ = nh.advertise<spott_msgs::MonitorEvent>("monitor_events", 50);
  markers_pub_ = ros::NodeHandle("~").advertise<visualization_msgs::MarkerArray>("markers", 20);
  take_ = nh.serviceClient<spott_msgs::TakeWheels>(params.arbiter + "/take_wheels");
  release_ = nh.serviceClient<spott_msgs::ReleaseWheels>(params.arbiter + "/release_wheels");
  timer_ = nh.createTimer(ros::Duration(1.0 / params.control_rate_hz),
                          [this](const ros::TimerEvent&) { Cycle(); });
}

NcBinding::~NcBinding() {
  if (have_wheels_) Wheels(false);
}

void NcBinding::Create(const spott_msgs::RangeRing& msg) {
  std::string error;
  const std::optional<double> radius =
      spott_ros::FootprintRadiusFromParameter(nh_, "robot_description", params_.base_frame, &error);
  if (!radius) {
    not_ready_ = "no robot radius: " + error;
    ROS_ERROR_THROTTLE(10.0, "rpl_executive: Noreils-Chatila missions cannot run: %s",
                       not_ready_.c_str());
    return;
  }
  ring_ = conv::RingFromMsg(msg);
  nc::OnBoardParameters on_board = params_.on_board;
  on_board.wall_following.robot_radius_m = *radius;  // the belt's distance from the centre
  try {
    kit_ = std::make_unique<nc::OnBoardModules>(on_board, ring_);
    exec_ = std::make_unique<nc::Executive>(params_.nc, params_.surveillance, ring_, kit_.get());
  } catch (const std::exception& e) {
    not_ready_ = std::string("the modules refused the ring or the parameters: ") + e.what();
    ROS_ERROR("rpl_executive: %s", not_ready_.c_str());
    kit_.reset();
    exec_.reset();
    return;
  }
  not_ready_.clear();
  exec_->SetRobotState("motors", nc::Value::Symbol(motors_on_ ? "ON" : "OFF"));
  ApplyPlaces();
  if (!params_.o_surveillances.empty()) {
    const std::string path =
        ros::package::getPath("rpl_executive") + "/missions/" + params_.o_surveillances + ".nc";
    const nc::ParseResult parsed = nc::ParseMissionFile(path);
    std::vector<nc::Diagnostic> d = parsed.diagnostics;
    if (parsed.ok()) {
      o_surveillances_ = parsed.file;
      d = exec_->SetOSurveillances(o_surveillances_, Now());
    }
    if (nc::HasErrors(d)) {
      ROS_ERROR("rpl_executive: O-surveillances %s not installed:\n%s", path.c_str(),
                nc::FormatDiagnostics(d).c_str());
    } else {
      ROS_INFO("rpl_executive: O-surveillances of %s installed", path.c_str());
    }
  }
  ROS_INFO("rpl_executive: Noreils-Chatila ready: %zu sonars, robot radius %.3f m",
           ring_.mounts.size(), *radius);
}

std::string NcBinding::NotReady() const { return not_ready_; }

std::string NcBinding::Start(const std::string& text, const std::string& file) {
  if (!exec_) return "not ready: " + not_ready_;
  const nc::ParseResult parsed = nc::ParseMissionText(text, file);
  if (!parsed.ok()) return nc::FormatDiagnostics(parsed.diagnostics);
  mission_ = parsed.file;
  // The odometry is placed in the map where the localization has the robot now.
  const std::string anchor = AnchorOdometry();
  if (!anchor.empty()) return "not ready: " + anchor;
  exec_->log().Clear();
  log_read_ = 0;
  last_event_.reset();
  UpdatePose(Now());
  const nc::StartResult r = exec_->StartMission(mission_, Now());
  if (!r.accepted) {
    std::string why = nc::HasErrors(r.errors) ? nc::FormatDiagnostics(r.errors) : "";
    if (!r.refusal.empty()) {
      why += (why.empty() ? "" : "\n") + nc::LocationText(file, r.refusal_where) + ": " + r.refusal;
    }
    return why.empty() ? "refused" : why;
  }
  last_state_ = nc::MissionState::kRunning;
  Wheels(true);
  Cycle();
  return "";
}

void NcBinding::Abort(const std::string& reason) {
  if (!exec_) return;
  exec_->Abort(reason, Now());
  Cycle();
}

bool NcBinding::running() const { return exec_ && exec_->state() == nc::MissionState::kRunning; }
nc::MissionState NcBinding::state() const {
  return exec_ ? exec_->state() : nc::MissionState::kIdle;
}
const std::string& NcBinding::mission_name() const {
  static const std::string none;
  return exec_ ? exec_->mission_name() : none;
}
std::string NcBinding::FailureText() const {
  return exec_ && exec_->state() == nc::MissionState::kFailed ? exec_->diagnosis().ToString() : "";
}
std::string NcBinding::CurrentCommand() const { return exec_ ? exec_->CurrentCommand() : ""; }
std::vector<std::string> NcBinding::ActiveMonitors() const {
  return exec_ ? exec_->ActiveMonitors() : std::vector<std::string>();
}
std::vector<spott_msgs::MonitorEvent> NcBinding::Fired() const {
  std::vector<spott_msgs::MonitorEvent> out;
  if (!exec_) return out;
  for (const nc::MonitorEvent& e : exec_->fired()) {
    out.push_back(conv::ToMsg(e, exec_->mission_name(), params_.map_frame, ros::Time(e.time_s)));
  }
  return out;
}

std::vector<std::string> NcBinding::TakeEvents() {
  std::vector<std::string> out;
  if (!exec_) return out;
  const auto& messages = exec_->log().messages();
  if (log_read_ > messages.size()) log_read_ = messages.size();  // the log dropped its oldest
  for (std::size_t i = log_read_; i < messages.size(); ++i) out.push_back(messages[i].ToString());
  log_read_ = messages.size();
  return out;
}

// ---- data --------------------------------------------------------------------------------------

void NcBinding::OnSonar(const spott_msgs::RangeRing& ring) {
  if (const std::string problem = spott_ros::RangeRingProblem(ring); !problem.empty()) {
    refusals_->RefuseProblem(params_.sonar_topic, problem);
    return;
  }
  if (!exec_) {
    if (ring.mounts.empty() || ring.mounts.size() != ring.ranges.size()) {
      not_ready_ = "the sonar ring has no mounts (or not one per range)";
      return;
    }
    Create(ring);
    if (!exec_) return;
  }
  if (ring.ranges.size() != ring_.mounts.size()) {
    ROS_WARN_THROTTLE(5.0, "rpl_executive: sonar ring of %zu ranges refused (the belt has %zu)",
                      ring.ranges.size(), ring_.mounts.size());
    return;
  }
  const double now = Now();
  int discarded = -1;
  const nc::SonarScan scan = conv::ScanFromMsg(ring, &discarded);
  if (discarded >= 0) {
    refusals_->Refuse(params_.sonar_topic, "ranges",
                      spott_ros::DiscardedReadingWhy(discarded, ring.ranges[discarded]));
  }
  UpdatePose(now);
  kit_->OnSonar(scan);
  exec_->OnSonar(scan, now);  // a monitor that fires runs its reflex here ...
  Cycle();                    // ... and the modules' new command goes to the wheels at once
}

void NcBinding::OnLaser(const sensor_msgs::LaserScan& scan) {
  if (!exec_) return;
  if (const std::string problem = spott_ros::LaserScanProblem(scan); !problem.empty()) {
    refusals_->RefuseProblem(params_.laser_topic, problem);
    return;
  }
  if (!laser_yaw_ || laser_frame_ != scan.header.frame_id) {
    try {
      const auto t = tf_.lookupTransform(params_.base_frame, scan.header.frame_id, ros::Time(0));
      const auto p = spott_ros::ToPose2D(t.transform);
      if (!p) return;
      laser_yaw_ = p->theta;
      laser_frame_ = scan.header.frame_id;
    } catch (const tf2::TransformException& e) {
      ROS_WARN_THROTTLE(10.0, "rpl_executive: laser frame: %s", e.what());
      return;
    }
  }
  exec_->OnLaser(conv::FromMsg(scan, *laser_yaw_), Now());
  Cycle();
}

void NcBinding::OnBattery(const sensor_msgs::BatteryState& battery) {
  if (!exec_) return;
  // NaN: not measured (sensor_msgs/BatteryState), nothing to say; beyond [0, 1]: not a charge.
  if (!std::isnan(battery.percentage) &&
      !(battery.percentage >= 0.0f && battery.percentage <= 1.0f)) {
    refusals_->Refuse(params_.battery_topic, "percentage",
                      std::to_string(battery.percentage) + " is not a fraction in [0, 1]");
    return;
  }
  const auto datum = conv::FromMsg(battery);
  if (!datum) return;
  exec_->OnBattery(*datum, Now());
  Cycle();
}

void NcBinding::OnPlaces(const spott_msgs::WorldPlaces& places) {
  if (const std::string problem = spott_map::ros_conversions::PlacesProblem(places);
      !problem.empty()) {
    refusals_->RefuseProblem("world_places", problem);
    return;
  }
  places_ = places;
  ApplyPlaces();
}

void NcBinding::ApplyPlaces() {
  if (!exec_ || !places_) return;
  for (const spott_msgs::Zone& z : places_->zones) {
    exec_->SetWorldZone(z.id, conv::PolygonFromMsg(z.polygon));
  }
  for (const spott_msgs::NamedPath& p : places_->paths) {
    exec_->SetWorldVariable(p.id, conv::PathToValue(p));
  }
}

void NcBinding::OnArbiter(const spott_msgs::ArbiterStatus&) {
  // The arbiter is the motors' interface: while it runs, the motors are ON.
  if (motors_on_) return;
  motors_on_ = true;
  if (exec_) exec_->SetRobotState("motors", nc::Value::Symbol("ON"));
}

std::string NcBinding::AnchorOdometry() {
  if (params_.pose_source != "odometry") return "";
  try {
    const auto t = tf_.lookupTransform(params_.map_frame, params_.odom_frame, ros::Time(0));
    map_to_odom_ = spott_ros::ToPose2D(t.transform);
    if (!map_to_odom_)
      return "the transform " + params_.map_frame + " -> " + params_.odom_frame +
             " is not a planar pose";
  } catch (const tf2::TransformException& e) {
    map_to_odom_.reset();
    return "no " + params_.map_frame + " -> " + params_.odom_frame +
           " to place the odometry in the map (is the localization running?): " + e.what();
  }
  last_pose_stamp_.reset();
  return "";
}

void NcBinding::UpdatePose(double now) {
  const bool odometry = params_.pose_source == "odometry";
  if (odometry && !map_to_odom_ && !AnchorOdometry().empty()) return;
  const std::string& frame = odometry ? params_.odom_frame : params_.map_frame;
  geometry_msgs::TransformStamped t;
  try {
    t = tf_.lookupTransform(frame, params_.base_frame, ros::Time(0));
  } catch (const tf2::TransformException& e) {
    ROS_WARN_THROTTLE(10.0, "rpl_executive: no pose (%s -> %s): %s", frame.c_str(),
                      params_.base_frame.c_str(), e.what());
    return;
  }
  if (last_pose_stamp_ && t.header.stamp <= *last_pose_stamp_) return;
  last_pose_stamp_ = t.header.stamp;
  auto p = spott_ros::ToPose2D(t.transform);
  if (!p) return;
  if (odometry) p = spott_ros::Compose(*map_to_odom_, *p);
  const nc::PoseDatum pose{nc::Pose2{p->x, p->y, p->theta}};
  kit_->OnPose(pose);
  exec_->OnPose(pose, now);
}

void NcBinding::Cycle() {
  if (!exec_) return;
  const double now = Now();
  UpdatePose(now);
  for (const auto& [handle, reply] : kit_->TakeReports()) {
    exec_->OnOperatorReport(handle, reply, now);
  }
  exec_->Step(now);
  SendWheels(now);
  for (const nc::DrawCommand& d : kit_->TakeDrawings()) {
    markers_pub_.publish(
        conv::DrawToMarkers(d, ring_, params_.map_frame, ros::Time::now(), &marker_id_));
  }
  const nc::MissionState state = exec_->state();
  if (state != last_state_) {
    if (last_state_ == nc::MissionState::kRunning) Wheels(false);
    last_state_ = state;
  }
  PublishMonitorEvents();
  if (changed_) changed_();
}

void NcBinding::SendWheels(double now) {
  if (!kit_) return;
  const nc::VelocityCommand v = kit_->Update(now);
  const bool nonzero = v.linear_mps != 0.0 || v.angular_rps != 0.0;
  const bool driving = running() || !kit_->wheels_holder().empty();
  if (driving || nonzero || sent_nonzero_) {
    cmd_pub_.publish(conv::ToTwist(v));
    sent_nonzero_ = nonzero;
  }
}

void NcBinding::PublishMonitorEvents() {
  for (const nc::MonitorEvent& e : exec_->TakeMonitorEvents()) {
    spott_msgs::MonitorEvent m =
        conv::ToMsg(e, exec_->mission_name(), params_.map_frame, ros::Time::now());
    events_pub_.publish(m);
    last_event_ = m;
  }
}

void NcBinding::Wheels(bool take) {
  if (take == have_wheels_) return;
  have_wheels_ = take;
  if (take) {
    spott_msgs::TakeWheels t;
    t.request.source = params_.wheels_source;
    if (!take_.call(t) || !t.response.success) {
      ROS_WARN("rpl_executive: take_wheels as '%s' failed: %s", params_.wheels_source.c_str(),
               t.response.message.c_str());
    }
  } else {
    spott_msgs::ReleaseWheels r;
    r.request.source = params_.wheels_source;
    if (!release_.call(r) || !r.response.success) {
      ROS_WARN("rpl_executive: release_wheels failed: %s", r.response.message.c_str());
    }
  }
}

}  // namespace rpl_executive
