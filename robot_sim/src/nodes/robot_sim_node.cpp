// robot_sim: the simulator node. Steps the ROS-free core at physics_rate_hz of simulated time,
// publishes /clock (faster than real time when asked), odometry and tf odom->base_link, the
// sensors, the battery, ground truth (evaluation only), and serves the fault services. Topics,
// services and parameters are documented in robot_sim/README.md and config/robot_sim.yaml.
#include <cmath>
#include <cstring>
#include <memory>
#include <optional>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/TransformStamped.h>
#include <ros/callback_queue.h>
#include <ros/package.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/JointState.h>
#include <spott_msgs/LoadWorld.h>
#include <spott_msgs/RemoveObstacle.h>
#include <std_msgs/Float64.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/transform_broadcaster.h>
#include <topic_tools/shape_shifter.h>

#include "robot_sim/fault_events.h"
#include "robot_sim/ros/conversions.h"
#include "robot_sim/ros/parameters.h"
#include "spott_map/pose_algebra.h"
#include "spott_map/pose_text.h"
#include "spott_map/world_loader.h"
#include "spott_ros/parameter_reader.h"
#include "spott_ros/pose_conversions.h"

#include <octomap/OcTree.h>

namespace robot_sim {
namespace {

namespace conv = ros_conversions;

geometry_msgs::TransformStamped ToTransform(const spott_map::Pose2& p, const std::string& frame,
                                            const std::string& child, const ros::Time& stamp) {
  return spott_ros::ToTransform(spott_ros::MakePose2D(p.x, p.y, p.yaw), frame, child, stamp);
}

// The header stamp of any message that starts with a std_msgs/Header (seq, stamp, frame_id):
// the consumers' outputs the pacer watches, whatever their type.
std::optional<ros::Time> HeaderStamp(const topic_tools::ShapeShifter& msg) {
  if (msg.size() < 12) return std::nullopt;
  std::vector<std::uint8_t> bytes(msg.size());
  ros::serialization::OStream out(bytes.data(), static_cast<std::uint32_t>(bytes.size()));
  msg.write(out);
  std::uint32_t sec, nsec;
  std::memcpy(&sec, bytes.data() + 4, 4);
  std::memcpy(&nsec, bytes.data() + 8, 4);
  if (nsec >= 1000000000u) return std::nullopt;
  return ros::Time(sec, nsec);
}

class SimNode {
 public:
  SimNode(ros::NodeHandle& nh, ros::NodeHandle& pnh, SimNodeParameters params,
          std::unique_ptr<Simulator> sim, int robot, std::vector<FaultEvent> schedule)
      : params_(std::move(params)),
        sim_(std::move(sim)),
        robot_(robot),
        schedule_(std::move(schedule)),
        rng_(static_cast<std::uint64_t>(params_.seed)),
        pacer_(params_.consumers),
        battery_(params_.battery) {
    const RobotSpec& spec = sim_->spec(robot_);
    clock_pub_ = nh.advertise<rosgraph_msgs::Clock>("clock", 10);
    odom_pub_ = nh.advertise<nav_msgs::Odometry>("odom", 10);
    // 2 s of ground truth queued per subscriber: the runs' judges (demo_report, the recorder)
    // must not lose samples to a short stall on a loaded machine.
    truth_pub_ = nh.advertise<nav_msgs::Odometry>("sim/ground_truth", 100);
    joints_pub_ = nh.advertise<sensor_msgs::JointState>("joint_states", 10);
    for (const RangeRingSpec& ring : spec.rings) {
      ring_pubs_.push_back(nh.advertise<spott_msgs::RangeRing>(ring.name, 10));
      range_pubs_.push_back(
          nh.advertise<sensor_msgs::Range>(ring.name + "/range", ring.mounts.size() * 2));
    }
    if (spec.laser) scan_pub_ = nh.advertise<sensor_msgs::LaserScan>("scan", 10);
    contact_pub_ = nh.advertise<spott_msgs::BumperRing>("sim/contact", 10);
    if (spec.bumper) {
      bumper_pub_ = nh.advertise<spott_msgs::BumperRing>("bumper", 10);
      bumper_markers_pub_ =
          nh.advertise<visualization_msgs::MarkerArray>("bumper_markers", 1, true);
    }
    if (!spec.profilers.empty()) {
      profile_pub_ = nh.advertise<spott_msgs::RangeProfile>("range_profile", 10);
      head_sub_ = nh.subscribe("range_profile/point_head", 10, &SimNode::OnPointHead, this);
    }
    markers_pub_ = nh.advertise<visualization_msgs::MarkerArray>("sim/octomap_markers", 1, true);
    cmd_sub_ = nh.subscribe("cmd_vel", 10, &SimNode::OnCmdVel, this);
    turret_sub_ = nh.subscribe("turret/command", 10, &SimNode::OnTurret, this);
    ros::NodeHandle sim_nh(nh, "sim");
    services_.push_back(sim_nh.advertiseService("kidnap", &SimNode::OnKidnap, this));
    services_.push_back(sim_nh.advertiseService("set_door_state", &SimNode::OnDoor, this));
    services_.push_back(sim_nh.advertiseService("add_obstacle", &SimNode::OnAddObstacle, this));
    services_.push_back(
        sim_nh.advertiseService("remove_obstacle", &SimNode::OnRemoveObstacle, this));
    services_.push_back(sim_nh.advertiseService("sensor_fault", &SimNode::OnSensorFault, this));
    services_.push_back(sim_nh.advertiseService("odometry_slip", &SimNode::OnSlip, this));
    services_.push_back(sim_nh.advertiseService("save_octomap", &SimNode::OnSaveOctomap, this));
    services_.push_back(sim_nh.advertiseService("load_world", &SimNode::OnLoadWorld, this));
    for (std::size_t i = 0; i < params_.consumers.topics.size(); ++i) {
      consumer_subs_.push_back(nh.subscribe<topic_tools::ShapeShifter>(
          params_.consumers.topics[i], 5, [this, i](const topic_tools::ShapeShifter::ConstPtr& m) {
            if (const auto stamp = HeaderStamp(*m)) pacer_.Observe(i, stamp->toSec());
          }));
    }
    rtf_pub_ = nh.advertise<std_msgs::Float64>("sim/real_time_factor", 1);
    faults_pub_ = nh.advertise<diagnostic_msgs::DiagnosticArray>("sim/faults", 10, true);
    battery_pub_ = nh.advertise<sensor_msgs::BatteryState>("battery", 10);
    (void)pnh;
  }

