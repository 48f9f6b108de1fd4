// bag_report: the run's report recomputed from a bag alone (./spott report BAG). The legs are
// the demo's action goals and results in the bag (/mission for rpl_executive, /task for the TR+
// controller, else harmonic_planner/navigate); each is measured by the same LegMetrics and judged
// by the same rules as the live run, on the recorded ground truth, bumpers and localization
// statuses; the world is the one /room_door_graph names, the scenario (a mission's expected
// outcome and monitors, the goal tolerance) the one demo_report latched on /demo_report/scenario.
// Prints the navigation report; --json FILE writes the JSON report (FormatReportJson).
//   bag_report BAG [--json FILE] [--worlds DIR] [--tolerance M]
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <nav_msgs/Odometry.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <spott_msgs/BumperRing.h>
#include <spott_msgs/GlobalPath.h>
#include <spott_msgs/LocalizationStatus.h>
#include <spott_msgs/MissionActionGoal.h>
#include <spott_msgs/MissionActionResult.h>
#include <spott_msgs/NavigateActionFeedback.h>
#include <spott_msgs/NavigateActionGoal.h>
#include <spott_msgs/NavigateActionResult.h>
#include <spott_msgs/RoomDoorGraph.h>
#include <spott_msgs/TaskActionGoal.h>
#include <spott_msgs/TaskActionResult.h>
#include <std_msgs/String.h>

#include "demo_report.h"
#include "leg_messages.h"
#include "spott_launch/leg_metrics.h"
#include "spott_map/world_loader.h"
#include "spott_move_base/conversions.h"

namespace {

using spott_launch::NavigationLeg;

// A leg is closed once the bag has passed its window (messages are recorded a little after
// their stamps).
constexpr double kRecordLagS = 0.5;

struct Options {
  std::string bag, json, worlds = SPOTT_WORLDS_DIR;
  double tolerance_m = 0.25;
  bool tolerance_given = false;
};

enum class RunKind { kNavigate, kTask, kMission };

struct OpenLeg {
  NavigationLeg leg;
  std::string goal_id;
  spott_map::Pose2 start;
  double end_s = -1.0;  ///< Simulated time of the result (-1: still running).
  bool succeeded = false;
  /// Navigate said "not localized": the demo localizes actively and sends the goal again
  /// (RunNavigation); the leg goes on with that goal.
  bool awaits_retry = false;
  int retries = 0;
  std::string refusal;
  spott_launch::NavigateFeedbackLog feedback;
  std::string first_path, last_path;
};

class Replay {
 public:
  Replay(const spott_map::World& world, RunKind kind, double tolerance_m)
      : metrics_(world), world_(world), kind_(kind), tolerance_m_(tolerance_m) {}

