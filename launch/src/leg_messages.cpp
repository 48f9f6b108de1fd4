#include "leg_messages.h"

#include <algorithm>
#include <cmath>

#include "spott_tr_plus/controller/navigation_controller.h"

namespace spott_launch {

bool AnyPressed(const spott_msgs::BumperRing& ring) {
  return std::any_of(ring.pressed.begin(), ring.pressed.end(), [](bool b) { return b; });
}

std::string GlobalPathText(const spott_msgs::GlobalPath& path) {
  std::string text;
  for (std::size_t i = 0; i < path.rooms.size(); ++i) {
    text += (i == 0 ? "" : " -> ") + path.rooms[i];
    if (i < path.doors.size()) text += " -> " + path.doors[i];
  }
  return text.empty() ? "(no path)" : text;
}

void NavigateFeedbackLog::On(const spott_msgs::NavigateFeedback& feedback) {
  if (path_summary.empty() && !feedback.global_path_summary.empty())
    path_summary = feedback.global_path_summary;
  const bool now = feedback.state == spott_msgs::NavigateFeedback::RECOVERING;
  if (now && !recovering)
    recoveries.push_back(feedback.note.empty() ? "recovering" : feedback.note);
  recovering = now;
}

// One reading of Navigate's contract, the TR+ controller's (its outcomes are the message's).
bool NotLocalized(const spott_msgs::NavigateResult& result) {
  return spott_tr_plus::controller::NavigateNotLocalized(
      static_cast<spott_tr_plus::controller::NavigateOutcome>(result.outcome), result.reason);
}

std::string ApplyMissionResult(const spott_msgs::MissionResult& result, const MissionSpec& spec,
                               NavigationLeg& leg) {
  leg.mission_outcome = result.outcome;
  leg.monitors_fired.clear();
  for (const auto& e : result.events) leg.monitors_fired.push_back(e.condition);
  leg.navigate_outcome = result.outcome + (result.message.empty() ? "" : ": " + result.message);
  return MissionMismatch(spec, result.outcome, result.message, leg.monitors_fired);
}

bool ApplyTaskResult(const spott_msgs::TaskResult& result,
                     std::vector<std::string>& features_before, NavigationLeg& leg) {
  leg.interpretation = result.interpretation;
  leg.trace = result.trace;
  // A `find` ends "found", a tele-operation "stopped" (the object's place and the way driven are
  // judged by OffTaskGoal).
  const bool reached =
      result.outcome == "reached" || result.outcome == "found" || result.outcome == "stopped";
  leg.found_label = result.found_label;
  leg.found_at = spott_map::Vec2(result.found_at.x, result.found_at.y);
  // The message says why a task failed, and why a tele-operation stopped (once: the
  // controller's may already begin with the outcome).
  const bool say = !reached || result.outcome == "stopped";
  std::string why = result.message;
  if (why.rfind(result.outcome + ": ", 0) == 0) why.erase(0, result.outcome.size() + 2);
  leg.task_outcome = result.outcome + (why.empty() || !say ? "" : ": " + why);
  for (const std::string& id : result.features_added) {
    if (std::find(features_before.begin(), features_before.end(), id) == features_before.end())
      leg.features_added.push_back(id);
  }
  features_before = result.features_added;
  leg.has_target = std::isfinite(result.goal.x) && std::isfinite(result.goal.y);
  if (leg.has_target) leg.target = spott_map::Pose2{result.goal.x, result.goal.y, 0.0};
  return reached;
}

std::vector<DemoReport::Fault> FaultsFrom(const diagnostic_msgs::DiagnosticArray& message) {
  std::vector<DemoReport::Fault> faults;
  for (const auto& status : message.status) {
    faults.push_back({message.header.stamp.toSec(), status.hardware_id, status.message,
                      status.level == diagnostic_msgs::DiagnosticStatus::OK});
  }
  return faults;
}

}  // namespace spott_launch