  void Run() {
    const double dt = 1.0 / params_.physics_rate_hz;
    auto every = [&](double rate) {
      return std::max<long>(1, std::lround(params_.physics_rate_hz / rate));
    };
    const long odom_every = every(params_.odom_rate_hz);
    const long sensor_every = every(params_.sensor_rate_hz);
    const long laser_every = every(params_.laser_rate_hz);
    const long profile_every = every(params_.profile_rate_hz);
    const long battery_every = every(params_.battery_rate_hz);
    PublishClock(ros::Time(0, 0));
    PublishOdometry(ros::Time(0, 0));
    ros::WallTime wall_start = ros::WallTime::now();
    long step = 0;
    ros::WallTime rtf_wall = wall_start;
    double rtf_sim = 0.0;
    while (ros::ok()) {
      ros::getGlobalCallbackQueue()->callAvailable();
      const double now_s = step * dt;
      // The stack lags behind the clock (a busy machine): wait for it instead of stepping on.
      if (pacer_.Hold(now_s, ros::WallTime::now().toSec())) {
        ROS_WARN_THROTTLE(10.0, "robot_sim: holding the clock: the stack lags %.2f s behind",
                          pacer_.lag_s());
        ros::WallDuration(0.0005).sleep();
        if (params_.real_time_factor > 0) {  // resume at the asked pace, without a burst
          wall_start =
              ros::WallTime::now() - ros::WallDuration(step * dt / params_.real_time_factor);
        }
        continue;
      }
      for (const std::string& t : pacer_.TakeGivenUp()) {
        ROS_WARN(
            "robot_sim: %s is silent for %.1f s of wall time: not waiting for it until it "
            "publishes again",
            t.c_str(), params_.consumers.max_hold_s);
      }
      RunSchedule(now_s);
      if (params_.cmd_vel_timeout_s > 0 && have_command_ &&
          now_s - last_command_s_ > params_.cmd_vel_timeout_s) {
        sim_->SetCommand(robot_, {}, nullptr);
        have_command_ = false;
        ROS_WARN("robot_sim: no cmd_vel for %.2f s of simulated time: stopping",
                 params_.cmd_vel_timeout_s);
      }
      sim_->Step(dt, rng_);
      battery_.Step(dt, sim_->Velocity(robot_).v, sim_->Velocity(robot_).w);
      ++step;
      const ros::Time stamp(step * dt);
      PublishClock(stamp);
      if (step % odom_every == 0) PublishOdometry(stamp);
      if (step % sensor_every == 0) PublishSensors(stamp);
      if (step % laser_every == 0) PublishLaser(stamp, laser_every * dt);
      if (step % profile_every == 0) PublishProfiles(stamp);
      if (step % battery_every == 0) {
        battery_pub_.publish(conv::ToBatteryState(battery_, params_.base_frame, stamp));
      }
      if (step % odom_every == 0) {  // the real-time factor achieved over the last second
        const ros::WallTime w = ros::WallTime::now();
        if ((w - rtf_wall).toSec() >= 1.0) {
          std_msgs::Float64 rtf;
          rtf.data = (step * dt - rtf_sim) / (w - rtf_wall).toSec();
          rtf_pub_.publish(rtf);
          rtf_wall = w;
          rtf_sim = step * dt;
        }
      }
      if (params_.publish_octomap_markers && sim_->world().revision() != markers_revision_) {
        markers_revision_ = sim_->world().revision();
        markers_pub_.publish(
            conv::ToVoxelMarkers(sim_->world().OccupiedLeaves(), params_.map_frame, stamp));
      }
      if (params_.real_time_factor > 0) {
        const ros::WallTime target =
            wall_start + ros::WallDuration(step * dt / params_.real_time_factor);
        const ros::WallTime wall_now = ros::WallTime::now();
        if (target > wall_now) {
          (target - wall_now).sleep();
        } else if ((wall_now - target).toSec() > 1.0) {
          // Far behind (a loaded machine): do not try to catch up in a burst.
          wall_start += wall_now - target;
        }
      }
    }
  }

