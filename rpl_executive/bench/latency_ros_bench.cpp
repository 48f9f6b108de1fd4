// The executives' latencies through ROS (issues 17 and 18): the rpl_executive node (its YAML),
// cmd_vel_arbiter and world_server (bonn_department: the room/door graph the RPL navigation plans
// need) run as child processes under a private master; this program is the rest of the robot.
//
// BM_LowCertaintyToNavigateCancel (issue 17): the office delivery plan runs; this program serves
// the Navigate action and ActiveLocalize, and publishes /localization_status. With a Navigate goal
// active it publishes one status with certainty 0.5 and times the goal's cancel request: the
// policy WHENEVER (<= POS-CERTAINTY* 0.8) wakes, ACTIVATE-ACTIVE-LOCALIZATION deletes the target
// points (the NAVIGATION module cancels its goal). Then the ActiveLocalize goal succeeds with the
// certainty back at 0.95, the policy releases, and the loop's next navigation plan sends the next
// Navigate goal: the next iteration.
//
// BM_SonarToReflexStopOnCmdVel (issue 18): a Noreils-Chatila mission smooth-moves along a path
// under a monitor (S_us-threshold) whose reflex is (stop). This program holds the robot still
// (static tf), so the Pilot keeps commanding forward; it publishes one sonar ring with every echo
// at 0.2 m and times the first still /cmd_vel from the arbiter: /sonar -> the executive's
// surveillance manager (reflex) -> /cmd_vel/executive -> arbiter -> /cmd_vel. The control action
// FAILs the mission; the next iteration starts it again (untimed).
//
// Peers, in the same run, as child processes of this program (--peer=...), each the same path
// without our executive:
// - polling (issue 17's peer, PyCRAM's Monitor design): a node that reads /localization_status
//   and, every 0.1 s, cancels its Navigate goal when the certainty is at or below 0.8;
// - reflex (the floor of any ROS reflex): a node that publishes a still /cmd_vel/executive on
//   the sonar message with an echo under 0.4 m, nothing else in between.
// They are started after our benchmarks (they would send goals and wheel commands of their own).
//
// Counters: p50_us / p99_us (targets: a median under 2 ms for the reflex, issue 18).
#include <actionlib/client/simple_action_client.h>
#include <actionlib/server/action_server.h>
#include <benchmark/benchmark.h>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/Twist.h>
#include <ros/ros.h>
#include <spott_msgs/ActiveLocalizeAction.h>
#include <spott_msgs/LocalizationStatus.h>
#include <spott_msgs/MissionAction.h>
#include <spott_msgs/NavigateAction.h>
#include <spott_msgs/RangeRing.h>
#include <std_srvs/Empty.h>
#include <tf2_ros/static_transform_broadcaster.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <fstream>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "spott_ros/testing/private_master.h"
#include "spott_ros/testing/ros_benchmark.h"

namespace {

spott_ros::testing::PrivateMaster* g_master = nullptr;

using Clock = std::chrono::steady_clock;
using MissionClient = actionlib::SimpleActionClient<spott_msgs::MissionAction>;

double Seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

// Three warm-up rounds (connections, the first plan), then one timed round per iteration.
// `once(timeout_s)` gives the latency (s), -1 when the trigger's precondition never came, -2
// when the answer did not; `why(code)` says which. False after an error.
bool Measure(benchmark::State& state, const std::function<double(double)>& once,
             const std::function<const char*(double)>& why) {
  for (int i = 0; i < 3; ++i) {
    const double s = once(20.0);
    if (s < 0) {
      state.SkipWithError(why(s));
      return false;
    }
  }
  std::vector<double> samples;
  for (auto _ : state) {
    const double s = once(10.0);
    if (s < 0) {
      state.SkipWithError(why(s));
      return false;
    }
    samples.push_back(s);
    state.SetIterationTime(s);
  }
  spott_ros::testing::RecordPercentiles(state, samples);
  return true;
}

// Waits on `cv` under `lock` until `done` or `timeout_s` passes.
template <typename Pred>
bool WaitFor(std::condition_variable& cv, std::unique_lock<std::mutex>& lock, double timeout_s,
             Pred done) {
  return cv.wait_for(lock, std::chrono::duration<double>(timeout_s), done);
}

// ---- issue 17: the localization, Navigate and ActiveLocalize as seen by the executive ---------

class OfficeRobot {
 public:
  explicit OfficeRobot(ros::NodeHandle& nh)
      : navigate_(
            nh, "harmonic_planner/navigate",
            [this](NavigateServer::GoalHandle g) { OnNavigateGoal(g); },
            [this](NavigateServer::GoalHandle g) { OnNavigateCancel(g); }, false),
        active_(
            nh, "active_localize", [this](ActiveServer::GoalHandle g) { OnActiveGoal(g); },
            [](ActiveServer::GoalHandle g) { g.setCanceled(); }, false) {
    status_pub_ = nh.advertise<spott_msgs::LocalizationStatus>("localization_status", 5);
    global_ = nh.advertiseService("global_localization", &OfficeRobot::OnGlobal, this);
    navigate_.start();
    active_.start();
    // The tracker's regular status (POSITION-TRACKING needs one within 3 s).
    timer_ = nh.createWallTimer(ros::WallDuration(0.2), [this](const ros::WallTimerEvent&) {
      std::lock_guard<std::mutex> lock(mutex_);
      PublishLocked();
    });
  }

