#include "demo_navigation.h"

#include "leg_messages.h"

#include <actionlib/client/simple_action_client.h>
#include <nav_msgs/Odometry.h>
#include <ros/callback_queue.h>
#include <ros/spinner.h>
#include <spott_msgs/ActiveLocalizeAction.h>
#include <spott_msgs/BumperRing.h>
#include <spott_msgs/GlobalPath.h>
#include <spott_msgs/LocalizationStatus.h>
#include <spott_msgs/MissionAction.h>
#include <spott_msgs/NavigateAction.h>
#include <spott_msgs/TaskAction.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <functional>
#include <iomanip>
#include <limits>
#include <mutex>
#include <optional>
#include <sstream>

#include "spott_map/geometry.h"
#include "spott_map/map_feature.h"
#include "spott_move_base/conversions.h"
#include "spott_ros/goal_resend.h"
#include "spott_ros/pose_conversions.h"
#include "spott_ros/robot_pose.h"
#include "spott_tr_plus/task_command.h"

namespace spott_launch {
namespace {

using NavigateClient = actionlib::SimpleActionClient<spott_msgs::NavigateAction>;

// What the simulator says while a leg runs (LegMetrics), filled by subscriber callbacks.
struct LegWatcher {
  std::mutex mutex;
  explicit LegWatcher(const spott_map::World& world) : metrics(world) {}
  LegMetrics metrics;
  std::string global_path;  ///< The first plan made for the current goal.
  std::string last_path;    ///< The latest plan (latched: unchanged plans are not re-sent).
  ros::Time goal_time;

  void Reset(const ros::Time& now) {
    std::lock_guard<std::mutex> lock(mutex);
    global_path.clear();
    goal_time = now;
    metrics.Reset(now.toSec());
  }
  spott_map::Pose2 Pose() {
    std::lock_guard<std::mutex> lock(mutex);
    return metrics.pose();
  }
  void OnTruth(const nav_msgs::Odometry& odom) {
    const auto& q = odom.pose.pose.orientation;
    std::lock_guard<std::mutex> lock(mutex);
    metrics.OnTruth(odom.header.stamp.toSec(), odom.pose.pose.position.x, odom.pose.pose.position.y,
                    2.0 * std::atan2(q.z, q.w));
  }
  void OnStatus(const spott_msgs::LocalizationStatus& status) {
    std::lock_guard<std::mutex> lock(mutex);
    metrics.OnStatus(status.header.stamp.toSec(), status.estimate.x, status.estimate.y,
                     status.estimate.theta, status.lost);
  }
  // The stack's belief as tf has it (map -> odom -> base_link), for stacks without a
  // localization_status (dead reckoning, the simulator's truth): never "lost".
  void OnTfEstimate(const spott_ros::RobotPose& pose) {
    std::lock_guard<std::mutex> lock(mutex);
    metrics.OnStatus(pose.stamp.toSec(), pose.pose.x, pose.pose.y, pose.pose.theta, false);
  }
  void OnBumper(const spott_msgs::BumperRing& ring) {
    std::lock_guard<std::mutex> lock(mutex);
    metrics.OnBumper(ring.header.stamp.toSec(), AnyPressed(ring));
  }
  void OnBodyContact(const spott_msgs::BumperRing& ring) {
    std::lock_guard<std::mutex> lock(mutex);
    metrics.OnBodyContact(ring.header.stamp.toSec(), AnyPressed(ring));
  }
  void OnGlobalPath(const spott_msgs::GlobalPath& path) {
    const std::string text = GlobalPathText(path);
    std::lock_guard<std::mutex> lock(mutex);
    last_path = text;
    if (global_path.empty() && path.header.stamp >= goal_time) global_path = last_path;
  }
};

// Navigate's feedback during a leg, from the action client's thread.
struct FeedbackLog {
  std::mutex mutex;
  NavigateFeedbackLog log;
  void On(const spott_msgs::NavigateFeedback& fb) {
    std::lock_guard<std::mutex> lock(mutex);
    log.On(fb);
  }
};

}  // namespace

namespace {

// Copies what the watcher measured during a leg into it.
void Measure(LegWatcher& watcher, const spott_map::Vec2& target, NavigationLeg& leg) {
  std::lock_guard<std::mutex> lock(watcher.mutex);
  if (leg.global_path.empty())
    leg.global_path = watcher.global_path.empty() ? watcher.last_path : watcher.global_path;
  watcher.metrics.Measure(target, leg);
}

// The simulator's side of a run, on a callback queue of its own so that ground truth, bumper,
// global path and localization status keep coming while the demo waits on an action. Add
// subscribers on `nh` before Start().
struct RunWatch {
  LegWatcher watcher;
  ros::CallbackQueue queue;
  ros::NodeHandle nh;
  std::vector<ros::Subscriber> subscribers;
  ros::AsyncSpinner spinner{1, &queue};