 private:
  ros::Time Now() const { return ros::Time(sim_->time()); }

  void PublishClock(const ros::Time& stamp) {
    rosgraph_msgs::Clock c;
    c.clock = stamp;
    clock_pub_.publish(c);
  }

  void PublishOdometry(const ros::Time& stamp) {
    const Odometry& odo = sim_->odometry(robot_);
    odom_pub_.publish(
        conv::ToOdometry(odo.pose(), odo.twist(), params_.odom_frame, params_.base_frame, stamp));
    tf_.sendTransform(ToTransform(odo.pose(), params_.odom_frame, params_.base_frame, stamp));
    if (params_.publish_truth_map_to_odom || params_.publish_start_map_to_odom) {
      spott_map::Pose2 map_odom = spott_map::MapToOdom(sim_->GroundTruth(robot_), odo.pose());
      if (params_.publish_start_map_to_odom) {  // dead reckoning: the start's, held
        if (!start_map_odom_) start_map_odom_ = map_odom;
        map_odom = *start_map_odom_;
      }
      tf_.sendTransform(ToTransform(map_odom, params_.map_frame, params_.odom_frame, stamp));
    }
    truth_pub_.publish(conv::ToOdometry(sim_->GroundTruth(robot_), sim_->Velocity(robot_),
                                        params_.map_frame, params_.base_frame, stamp));
    sensor_msgs::JointState js;
    js.header.stamp = stamp;
    const RobotSpec& spec = sim_->spec(robot_);
    for (const std::string& j : spec.movable_joints) {
      double position = j == spec.turret_joint ? sim_->turret_yaw(robot_) : 0.0;
      for (std::size_t i = 0; i < spec.profilers.size(); ++i) {
        const auto [pan, tilt] = sim_->Head(robot_, static_cast<int>(i));
        if (j == spec.profilers[i].pan_joint) position = pan;
        if (j == spec.profilers[i].tilt_joint) position = tilt;
      }
      js.name.push_back(j);
      js.position.push_back(position);
    }
    joints_pub_.publish(js);
  }