  bool Connected() const { return status_pub_.getNumSubscribers() > 0; }

  // Waits for an active Navigate goal; then seconds from the low-certainty status to its cancel
  // request, or < 0. `restore`: the certainty is back at 0.95 after the cancel (the peer asks for
  // no active localization, which does that for the executive).
  double Once(double timeout_s, bool restore = false) {
    std::unique_lock<std::mutex> lock(mutex_);
    if (!WaitFor(cv_, lock, timeout_s, [this] { return navigate_active_; })) return -1.0;
    // At a random phase of any polling period (a goal may come just after a peer's poll).
    lock.unlock();
    ros::WallDuration(std::uniform_real_distribution<double>(0.0, 0.1)(rng_)).sleep();
    lock.lock();
    if (!navigate_active_) return -1.0;
    cancelled_.reset();
    certainty_ = 0.5;
    const Clock::time_point start = Clock::now();
    PublishLocked();
    if (!WaitFor(cv_, lock, 2.0, [this] { return cancelled_.has_value(); })) return -2.0;
    if (restore) {
      certainty_ = 0.95;
      PublishLocked();
    }
    return Seconds(start, *cancelled_);
  }

 private:
  using NavigateServer = actionlib::ActionServer<spott_msgs::NavigateAction>;
  using ActiveServer = actionlib::ActionServer<spott_msgs::ActiveLocalizeAction>;

  void PublishLocked() {
    spott_msgs::LocalizationStatus s;
    s.header.stamp = ros::Time::now();
    s.header.frame_id = "map";
    s.mode = spott_msgs::LocalizationStatus::TRACKING;
    s.certainty = certainty_;
    s.lost = certainty_ <= 0.8;
    s.num_modes = 1;
    s.estimate.x = 25.5;  // bonn_department's start: the east end of the hallway
    s.estimate.y = 10.0;
    s.estimate.theta = -1.78;
    status_pub_.publish(s);
  }

  void OnNavigateGoal(NavigateServer::GoalHandle g) {
    g.setAccepted();
    std::lock_guard<std::mutex> lock(mutex_);
    goal_ = g;
    navigate_active_ = true;  // it never arrives: the robot stands still
    cv_.notify_all();
  }
  void OnNavigateCancel(NavigateServer::GoalHandle g) {
    const Clock::time_point now = Clock::now();
    g.setCanceled();
    std::lock_guard<std::mutex> lock(mutex_);
    navigate_active_ = false;
    if (!cancelled_) cancelled_ = now;
    cv_.notify_all();
  }
  void OnActiveGoal(ActiveServer::GoalHandle g) {
    g.setAccepted();
    {
      std::lock_guard<std::mutex> lock(mutex_);
      certainty_ = 0.95;  // relocalized where the robot stands
      PublishLocked();
    }
    spott_msgs::ActiveLocalizeResult r;
    r.success = true;
    r.certainty = 0.95;
    r.estimate.x = 25.5;
    r.estimate.y = 10.0;
    r.estimate.theta = -1.78;
    g.setSucceeded(r);
  }
  bool OnGlobal(std_srvs::Empty::Request&, std_srvs::Empty::Response&) { return true; }