  void Time(double t) {
    if (open_ && open_->end_s >= 0.0 && !open_->awaits_retry &&
        t > open_->end_s + spott_launch::LegMetrics::kSettleS + kRecordLagS) {
      Close();
    }
  }
  void Truth(const nav_msgs::Odometry& m) {
    const auto& q = m.pose.pose.orientation;
    metrics_.OnTruth(m.header.stamp.toSec(), m.pose.pose.position.x, m.pose.pose.position.y,
                     2.0 * std::atan2(q.z, q.w));
  }
  void Status(const spott_msgs::LocalizationStatus& m) {
    metrics_.OnStatus(m.header.stamp.toSec(), m.estimate.x, m.estimate.y, m.estimate.theta, m.lost);
  }
  void Bumper(const spott_msgs::BumperRing& m) {
    metrics_.OnBumper(m.header.stamp.toSec(), spott_launch::AnyPressed(m));
  }
  void BodyContact(const spott_msgs::BumperRing& m) {
    metrics_.OnBodyContact(m.header.stamp.toSec(), spott_launch::AnyPressed(m));
  }
  void Path(const spott_msgs::GlobalPath& m) {
    if (!open_ || open_->end_s >= 0.0) return;
    open_->last_path = spott_launch::GlobalPathText(m);
    if (open_->first_path.empty() && m.header.stamp.toSec() >= open_->leg.start_sim_s)
      open_->first_path = open_->last_path;
  }
  /// Navigate's feedback; of `goal_id` only when the run sends Navigate goals itself (the
  /// live demo hears its own goals' feedback, not active localization's).
  void Feedback(const spott_msgs::NavigateFeedback& fb, const std::string& goal_id) {
    if (!open_ || (kind_ == RunKind::kNavigate && open_->goal_id != goal_id)) return;
    open_->feedback.On(fb);
  }
  /// The goal sent again to the open leg's target after "not localized": the leg goes on.
  bool Retry(const std::string& goal_id, const spott_map::Pose2& target) {
    if (!open_ || !open_->awaits_retry ||
        (open_->leg.target.Position() - target.Position()).norm() > 1e-6)
      return false;
    open_->awaits_retry = false;
    open_->goal_id = goal_id;
    open_->end_s = -1.0;
    ++open_->retries;
    open_->feedback.recoveries.push_back(spott_launch::kActiveLocalizationNote);
    return true;
  }
  void Open(double t, const std::string& goal_id, NavigationLeg leg) {
    if (open_) Close();
    open_.emplace();
    open_->start = metrics_.pose();
    open_->goal_id = goal_id;
    open_->leg = std::move(leg);
    open_->leg.start_sim_s = t;
    metrics_.Reset(t);
  }
  OpenLeg* Current(const std::string& goal_id) {
    return open_ && open_->goal_id == goal_id && open_->end_s < 0.0 ? &*open_ : nullptr;
  }
  /// `retried`: Navigate said "not localized" and the demo goes on with the leg (RunNavigation:
  /// active localization, the goal again), its window open meanwhile as the live run's is.
  void End(OpenLeg& leg, double t, bool retried = false) {
    leg.end_s = t;
    leg.awaits_retry = retried;
    leg.leg.sim_time_s = t - leg.leg.start_sim_s;
    if (!retried) metrics_.EndAt(t + spott_launch::LegMetrics::kSettleS);
  }
  /// The open leg never was one: its goal was refused before anything ran (a mission the
  /// executive was not ready for, sent again).
  void Drop() { open_.reset(); }
  std::vector<NavigationLeg> Finish() {
    if (open_) Close();
    return legs_;
  }

 private:
  void Close() {
    OpenLeg& o = *open_;
    NavigationLeg& leg = o.leg;
    leg.recoveries = o.feedback.recoveries;
    leg.global_path = o.feedback.path_summary;
    if (leg.global_path.empty())
      leg.global_path = o.first_path.empty() ? o.last_path : o.first_path;
    metrics_.Measure(leg.target.Position(), leg);
    if (o.end_s < 0.0) {
      JudgeLeg("no result in the bag", "", leg);
    } else if (kind_ == RunKind::kTask) {
      JudgeLeg(o.refusal, spott_launch::OffTaskGoal(world_, leg.task, o.start, leg, tolerance_m_),
               leg);
      leg.found_nearest_m =
          spott_launch::NearestObjectOfKind(world_, leg.found_label, leg.found_at);
    } else if (kind_ == RunKind::kMission) {
      spott_launch::JudgeMissionLeg(o.refusal, tolerance_m_, leg);
    } else {
      JudgeLeg(o.refusal, spott_launch::OffPlace(leg, tolerance_m_), leg);
    }
    legs_.push_back(leg);
    open_.reset();
  }