  void PublishSensors(const ros::Time& stamp) {
    const RobotSpec& spec = sim_->spec(robot_);
    for (std::size_t r = 0; r < spec.rings.size(); ++r) {
      const RangeRingSpec& ring = spec.rings[r];
      const std::vector<double> ranges = sim_->SenseRing(robot_, ring, rng_);
      ring_pubs_[r].publish(
          conv::ToRangeRing(ring, ranges, params_.base_frame, stamp, sim_->turret_yaw(robot_)));
      if (range_pubs_[r].getNumSubscribers() > 0) {
        for (std::size_t i = 0; i < ranges.size(); ++i) {
          range_pubs_[r].publish(conv::ToRange(ring, i, ranges[i], stamp));
        }
      }
    }
    // The body's contacts as the ground truth knows them, for every robot (evaluation only).
    const BumperSpec sectors{kContactSectors, Simulator::kBodyTouchM};
    contact_pub_.publish(conv::ToBumperRing(
        sectors, BumperSegments(sectors, sim_->BodyContacts(robot_)), params_.base_frame, stamp));
    if (spec.bumper) {
      const std::vector<bool> pressed = sim_->Bumper(robot_);
      bumper_pub_.publish(conv::ToBumperRing(*spec.bumper, pressed, params_.base_frame, stamp));
      if (pressed != last_pressed_) {  // on change: rviz keeps the last
        last_pressed_ = pressed;
        bumper_markers_pub_.publish(
            conv::ToBumperMarkers(*spec.bumper, spec.radius_m, pressed, params_.base_frame, stamp));
      }
    }
  }

  void PublishLaser(const ros::Time& stamp, double period) {
    const RobotSpec& spec = sim_->spec(robot_);
    if (!spec.laser) return;
    scan_pub_.publish(
        conv::ToLaserScan(*spec.laser, sim_->SenseLaser(robot_, rng_), period, stamp));
  }

  void PublishProfiles(const ros::Time& stamp) {
    const RobotSpec& spec = sim_->spec(robot_);
    for (std::size_t i = 0; i < spec.profilers.size(); ++i) {
      const auto [pan, tilt] = sim_->Head(robot_, static_cast<int>(i));
      for (const bool horizontal : {true, false}) {
        std::vector<double> angles;
        const std::vector<double> ranges =
            sim_->SenseProfile(robot_, static_cast<int>(i), horizontal, rng_, &angles);
        profile_pub_.publish(
            conv::ToRangeProfile(spec.profilers[i], horizontal, pan, tilt, angles, ranges, stamp));
      }
    }
  }