  NavigateServer navigate_;
  ActiveServer active_;
  ros::Publisher status_pub_;
  ros::ServiceServer global_;
  ros::WallTimer timer_;
  std::mutex mutex_;
  std::condition_variable cv_;
  double certainty_ = 0.95;
  bool navigate_active_ = false;
  std::optional<Clock::time_point> cancelled_;
  NavigateServer::GoalHandle goal_;
  std::mt19937 rng_{17};
};

void StartMission(MissionClient& client, uint8_t language, const std::string& name,
                  const std::string& text) {
  spott_msgs::MissionGoal goal;
  goal.language = language;
  goal.name = name;
  goal.text = text;
  goal.source_name = "latency_ros_bench";
  client.sendGoal(goal);
}

// The /mission server is up and the probe's topics are connected (`connected`), then a second
// for the latched maps and the first data to arrive. False (the benchmark skipped) without it.
bool WaitForExecutive(benchmark::State& state, MissionClient& mission,
                      const std::function<bool()>& connected) {
  if (!mission.waitForServer(ros::Duration(30.0))) {
    state.SkipWithError("no /mission server");
    return false;
  }
  const Clock::time_point deadline = Clock::now() + std::chrono::seconds(30);
  while (!connected() && Clock::now() < deadline) ros::WallDuration(0.1).sleep();
  ros::WallDuration(1.0).sleep();
  return true;
}

void BM_LowCertaintyToNavigateCancel(benchmark::State& state) {
  ros::NodeHandle nh;
  OfficeRobot robot(nh);
  MissionClient mission("mission", true);
  if (!WaitForExecutive(state, mission, [&] { return robot.Connected(); })) return;
  StartMission(mission, spott_msgs::MissionGoal::RPL, "office_delivery", "");
  Measure(
      state, [&](double timeout_s) { return robot.Once(timeout_s); },
      [](double code) {
        return code < -1.5 ? "the Navigate goal was not cancelled within 2 s"
                           : "no (new) Navigate goal from the plan";
      });
  mission.cancelGoal();
  mission.waitForResult(ros::Duration(5.0));
}

void BM_LowCertaintyToNavigateCancel_PollingPeer(benchmark::State& state) {
  ros::NodeHandle nh;
  OfficeRobot robot(nh);
  g_master->Spawn({"/proc/self/exe", "--peer=polling", "__name:=polling_peer"});
  Measure(
      state, [&](double timeout_s) { return robot.Once(timeout_s, true); },
      [](double) { return "the polling peer sent no goal or did not cancel it"; });
}

// ---- issue 18: the sonar belt and the wheels as seen by the Noreils-Chatila executive ---------

// Smooth-move east along the hallway's line; any echo nearer than 40-50 cm on the front sonars
// stops the robot (the reflex) and FAILs the mission (the control action).
const char* kReflexMission = R"((define Tpath PATH ((2700 1000)(2900 1000)))
(define Tclist[4] sensors-list ((1 40)(2 50)(3 50)(4 40)))
(MISSION reflex_latency
(PRE: (eq motor ON))
(MAIN:
  (smooth-move(PATH)
    MNTR(S_us-threshold sensors-list) => ((stop)){(FAIL)}
  )
)
)
)";

class HilareBelt {
 public:
  explicit HilareBelt(ros::NodeHandle& nh) {
    sonar_pub_ = nh.advertise<spott_msgs::RangeRing>("sonar", 5);
    cmd_sub_ = nh.subscribe<geometry_msgs::Twist>(
        "cmd_vel", 20, [this](const geometry_msgs::Twist::ConstPtr& t) { OnCmd(*t); },
        ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay());
    // The belt's regular readings: nothing within 3 m.
    timer_ = nh.createWallTimer(ros::WallDuration(0.1), [this](const ros::WallTimerEvent&) {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!obstacle_) Publish(3.0);
    });
  }
  bool Connected() const {
    return sonar_pub_.getNumSubscribers() > 0 && cmd_sub_.getNumPublishers() > 0;
  }

  // Waits until the robot is commanded forward, then seconds from the close echoes to the first
  // still /cmd_vel, or < 0.
  double Once(double timeout_s) {
    std::unique_lock<std::mutex> lock(mutex_);
    obstacle_ = false;
    if (!WaitFor(cv_, lock, timeout_s, [this] { return moving_; })) return -1.0;
    obstacle_ = true;
    stopped_.reset();
    const Clock::time_point start = Clock::now();
    Publish(0.2);
    if (!WaitFor(cv_, lock, 2.0, [this] { return stopped_.has_value(); })) return -2.0;
    return Seconds(start, *stopped_);
  }

 private:
  void Publish(double range_m) {
    spott_msgs::RangeRing ring;
    ring.header.stamp = ros::Time::now();
    ring.header.frame_id = "base_link";
    ring.radiation_type = spott_msgs::RangeRing::ULTRASOUND;
    ring.field_of_view = 0.52;  // robot_sim/config/robots/hilare.yaml
    ring.min_range = 0.15;
    ring.max_range = 4.0;
    for (int i = 0; i < 16; ++i) {  // sensor 1 ahead, counter-clockwise, on a 0.4 m belt
      geometry_msgs::Pose2D m;
      m.theta = i * 2.0 * M_PI / 16.0;
      m.x = 0.4 * std::cos(m.theta);
      m.y = 0.4 * std::sin(m.theta);
      ring.mounts.push_back(m);
      ring.frame_ids.push_back("sonar_" + std::to_string(i + 1));
      ring.ranges.push_back(static_cast<float>(range_m));
    }
    sonar_pub_.publish(ring);
  }
  void OnCmd(const geometry_msgs::Twist& t) {
    const Clock::time_point now = Clock::now();
    std::lock_guard<std::mutex> lock(mutex_);
    const bool still = t.linear.x == 0.0 && t.angular.z == 0.0;
    moving_ = !still;
    if (still && obstacle_ && !stopped_) stopped_ = now;
    cv_.notify_all();
  }

  ros::Publisher sonar_pub_;
  ros::Subscriber cmd_sub_;
  ros::WallTimer timer_;
  std::mutex mutex_;
  std::condition_variable cv_;
  bool obstacle_ = false, moving_ = false;
  std::optional<Clock::time_point> stopped_;
};