  RunWatch(ros::NodeHandle& parent, const spott_map::World& world, bool estimate_from_tf)
      : watcher(world), nh(parent) {
    nh.setCallbackQueue(&queue);
    subscribers.push_back(nh.subscribe("/sim/ground_truth", 200, &LegWatcher::OnTruth, &watcher));
    subscribers.push_back(nh.subscribe("/bumper", 10, &LegWatcher::OnBumper, &watcher));
    subscribers.push_back(nh.subscribe("/sim/contact", 10, &LegWatcher::OnBodyContact, &watcher));
    subscribers.push_back(nh.subscribe("global_path", 5, &LegWatcher::OnGlobalPath, &watcher));
    subscribers.push_back(nh.subscribe("localization_status", 20, &LegWatcher::OnStatus, &watcher));
    // No localization_status (truth, dead reckoning): sample tf at 5 Hz instead.
    if (estimate_from_tf) {
      tf = std::make_unique<tf2_ros::Buffer>();
      listener = std::make_unique<tf2_ros::TransformListener>(*tf);
      tf_timer = nh.createTimer(ros::Duration(0.2), [this](const ros::TimerEvent&) {
        try {
          watcher.OnTfEstimate(spott_ros::LookupRobotPose(*tf, {"map", "odom", "base_link"}));
        } catch (const tf2::TransformException&) {  // not yet: the next sample
        }
      });
    }
  }
  void Start() { spinner.start(); }
  std::unique_ptr<tf2_ros::Buffer> tf;
  std::unique_ptr<tf2_ros::TransformListener> listener;
  ros::Timer tf_timer;
};

// False (with why in the report) when the simulator's clock never came.
bool WaitForClock(ros::NodeHandle& nh, double connect_timeout_s, NavigationReport& report) {
  if (!ros::Time::waitForValid(ros::WallDuration(connect_timeout_s))) {
    report.skipped = "no /clock from the simulator";
    return false;
  }
  nh.param("/robot_sim/real_time_factor", report.requested_real_time_factor, 0.0);
  return true;
}

// Sends the goal (`send`) and waits until it ends or the leg's time (simulated) runs out; true
// when it ended. A goal the server never acknowledges (lost in transport) is sent again.
template <class Client>
bool SendAndWait(Client& client, const std::function<void()>& send, const ros::Time& started,
                 double leg_timeout_s) {
  spott_ros::GoalAckWatch ack;
  send();
  spott_ros::MarkGoalSent(ack);
  while (ros::ok() && (ros::Time::now() - started).toSec() < leg_timeout_s) {
    if (client.getState().isDone()) return true;
    if (spott_ros::GoalLostInTransport(ack, client, "demo", "the goal's server")) send();
    ros::WallDuration(0.05).sleep();
  }
  return false;
}

using ActiveLocalizeClient = actionlib::SimpleActionClient<spott_msgs::ActiveLocalizeAction>;

// Navigate said "not localized": what a client of a cognizant localization does (Beetz et al.
// 2.2, as rpl_executive's policy does): localize actively, within the leg's time. False when
// there is no ActiveLocalize (AMCL, dead reckoning) or no time left; its own outcome does not
// matter: the goal sent again is judged anew.
bool Relocalize(ActiveLocalizeClient& active, const ros::Time& started, double leg_timeout_s) {
  const double left_s = leg_timeout_s - (ros::Time::now() - started).toSec();
  if (left_s <= 1.0 || !active.waitForServer(ros::Duration(1.0))) return false;
  spott_msgs::ActiveLocalizeGoal goal;
  goal.timeout = left_s - 1.0;
  ROS_INFO("demo: Navigate says not localized: localizing actively (at most %.0f s)", goal.timeout);
  const bool done = SendAndWait(
      active, [&] { active.sendGoal(goal); }, started, leg_timeout_s - 1.0);
  if (!done) active.cancelGoal();
  const auto result = active.getResult();
  ROS_INFO("demo: active localization %s (certainty %.2f, %u targets)%s%s",
           result && result->success ? "succeeded" : "gave up", result ? result->certainty : 0.0,
           result ? result->targets_visited : 0u, result && !result->reason.empty() ? ": " : "",
           result ? result->reason.c_str() : "");
  return (ros::Time::now() - started).toSec() < leg_timeout_s - 1.0;
}

// When a goal's result came (simulated time), set by the client's done callback.
struct DoneTime {
  std::mutex mutex;
  std::optional<ros::Time> at;
  void Set() {
    std::lock_guard<std::mutex> lock(mutex);
    if (!at) at = ros::Time::now();
  }
  ros::Time Get() {
    std::lock_guard<std::mutex> lock(mutex);
    return at ? *at : ros::Time::now();
  }
  void Reset() {
    std::lock_guard<std::mutex> lock(mutex);
    at.reset();
  }
};

// Closes the leg's window at its result plus LegMetrics::kSettleS and waits until the messages
// stamped within it have come (as bag_report counts them from a bag). Returns the end.
ros::Time CloseLeg(LegWatcher& watcher, DoneTime& done) {
  const ros::Time end = done.Get();
  {
    std::lock_guard<std::mutex> lock(watcher.mutex);
    watcher.metrics.EndAt(end.toSec() + LegMetrics::kSettleS);
  }
  const ros::Time until = end + ros::Duration(LegMetrics::kSettleS + 0.2);
  const ros::WallTime give_up = ros::WallTime::now() + ros::WallDuration(3.0);
  while (ros::ok() && ros::Time::now() < until && ros::WallTime::now() < give_up)
    ros::WallDuration(0.02).sleep();
  return end;
}

std::string TimedOutText(double leg_timeout_s) {
  char text[64];
  std::snprintf(text, sizeof(text), "timed out after %.0f s of simulated time", leg_timeout_s);
  return text;
}

}  // namespace

std::string CompactTrace(const std::vector<std::string>& trace) {
  std::string out;
  std::string last;
  int repeats = 0;
  const auto flush = [&] {
    if (last.empty()) return;
    out += (out.empty() ? "" : ", ") + last + (repeats > 1 ? " x" + std::to_string(repeats) : "");
  };
  for (const std::string& rule : trace) {
    const std::string head = rule.substr(0, rule.find(':'));
    if (head == last) {
      ++repeats;
      continue;
    }
    flush();
    last = head;
    repeats = 1;
  }
  flush();
  return out;
}

NavigationReport RunTasks(ros::NodeHandle& nh, const spott_map::World& world,
                          const std::vector<std::string>& tasks, double leg_timeout_s,
                          double connect_timeout_s, double goal_tolerance_m,
                          bool estimate_from_tf) {
  using TaskClient = actionlib::SimpleActionClient<spott_msgs::TaskAction>;
  NavigationReport report;
  report.by_task = true;
  if (!WaitForClock(nh, connect_timeout_s, report)) return report;
  FeedbackLog log;
  RunWatch watch(nh, world, estimate_from_tf);
  LegWatcher& watcher = watch.watcher;
  if (watch.tf) report.estimate_source = "tf's map -> base_link";
  // What Navigate tells the TR+ controller (recoveries, the global path), overheard.
  watch.subscribers.push_back(watch.nh.subscribe<spott_msgs::NavigateActionFeedback>(
      "harmonic_planner/navigate/feedback", 20,
      [&log](const spott_msgs::NavigateActionFeedback::ConstPtr& m) { log.On(m->feedback); }));
  watch.Start();

  TaskClient client(nh, "task", true);
  if (!client.waitForServer(ros::Duration(connect_timeout_s))) {
    report.skipped = "/task is not offered (the TR+ controller is not running)";
    return report;
  }
  report.ran = true;
  std::vector<std::string> features_before;
  for (const std::string& command : tasks) {
    NavigationLeg leg;
    leg.task = command;
    const spott_map::Pose2 start = watcher.Pose();
    const ros::Time started = ros::Time::now();
    const ros::WallTime wall_started = ros::WallTime::now();
    leg.start_sim_s = started.toSec();
    watcher.Reset(started);
    {
      std::lock_guard<std::mutex> lock(log.mutex);
      log.log = NavigateFeedbackLog{};
    }
    spott_msgs::TaskGoal goal;
    goal.command = command;
    DoneTime done_time;
    const bool done = SendAndWait(
        client,
        [&] {
          client.sendGoal(goal,
                          [&done_time](const actionlib::SimpleClientGoalState&,
                                       const spott_msgs::TaskResultConstPtr&) { done_time.Set(); });
        },
        started, leg_timeout_s);
    leg.wall_time_s = (ros::WallTime::now() - wall_started).toSec();
    spott_msgs::TaskResultConstPtr result;
    if (done) {
      result = client.getResult();
    } else {
      client.cancelGoal();
      client.waitForResult(ros::Duration(5.0));
      result = client.getResult();
    }
    leg.sim_time_s = (CloseLeg(watcher, done_time) - started).toSec();
    bool reached_by_controller = false;
    if (result) reached_by_controller = ApplyTaskResult(*result, features_before, leg);
    if (!done) {
      leg.task_outcome = TimedOutText(leg_timeout_s);
    } else if (!result) {
      leg.task_outcome = "no result";
    }
    leg.navigate_outcome = leg.task_outcome;
    {
      std::lock_guard<std::mutex> lock(log.mutex);
      leg.recoveries = log.log.recoveries;
      leg.global_path = log.log.path_summary;
    }
    Measure(watcher, leg.target.Position(), leg);
    // The goal region of the command from where the robot really started.
    const std::string off_goal = OffTaskGoal(world, command, start, leg, goal_tolerance_m);
    leg.found_nearest_m = NearestObjectOfKind(world, leg.found_label, leg.found_at);
    JudgeLeg(reached_by_controller ? "" : "the controller says " + leg.task_outcome, off_goal, leg);
    report.legs.push_back(leg);
  }
  return report;
}

NavigationReport RunNavigation(ros::NodeHandle& nh, const spott_map::World& world,
                               const std::vector<std::string>& goals, double leg_timeout_s,
                               double connect_timeout_s, double goal_tolerance_m,
                               bool estimate_from_tf) {
  NavigationReport report;
  if (!WaitForClock(nh, connect_timeout_s, report)) return report;
  RunWatch watch(nh, world, estimate_from_tf);
  LegWatcher& watcher = watch.watcher;
  if (watch.tf) report.estimate_source = "tf's map -> base_link";
  watch.Start();

  NavigateClient client(nh, "harmonic_planner/navigate", true);
  if (!client.waitForServer(ros::Duration(connect_timeout_s))) {
    report.skipped = "harmonic_planner/navigate is not offered";
    return report;
  }
  ActiveLocalizeClient active(nh, "active_localize", true);  // markov_localization's, if it runs
  report.ran = true;
  for (const std::string& name : goals) {
    NavigationLeg leg;
    leg.goal = name;
    const spott_map::Place* place = world.FindPlace(name);
    if (!place) {
      leg.outcome = "not reached: no place '" + name + "' in the world file";
      report.legs.push_back(leg);
      continue;
    }
    leg.target = place->pose;
    const ros::Time started = ros::Time::now();
    const ros::WallTime wall_started = ros::WallTime::now();
    leg.start_sim_s = started.toSec();
    watcher.Reset(started);
    FeedbackLog log;
    // Navigate waits in PLANNING for the pose and the global planner's answer: nothing to
    // prepare here but the goal.
    DoneTime done_time;
    const auto goal = NavigateGoalTo(place->pose, /*ignore_heading=*/false, goal_tolerance_m);
    bool done = false;
    for (int relocalized = 0;; ++relocalized) {
      done_time.Reset();
      done = SendAndWait(
          client,
          [&] {
            client.sendGoal(
                goal,
                [&done_time](const actionlib::SimpleClientGoalState&,
                             const spott_msgs::NavigateResultConstPtr&) { done_time.Set(); },
                NavigateClient::SimpleActiveCallback(),
                [&log](const spott_msgs::NavigateFeedbackConstPtr& fb) { log.On(*fb); });
          },
          started, leg_timeout_s);
      const auto result = done ? client.getResult() : nullptr;
      if (!result || !NotLocalized(*result) || relocalized >= kMaxActiveLocalizations) break;
      if (!Relocalize(active, started, leg_timeout_s)) break;
      std::lock_guard<std::mutex> lock(log.mutex);
      log.log.recoveries.push_back(kActiveLocalizationNote);
    }
    leg.wall_time_s = (ros::WallTime::now() - wall_started).toSec();
    bool succeeded = false;
    if (done) {
      const auto result = client.getResult();
      leg.navigate_outcome = result ? spott_move_base::TextOf(*result) : "failed: no result";
      succeeded = result && result->outcome == spott_msgs::NavigateResult::SUCCEEDED;
    } else {
      client.cancelGoal();
      leg.navigate_outcome = TimedOutText(leg_timeout_s);
    }
    leg.sim_time_s = (CloseLeg(watcher, done_time) - started).toSec();
    {
      std::lock_guard<std::mutex> lock(log.mutex);
      leg.recoveries = log.log.recoveries;
      leg.global_path = log.log.path_summary;
    }
    Measure(watcher, place->pose.Position(), leg);
    const std::string off_goal = OffPlace(leg, goal_tolerance_m);
    JudgeLeg(succeeded ? "" : "Navigate " + leg.navigate_outcome, off_goal, leg);
    report.legs.push_back(leg);
  }
  return report;
}

NavigationReport RunMissions(ros::NodeHandle& nh, const spott_map::World& world,
                             const std::vector<MissionSpec>& missions, double leg_timeout_s,
                             double connect_timeout_s, double goal_tolerance_m,
                             bool estimate_from_tf) {
  using MissionClient = actionlib::SimpleActionClient<spott_msgs::MissionAction>;
  NavigationReport report;
  report.by_mission = true;
  if (!WaitForClock(nh, connect_timeout_s, report)) return report;
  RunWatch watch(nh, world, estimate_from_tf);
  LegWatcher& watcher = watch.watcher;
  if (watch.tf) report.estimate_source = "tf's map -> base_link";
  watch.Start();
  MissionClient client(nh, "mission", true);
  if (!client.waitForServer(ros::Duration(connect_timeout_s))) {
    report.skipped = "/mission is not offered (rpl_executive is not running)";
    return report;
  }
  report.ran = true;
  for (const MissionSpec& spec : missions) {
    NavigationLeg leg;
    SetMissionTarget(spec, world, leg);
    spott_msgs::MissionGoal goal;
    goal.language = spec.language == "rpl" ? spott_msgs::MissionGoal::RPL
                                           : spott_msgs::MissionGoal::NOREILS_CHATILA;
    goal.name = spec.name.text;
    goal.bindings = spec.bindings;
    ros::Time started = ros::Time::now();
    const ros::WallTime wall_started = ros::WallTime::now();
    bool done = false;
    DoneTime done_time;
    // The executive refuses a mission until its modules have their first readings ("not
    // ready"): asked again each second, as an operator would, within the leg's time.
    for (;;) {
      started = ros::Time::now();
      leg.start_sim_s = started.toSec();
      watcher.Reset(started);
      done = SendAndWait(
          client,
          [&] {
            client.sendGoal(
                goal, [&done_time](const actionlib::SimpleClientGoalState&,
                                   const spott_msgs::MissionResultConstPtr&) { done_time.Set(); });
          },
          started, leg_timeout_s);
      const auto early = client.getResult();
      if (!done || !early || early->outcome != "rejected" ||
          early->message.find("not ready") == std::string::npos ||
          (ros::WallTime::now() - wall_started).toSec() > connect_timeout_s) {
        break;
      }
      ros::WallDuration(1.0).sleep();
      done_time.Reset();
    }
    leg.wall_time_s = (ros::WallTime::now() - wall_started).toSec();
    std::string mismatch;
    const auto result = done ? client.getResult() : nullptr;
    if (result) {
      mismatch = ApplyMissionResult(*result, spec, leg);
    } else {
      if (!done) {
        client.cancelGoal();
        client.waitForResult(ros::Duration(5.0));
      }
      leg.mission_outcome = done ? "no result" : TimedOutText(leg_timeout_s);
      leg.navigate_outcome = mismatch = leg.mission_outcome;
    }
    leg.sim_time_s = (CloseLeg(watcher, done_time) - started).toSec();
    Measure(watcher, leg.has_target ? leg.target.Position() : watcher.Pose().Position(), leg);
    JudgeMissionLeg(mismatch, goal_tolerance_m, leg);
    report.legs.push_back(leg);
  }
  return report;
}

spott_msgs::NavigateGoal NavigateGoalTo(const spott_map::Pose2& target, bool ignore_heading,
                                        double tolerance_m) {
  spott_msgs::NavigateGoal goal;
  goal.target = spott_ros::ToPoseStamped(spott_ros::MakePose2D(target.x, target.y, target.yaw),
                                         "map", ros::Time::now());
  goal.speed_mode = spott_msgs::NavigateGoal::NORMAL;
  goal.direction_bias = std::numeric_limits<double>::quiet_NaN();
  goal.position_tolerance = tolerance_m;
  goal.ignore_heading = ignore_heading;
  return goal;
}

namespace {
std::string FormatMetres(double m) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.2f", m);
  return text;
}
}  // namespace