  // Joint positions for the heads' pan and tilt joints (names from the URDF).
  void OnPointHead(const sensor_msgs::JointState& msg) {
    const RobotSpec& spec = sim_->spec(robot_);
    if (msg.position.size() != msg.name.size()) {
      ROS_WARN_THROTTLE(1.0, "robot_sim: point_head: %zu names but %zu positions", msg.name.size(),
                        msg.position.size());
      return;
    }
    for (std::size_t k = 0; k < msg.name.size(); ++k) {
      bool known = false;
      for (std::size_t i = 0; i < spec.profilers.size(); ++i) {
        auto [pan, tilt] = sim_->Head(robot_, static_cast<int>(i));
        if (msg.name[k] == spec.profilers[i].pan_joint) {
          pan = msg.position[k];
        } else if (msg.name[k] == spec.profilers[i].tilt_joint) {
          tilt = msg.position[k];
        } else {
          continue;
        }
        known = true;
        if (!sim_->PointHead(robot_, static_cast<int>(i), pan, tilt)) {
          ROS_WARN_THROTTLE(1.0,
                            "robot_sim: point_head: refused %s = %f (not finite, or tilt "
                            "beyond +-pi/2)",
                            msg.name[k].c_str(), msg.position[k]);
        }
      }
      if (!known) {
        ROS_WARN_THROTTLE(1.0, "robot_sim: point_head: no pan or tilt joint '%s'",
                          msg.name[k].c_str());
      }
    }
  }

  void RunSchedule(double now_s) {
    // Doors and obstacles that waited for a robot to clear the place, first.
    for (auto it = waiting_.begin(); it != waiting_.end();) {
      std::string error;
      bool blocked = false;
      if (!ApplyFaultEvent(*sim_, robot_, *it, &error, &blocked) && blocked) {
        ++it;
        continue;
      }
      const std::string what = Describe(*it);
      ROS_INFO("robot_sim: scheduled fault at %.2f s (line %d) applied %.2f s late (%s): %s",
               it->time, it->where.line, now_s - it->time,
               error.empty() ? "the place is clear" : error.c_str(), what.c_str());
      PublishFault(now_s, *it, what, error);
      it = waiting_.erase(it);
    }
    while (next_event_ < schedule_.size() && schedule_[next_event_].time <= now_s) {
      const FaultEvent& e = schedule_[next_event_++];
      std::string error;
      bool blocked = false;
      const bool applied = ApplyFaultEvent(*sim_, robot_, e, &error, &blocked);
      const std::string what = Describe(e);
      if (blocked) {  // as a person closing a door waits for the robot to pass
        ROS_INFO("robot_sim: scheduled fault at %.2f s (line %d) waits: %s: %s", e.time,
                 e.where.line, what.c_str(), error.c_str());
        waiting_.push_back(e);
      } else if (applied) {
        ROS_INFO("robot_sim: scheduled fault at %.2f s (line %d) applied: %s", e.time, e.where.line,
                 what.c_str());
      } else {
        ROS_ERROR("robot_sim: scheduled fault at %.2f s (line %d) refused: %s: %s", e.time,
                  e.where.line, what.c_str(), error.c_str());
      }
      if (!blocked) PublishFault(now_s, e, what, applied ? "" : error);
    }
  }

  // /sim/faults: each scheduled fault as it happens (for reports and bags), one status each.
  void PublishFault(double now_s, const FaultEvent& e, const std::string& what,
                    const std::string& refusal) {
    diagnostic_msgs::DiagnosticArray array;
    array.header.stamp = ros::Time(now_s);
    diagnostic_msgs::DiagnosticStatus status;
    status.name = "robot_sim: fault";
    status.hardware_id = KindName(e.kind);
    status.level = refusal.empty() ? diagnostic_msgs::DiagnosticStatus::OK
                                   : diagnostic_msgs::DiagnosticStatus::ERROR;
    status.message = refusal.empty() ? what : what + ": refused: " + refusal;
    auto value = [&](const std::string& key, const std::string& v) {
      diagnostic_msgs::KeyValue kv;
      kv.key = key;
      kv.value = v;
      status.values.push_back(kv);
    };
    value("scheduled_s", std::to_string(e.time));
    value("line", std::to_string(e.where.line));
    array.status.push_back(status);
    faults_pub_.publish(array);
  }

  void OnCmdVel(const geometry_msgs::Twist& msg) {
    std::string error;
    if (!sim_->SetCommand(robot_, conv::FromMsg(msg), &error)) {
      ROS_WARN_THROTTLE(1.0, "robot_sim: %s", error.c_str());
      have_command_ = false;
      return;
    }
    have_command_ = true;
    last_command_s_ = sim_->time();
  }