void BM_SonarToReflexStopOnCmdVel(benchmark::State& state) {
  ros::NodeHandle nh;
  HilareBelt belt(nh);
  MissionClient mission("mission", true);
  if (!WaitForExecutive(state, mission, [&] { return belt.Connected(); })) return;
  bool sent = false;
  auto once = [&](double timeout_s) {
    if (sent) mission.waitForResult(ros::Duration(5.0));  // the previous run's FAIL
    sent = true;
    StartMission(mission, spott_msgs::MissionGoal::NOREILS_CHATILA, "", kReflexMission);
    return belt.Once(timeout_s);
  };
  Measure(state, once, [](double code) {
    return code < -1.5 ? "no still /cmd_vel within 2 s of the close echoes"
                       : "the mission did not move the robot";
  });
  mission.cancelGoal();
  mission.waitForResult(ros::Duration(5.0));
}

void BM_SonarToReflexStopOnCmdVel_ReflexPeer(benchmark::State& state) {
  ros::NodeHandle nh;
  HilareBelt belt(nh);
  g_master->Spawn({"/proc/self/exe", "--peer=reflex", "__name:=reflex_peer"});
  Measure(
      state, [&](double timeout_s) { return belt.Once(timeout_s); },
      [](double) { return "the reflex peer did not drive, or did not stop"; });
}

// Registration order is run order: the peers come after our benchmarks.
BENCHMARK(BM_LowCertaintyToNavigateCancel)->UseManualTime()->Iterations(100);
BENCHMARK(BM_SonarToReflexStopOnCmdVel)->UseManualTime()->Iterations(100);
BENCHMARK(BM_LowCertaintyToNavigateCancel_PollingPeer)->UseManualTime()->Iterations(100);
BENCHMARK(BM_SonarToReflexStopOnCmdVel_ReflexPeer)->UseManualTime()->Iterations(100);

// ---- the peers, run as child processes -------------------------------------------------------

// PyCRAM's Monitor: a condition tested every 0.1 s, here on the latest /localization_status.
int RunPollingPeer() {
  ros::NodeHandle nh;
  std::mutex mutex;
  double certainty = 0.0;
  ros::Subscriber sub = nh.subscribe<spott_msgs::LocalizationStatus>(
      "localization_status", 5, [&](const spott_msgs::LocalizationStatus::ConstPtr& s) {
        std::lock_guard<std::mutex> lock(mutex);
        certainty = s->certainty;
      });
  actionlib::SimpleActionClient<spott_msgs::NavigateAction> navigate("harmonic_planner/navigate",
                                                                     true);
  bool active = false;
  ros::WallTimer poll = nh.createWallTimer(ros::WallDuration(0.1), [&](const ros::WallTimerEvent&) {
    double c;
    {
      std::lock_guard<std::mutex> lock(mutex);
      c = certainty;
    }
    if (!navigate.isServerConnected()) return;
    if (active && c <= 0.8) {
      navigate.cancelGoal();
      active = false;
    } else if (!active && c > 0.8) {
      spott_msgs::NavigateGoal g;
      g.target.header.frame_id = "map";
      g.target.pose.position.x = 19.6;
      g.target.pose.position.y = 6.0;
      g.target.pose.orientation.w = 1.0;
      g.ignore_heading = true;
      g.position_tolerance = 0.3;
      navigate.sendGoal(g);
      active = true;
    }
  });
  ros::spin();
  return 0;
}