std::string FormatNavigation(const NavigationReport& report) {
  if (!report.ran && report.skipped.empty()) return "";
  std::ostringstream out;
  out << std::fixed << std::setprecision(2);
  if (report.by_task) {
    out << "\n Tasks (/task -> tr_plus_controller (SPOTT's TR+ navigation program) -> Navigate ->\n"
        << " global_planner + harmonic_planner -> cmd_vel_arbiter -> robot_sim; judged on the\n"
        << " simulator's ground truth, which nothing in the stack reads):\n";
  } else if (report.by_mission) {
    out << "\n Missions (/mission -> rpl_executive (RPL plans, Noreils-Chatila missions) -> "
           "Navigate\n"
        << " or its own modules -> cmd_vel_arbiter -> robot_sim; judged on what the executive\n"
        << " reports and on the simulator's ground truth):\n";
  } else {
    out << "\n Navigation (Navigate -> global_planner + harmonic_planner -> cmd_vel_arbiter ->\n"
        << " robot_sim; judged on the simulator's ground truth, which nothing in the stack "
           "reads):\n";
  }
  if (!report.ran) {
    out << "   not run: " << report.skipped << "\n";
    return out.str();
  }
  int reached = 0;
  for (const NavigationLeg& leg : report.legs) {
    reached += leg.reached;
    if (report.by_task) {
      out << "   task '" << leg.task << "': " << leg.outcome << "\n";
      if (!leg.interpretation.empty()) out << "     interpretation: " << leg.interpretation << "\n";
      if (!leg.trace.empty()) out << "     TR trace: " << CompactTrace(leg.trace) << "\n";
      out << "     controller: " << leg.task_outcome << "\n";
    } else if (report.by_mission) {
      out << "   mission " << leg.mission;
      if (leg.has_target) {
        out << " to " << (leg.goal.empty() ? "" : leg.goal + " ") << "(" << leg.target.x << ", "
            << leg.target.y << ")";
      }
      out << ": " << leg.outcome << "\n     executive: " << leg.navigate_outcome << "\n";
      out << "     monitors fired:";
      if (leg.monitors_fired.empty()) out << " none";
      for (std::size_t i = 0; i < leg.monitors_fired.size(); ++i)
        out << (i == 0 ? " " : ", ") << leg.monitors_fired[i];
      out << "\n";
    } else {
      out << "   to " << leg.goal << " (" << leg.target.x << ", " << leg.target.y
          << "): " << leg.outcome << "\n";
    }
    if (!leg.global_path.empty()) out << "     global path: " << leg.global_path << "\n";
    if (!report.by_task && !report.by_mission && !leg.outcome.empty() && !leg.reached &&
        !leg.navigate_outcome.empty() &&
        leg.outcome.find(leg.navigate_outcome) == std::string::npos) {
      out << "     Navigate: " << leg.navigate_outcome << "\n";
    }
    if (!leg.recoveries.empty()) {
      out << "     recovering " << leg.recoveries.size() << " times:";
      for (std::size_t i = 0; i < leg.recoveries.size(); ++i)
        out << (i == 0 ? " " : "; ") << leg.recoveries[i];
      out << "\n";
    }
    out << std::setprecision(1) << "     " << leg.sim_time_s << " s simulated ("
        << (leg.wall_time_s > 0 ? leg.sim_time_s / leg.wall_time_s : 0.0) << "x real time), "
        << leg.path_length_m << " m driven, ended at (" << leg.final_position.x() << ", "
        << leg.final_position.y() << "), " << std::setprecision(2)
        << (!leg.has_target  // a mission, a find, a tele-operation: nothing to measure from
                ? std::string("no goal to be at")
                : FormatMetres(leg.final_error_m) + " m from the target")
        << "; closest approach to a wall or object " << leg.min_wall_distance_m
        << " m (centre), bumper contacts: " << leg.bumper_hits
        << ", body contacts (ground truth): " << leg.body_contacts << "\n";
    if (leg.estimates > 0) {
      out << "     localization error (" << report.estimate_source << " vs ground truth, "
          << leg.estimates << " estimates): mean " << leg.mean_position_error_m << " m / "
          << std::setprecision(1) << leg.mean_heading_error_rad * 180.0 / M_PI << " deg, max "
          << std::setprecision(2) << leg.max_position_error_m << " m / " << std::setprecision(1)
          << leg.max_heading_error_rad * 180.0 / M_PI << " deg; said lost " << leg.lost_reports
          << " times\n"
          << std::setprecision(2);
    }
    if (!leg.found_label.empty()) {
      out << "     found: a " << leg.found_label << " at (" << leg.found_at.x() << ", "
          << leg.found_at.y() << "); the world's nearest " << leg.found_label << " is "
          << FormatMetres(leg.found_nearest_m) << " m from it\n";
    }
    if (report.by_task) {
      out << "     features the controller added to the map: ";
      if (leg.features_added.empty()) out << "none";
      for (std::size_t i = 0; i < leg.features_added.size(); ++i) {
        if (i == 12) {
          out << " ... (" << leg.features_added.size() << " in all)";
          break;
        }
        out << (i == 0 ? "" : ", ") << leg.features_added[i];
      }
      out << "\n";
    }
  }
  if (report.by_task) {  // the rules of the traces, once each
    std::vector<std::string> rules;
    for (const NavigationLeg& leg : report.legs) {
      for (const std::string& r : leg.trace) {
        if (std::find(rules.begin(), rules.end(), r) == rules.end()) rules.push_back(r);
      }
    }
    if (!rules.empty()) out << "   the rules of the TR traces:\n";
    for (const std::string& r : rules) out << "     " << r << "\n";
  }
  double sim = 0.0, wall = 0.0;
  for (const NavigationLeg& leg : report.legs) {
    sim += leg.sim_time_s;
    wall += leg.wall_time_s;
  }
  out << "   " << reached << " of " << report.legs.size()
      << (report.by_task      ? " tasks reached"
          : report.by_mission ? " missions as the scenario says"
                              : " goals reached");
  if (wall > 0) {
    out << std::setprecision(1) << "; real-time factor " << sim / wall << " achieved";
    if (report.requested_real_time_factor > 0)
      out << " (" << report.requested_real_time_factor << " asked)";
  }
  out << "\n";
  return out.str();
}

}  // namespace spott_launch