  void OnTurret(const std_msgs::Float64& msg) {
    if (!std::isfinite(msg.data)) {
      ROS_WARN_THROTTLE(1.0, "robot_sim: refused a turret angle that is not finite");
      return;
    }
    if (sim_->spec(robot_).turret_joint.empty()) {
      ROS_WARN_THROTTLE(1.0, "robot_sim: %s has no turret", sim_->spec(robot_).name.c_str());
      return;
    }
    sim_->SetTurretYaw(robot_, msg.data);
  }

  template <typename Request, typename Response>
  bool Apply(const Request& req, Response& res, const char* what) {
    FaultEvent e;
    std::string error;
    res.success = conv::FromRequest(req, e, &error) && ApplyFaultEvent(*sim_, robot_, e, &error);
    res.message = res.success ? std::string(what) + ": done" : error;
    if (!res.success) ROS_WARN("robot_sim: %s refused: %s", what, error.c_str());
    return true;
  }

  bool OnKidnap(spott_msgs::Kidnap::Request& req, spott_msgs::Kidnap::Response& res) {
    return Apply(req, res, "kidnap");
  }
  bool OnDoor(spott_msgs::SetDoorState::Request& req, spott_msgs::SetDoorState::Response& res) {
    return Apply(req, res, "set_door_state");
  }
  bool OnSensorFault(spott_msgs::SensorFault::Request& req,
                     spott_msgs::SensorFault::Response& res) {
    return Apply(req, res, "sensor_fault");
  }
  bool OnSlip(spott_msgs::OdometrySlip::Request& req, spott_msgs::OdometrySlip::Response& res) {
    return Apply(req, res, "odometry_slip");
  }
  bool OnAddObstacle(spott_msgs::AddObstacle::Request& req,
                     spott_msgs::AddObstacle::Response& res) {
    if (req.id.empty()) req.id = "obstacle_" + std::to_string(++obstacle_counter_);
    Apply(req, res, "add_obstacle");
    res.id = res.success ? req.id : "";
    return true;
  }
  bool OnRemoveObstacle(spott_msgs::RemoveObstacle::Request& req,
                        spott_msgs::RemoveObstacle::Response& res) {
    std::string error;
    res.success = sim_->world().RemoveObstacle(req.id, &error);
    res.message = res.success ? "removed" : error;
    return true;
  }
  // A new world file; on any error (file, line, column) the old world and the robot stay.
  bool OnLoadWorld(spott_msgs::LoadWorld::Request& req, spott_msgs::LoadWorld::Response& res) {
    const auto loaded = spott_map::LoadWorldFile(req.path);
    for (const auto& e : loaded.errors) res.errors.push_back(e.ToString());
    std::string error;
    res.success = loaded.ok() && sim_->ReplaceWorld(*loaded.world, &error);
    if (!error.empty()) res.errors.push_back(req.path + ": " + error);
    if (res.success) {
      ROS_INFO("robot_sim: loaded world '%s' from %s", loaded.world->name.c_str(),
               req.path.c_str());
    } else {
      ROS_WARN("robot_sim: load_world %s refused; keeping the current world", req.path.c_str());
    }
    return true;
  }

  bool OnSaveOctomap(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
    res.success = sim_->world().WriteOctomap(params_.octomap_file);
    res.message = (res.success ? "wrote " : "cannot write ") + params_.octomap_file;
    return true;
  }