// The floor of a reflex through ROS: the sonar message in, a still command out, nothing between.
int RunReflexPeer() {
  ros::NodeHandle nh;
  ros::Publisher cmd = nh.advertise<geometry_msgs::Twist>("cmd_vel/executive", 5);
  std::mutex mutex;
  geometry_msgs::Twist last;
  ros::Subscriber sub = nh.subscribe<spott_msgs::RangeRing>(
      "sonar", 5,
      [&](const spott_msgs::RangeRing::ConstPtr& ring) {
        geometry_msgs::Twist t;
        t.linear.x = 0.3;
        for (float r : ring->ranges) {
          if (r < 0.4f) t.linear.x = 0.0;
        }
        std::lock_guard<std::mutex> lock(mutex);
        last = t;
        cmd.publish(t);
      },
      ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay());
  ros::WallTimer keep =
      nh.createWallTimer(ros::WallDuration(0.05), [&](const ros::WallTimerEvent&) {
        std::lock_guard<std::mutex> lock(mutex);
        cmd.publish(last);
      });
  ros::spin();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]).rfind("--peer=", 0) == 0) {
    const std::string peer = std::string(argv[1]).substr(7);
    ros::init(argc, argv, peer + "_peer", ros::init_options::NoSigintHandler);
    if (peer == "polling") return RunPollingPeer();
    if (peer == "reflex") return RunReflexPeer();
    std::fprintf(stderr, "latency_ros_bench: unknown peer %s\n", peer.c_str());
    return 2;
  }
  // The nodes' INFO lines would bury the table: warnings and errors only, for every child too.
  const std::string console = "/tmp/latency_ros_bench_rosconsole.config";
  std::ofstream(console) << "log4j.logger.ros=WARN\n";
  setenv("ROSCONSOLE_CONFIG_FILE", console.c_str(), 1);
  spott_ros::testing::PrivateMaster master;
  g_master = &master;
  int ros_argc = 1;
  ros::init(ros_argc, argv, "latency_ros_bench", ros::init_options::NoSigintHandler);
  if (!spott_ros::testing::PrivateMaster::WaitForMaster(10.0)) {
    std::fprintf(stderr, "latency_ros_bench: the private rosmaster did not start\n");
    return 1;
  }
  using spott_ros::testing::PrivateMaster;
  ros::param::set("/robot_description",
                  spott_ros::testing::ReadTextFile(ROBOT_SIM_DIR "/urdf/hilare.urdf"));
  if (!PrivateMaster::Run(
          {"rosparam", "load", PACKAGE_DIR "/config/rpl_executive.yaml", "/rpl_executive"}) ||
      !PrivateMaster::Run({"rosparam", "load", ARBITER_YAML, "/cmd_vel_arbiter"}) ||
      !PrivateMaster::Run({"rosparam", "load", WORLD_SERVER_YAML, "/world_server"})) {
    std::fprintf(stderr, "latency_ros_bench: rosparam load failed\n");
    return 1;
  }
  ros::param::set("/world_server/world_file", std::string(WORLDS_DIR "/bonn_department.yaml"));
  // The robot stands still: map -> odom -> base_link (the executive's pose, both sources).
  tf2_ros::StaticTransformBroadcaster tf;
  geometry_msgs::TransformStamped map_odom, odom_base;
  map_odom.header.stamp = odom_base.header.stamp = ros::Time::now();
  map_odom.header.frame_id = "map";
  map_odom.child_frame_id = odom_base.header.frame_id = "odom";
  odom_base.child_frame_id = "base_link";
  map_odom.transform.rotation.w = 1.0;
  odom_base.transform.translation.x = 27.0;
  odom_base.transform.translation.y = 10.0;
  odom_base.transform.rotation.w = 1.0;
  tf.sendTransform({map_odom, odom_base});
  master.Spawn({WORLD_SERVER_EXE, "__name:=world_server"});
  master.Spawn({ARBITER_EXE, "__name:=cmd_vel_arbiter"});
  master.Spawn({NODE_EXE, "__name:=rpl_executive"});
  return spott_ros::testing::RunBenchmarksSpinning(argc, argv);
}