  spott_launch::LegMetrics metrics_;
  const spott_map::World& world_;
  RunKind kind_;
  double tolerance_m_;
  std::optional<OpenLeg> open_;
  std::vector<NavigationLeg> legs_;
};

int Usage(const std::string& why) {
  std::cerr << "bag_report: " << why
            << "\nusage: bag_report BAG [--json FILE] [--worlds DIR] [--tolerance M]\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if ((arg == "--json" || arg == "--worlds" || arg == "--tolerance") && i + 1 < argc) {
      const std::string value = argv[++i];
      if (arg == "--json") o.json = value;
      if (arg == "--worlds") o.worlds = value;
      if (arg == "--tolerance") {
        o.tolerance_given = true;
        try {
          o.tolerance_m = std::stod(value);
        } catch (const std::exception&) {
          return Usage("--tolerance: not a number: " + value);
        }
        if (!(o.tolerance_m > 0.0)) return Usage("--tolerance must be > 0 m");
      }
    } else if (!arg.empty() && arg[0] == '-') {
      return Usage("unknown option " + arg);
    } else if (o.bag.empty()) {
      o.bag = arg;
    } else {
      return Usage("one bag only");
    }
  }
  if (o.bag.empty()) return Usage("no bag");
  ros::Time::init();
  rosbag::Bag bag;
  try {
    bag.open(o.bag, rosbag::bagmode::Read);
  } catch (const rosbag::BagException& e) {
    std::cerr << o.bag << ": " << e.what() << "\n";
    return 1;
  }
  // The world, the scenario and the kind of run first.
  std::string world_name, scenario_text;
  bool by_task = false, by_mission = false;
  for (const rosbag::MessageInstance& m : rosbag::View(bag)) {
    if (m.getTopic() == "/room_door_graph" && world_name.empty()) {
      if (auto g = m.instantiate<spott_msgs::RoomDoorGraph>()) world_name = g->world;
    }
    if (m.getTopic() == "/demo_report/scenario" && scenario_text.empty()) {
      if (auto t = m.instantiate<std_msgs::String>()) scenario_text = t->data;
    }
    if (m.getTopic() == "/task/goal") by_task = true;
    if (m.getTopic() == "/mission/goal") by_mission = true;
  }
  // The scenario as the run had it: its tolerance, and what each mission must show.
  std::optional<spott_launch::Scenario> scenario;
  if (!scenario_text.empty()) {
    auto parsed = spott_launch::ParseScenario(scenario_text, o.bag + ":/demo_report/scenario");
    if (!parsed.ok()) {
      std::cerr << spott_map::FormatErrors(parsed.errors) << "\n";
      return 1;
    }
    scenario = std::move(parsed.scenario);
    if (!o.tolerance_given) o.tolerance_m = scenario->goal_tolerance_m;
  } else if (by_mission) {
    std::cerr << o.bag
              << ": no /demo_report/scenario: each mission is judged on the "
                 "executive's word (completed) and its contacts\n";
  }
  const RunKind kind = by_mission ? RunKind::kMission
                       : by_task  ? RunKind::kTask
                                  : RunKind::kNavigate;
  if (world_name.empty()) {
    std::cerr << o.bag << ": no /room_door_graph naming the world: not a run of the stack\n";
    return 1;
  }
  const auto world = spott_map::LoadWorldFile(o.worlds + "/" + world_name + ".yaml");
  if (!world.ok()) {
    std::cerr << spott_map::FormatErrors(world.errors) << "\n";
    return 1;
  }
  spott_launch::DemoReport report;
  report.ok = true;
  report.world = world_name;
  report.navigation.by_task = kind == RunKind::kTask;
  report.navigation.by_mission = kind == RunKind::kMission;
  report.navigation.ran = true;
  Replay replay(*world.world, kind, o.tolerance_m);
  std::string navigate_client;    // the node that sent the first Navigate goal (the demo)
  std::size_t missions_seen = 0;  // legs of missions that ran, matched to the scenario's
  std::vector<std::string> features_before;
  for (const rosbag::MessageInstance& m : rosbag::View(bag)) {
    const std::string& topic = m.getTopic();
    replay.Time(m.getTime().toSec());
    if (topic == "/sim/ground_truth") {
      if (auto p = m.instantiate<nav_msgs::Odometry>()) replay.Truth(*p);
    } else if (topic == "/localization_status") {
      if (auto p = m.instantiate<spott_msgs::LocalizationStatus>()) replay.Status(*p);
    } else if (topic == "/bumper") {
      if (auto p = m.instantiate<spott_msgs::BumperRing>()) replay.Bumper(*p);
    } else if (topic == "/sim/contact") {
      if (auto p = m.instantiate<spott_msgs::BumperRing>()) replay.BodyContact(*p);
    } else if (topic == "/global_path") {
      if (auto p = m.instantiate<spott_msgs::GlobalPath>()) replay.Path(*p);
    } else if (topic == "/harmonic_planner/navigate/feedback") {
      if (auto p = m.instantiate<spott_msgs::NavigateActionFeedback>())
        replay.Feedback(p->feedback, p->status.goal_id.id);
    } else if (topic == "/sim/faults") {
      if (auto p = m.instantiate<diagnostic_msgs::DiagnosticArray>()) {
        const auto faults = spott_launch::FaultsFrom(*p);
        report.faults.insert(report.faults.end(), faults.begin(), faults.end());
      }
    } else if (kind == RunKind::kMission && topic == "/mission/goal") {
      if (auto p = m.instantiate<spott_msgs::MissionActionGoal>()) {
        NavigationLeg leg;
        leg.has_target = false;  // unless the scenario gives a goal
        if (scenario && missions_seen < scenario->missions.size())
          spott_launch::SetMissionTarget(scenario->missions[missions_seen], *world.world, leg);
        leg.mission = p->goal.name;  // what ran
        replay.Open(p->header.stamp.toSec(), p->goal_id.id, leg);
      }
    } else if (kind == RunKind::kMission && topic == "/mission/result") {
      auto p = m.instantiate<spott_msgs::MissionActionResult>();
      OpenLeg* leg = p ? replay.Current(p->status.goal_id.id) : nullptr;
      if (!leg) continue;
      if (p->result.outcome == "rejected" &&
          p->result.message.find("not ready") != std::string::npos) {
        replay.Drop();  // sent again once the executive is ready (RunMissions)
        continue;
      }
      spott_launch::MissionSpec spec;  // no scenario: the executive's word
      if (scenario && missions_seen < scenario->missions.size())
        spec = scenario->missions[missions_seen];
      ++missions_seen;
      leg->refusal = spott_launch::ApplyMissionResult(p->result, spec, leg->leg);
      replay.End(*leg, p->header.stamp.toSec());
    } else if (kind == RunKind::kTask && topic == "/task/goal") {
      if (auto p = m.instantiate<spott_msgs::TaskActionGoal>()) {
        NavigationLeg leg;
        leg.task = p->goal.command;
        replay.Open(p->header.stamp.toSec(), p->goal_id.id, leg);
      }
    } else if (kind == RunKind::kTask && topic == "/task/result") {
      auto p = m.instantiate<spott_msgs::TaskActionResult>();
      OpenLeg* leg = p ? replay.Current(p->status.goal_id.id) : nullptr;
      if (!leg) continue;
      NavigationLeg& l = leg->leg;
      const bool reached = spott_launch::ApplyTaskResult(p->result, features_before, l);
      l.navigate_outcome = l.task_outcome;
      leg->refusal = reached ? "" : "the controller says " + l.task_outcome;
      replay.End(*leg, p->header.stamp.toSec());
    } else if (kind == RunKind::kNavigate && topic == "/harmonic_planner/navigate/goal") {
      if (auto p = m.instantiate<spott_msgs::NavigateActionGoal>()) {
        NavigationLeg leg;
        const auto& target = p->goal.target.pose;
        leg.target = spott_map::Pose2{target.position.x, target.position.y,
                                      2.0 * std::atan2(target.orientation.z, target.orientation.w)};
        // The place's name: the world's place at the goal's position.
        for (const auto& place : world.world->places) {
          if ((place.pose.Position() - leg.target.Position()).norm() < 1e-6) leg.goal = place.name;
        }
        if (leg.goal.empty()) leg.goal = "(a point)";
        // The run's own goals: active localization sends Navigate goals of its own.
        const std::string& id = p->goal_id.id;
        const std::string client = id.substr(0, id.find('-'));
        if (navigate_client.empty()) navigate_client = client;
        if (client != navigate_client || replay.Retry(id, leg.target)) continue;
        replay.Open(p->header.stamp.toSec(), id, leg);
      }
    } else if (kind == RunKind::kNavigate && topic == "/harmonic_planner/navigate/result") {
      auto p = m.instantiate<spott_msgs::NavigateActionResult>();
      OpenLeg* leg = p ? replay.Current(p->status.goal_id.id) : nullptr;
      if (!leg) continue;
      leg->leg.navigate_outcome = spott_move_base::TextOf(p->result);
      const bool succeeded = p->result.outcome == spott_msgs::NavigateResult::SUCCEEDED;
      leg->refusal = succeeded ? "" : "Navigate " + leg->leg.navigate_outcome;
      replay.End(*leg, p->header.stamp.toSec(),
                 spott_launch::NotLocalized(p->result) &&
                     leg->retries < spott_launch::kMaxActiveLocalizations);
    }
  }
  report.navigation.legs = replay.Finish();
  std::cout << spott_launch::FormatNavigation(report.navigation);
  if (!o.json.empty()) {
    std::ofstream out(o.json);
    out << spott_launch::FormatReportJson(report, "");
    if (!out) {
      std::cerr << "bag_report: cannot write " << o.json << "\n";
      return 1;
    }
  }
  return 0;
}