  SimNodeParameters params_;
  std::unique_ptr<Simulator> sim_;
  int robot_;
  std::vector<FaultEvent> schedule_;
  std::optional<spott_map::Pose2> start_map_odom_;  ///< publish_start_map_to_odom's, once known.
  ros::Publisher faults_pub_;
  std::size_t next_event_ = 0;
  std::vector<FaultEvent> waiting_;  ///< Scheduled, blocked by a robot standing there.
  Rng rng_;
  bool have_command_ = false;
  double last_command_s_ = 0.0;
  int markers_revision_ = -1;
  int obstacle_counter_ = 0;
  std::vector<bool> last_pressed_;           ///< The bumper markers are published on change.
  static constexpr int kContactSectors = 8;  ///< /sim/contact's resolution (45 degrees)
  ros::Publisher clock_pub_, odom_pub_, truth_pub_, joints_pub_, scan_pub_, bumper_pub_,
      bumper_markers_pub_, markers_pub_, profile_pub_, contact_pub_;
  std::vector<ros::Publisher> ring_pubs_, range_pubs_;
  ros::Subscriber cmd_sub_, turret_sub_, head_sub_;
  ConsumerPacer pacer_;
  std::vector<ros::Subscriber> consumer_subs_;
  ros::Publisher rtf_pub_;
  Battery battery_;
  ros::Publisher battery_pub_;
  std::vector<ros::ServiceServer> services_;
  tf2_ros::TransformBroadcaster tf_;
};

int Main(int argc, char** argv) {
  ros::init(argc, argv, "robot_sim");
  ros::NodeHandle nh, pnh("~");
  auto read =
      spott_ros::ReadNodeParameters<SimNodeParameters>(pnh, "robot_sim", ros_parameters::Read);
  if (!read) return 1;
  SimNodeParameters params = *read;
  const std::string pkg = ros::package::getPath("robot_sim");
  if (params.robot_file.empty())
    params.robot_file = pkg + "/config/robots/" + params.robot + ".yaml";
  if (params.urdf_file.empty()) params.urdf_file = pkg + "/urdf/" + params.robot + ".urdf";

  const auto spec = LoadRobotSpec(params.robot_file, params.urdf_file);
  if (!spec.ok()) {
    ROS_FATAL("robot_sim: robot '%s':\n%s", params.robot.c_str(),
              spott_map::FormatErrors(spec.errors).c_str());
    return 1;
  }
  const auto world = spott_map::LoadWorldFile(params.world_file);
  if (!world.ok()) {
    ROS_FATAL("robot_sim: world:\n%s", spott_map::FormatErrors(world.errors).c_str());
    return 1;
  }
  const auto schedule = ParseFaultSchedule(ros_parameters::FaultScheduleYaml(pnh), "~faults");
  if (!schedule.ok()) {
    ROS_FATAL("robot_sim: parameter faults:\n%s", spott_map::FormatErrors(schedule.errors).c_str());
    return 1;
  }
  spott_map::Pose2 start = world.world->robot_start;
  if (!params.start_pose.empty()) {
    std::string why;
    const auto pose = spott_map::ParsePoseText(params.start_pose, &why);
    if (!pose) {
      ROS_FATAL("robot_sim: parameter start_pose: %s", why.c_str());
      return 1;
    }
    start = *pose;
  }
  auto sim_world = std::make_unique<SimWorld>(params.world);
  sim_world->Build(*world.world);
  auto sim = std::make_unique<Simulator>(std::move(sim_world));
  std::string error;
  const auto robot = sim->AddRobot(*spec.spec, start, params.odometry, &error);
  if (!robot) {
    ROS_FATAL("robot_sim: %s", error.c_str());
    return 1;
  }
  ROS_INFO(
      "robot_sim: %s in world '%s' (%zu solids, OctoMap %zu nodes at %.2f m), start (%.2f, "
      "%.2f, %.2f), real-time factor %s",
      spec.spec->name.c_str(), world.world->name.c_str(), sim->world().solid_count(),
      sim->world().octree().size(), params.world.octomap_resolution_m, start.x, start.y, start.yaw,
      params.real_time_factor > 0 ? std::to_string(params.real_time_factor).c_str()
                                  : "as fast as possible");
  SimNode node(nh, pnh, params, std::move(sim), *robot, schedule.events);
  node.Run();
  return 0;
}

}  // namespace
}  // namespace robot_sim

int main(int argc, char** argv) { return robot_sim::Main(argc, argv); }
