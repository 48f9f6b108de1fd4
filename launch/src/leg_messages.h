// The stack's messages into a leg of the report: one reading for the live demo
// (demo_navigation.cpp, demo_report.cpp) and for a recorded bag (bag_report.cpp), so that both
// give the same report.
#pragma once

#include <string>
#include <vector>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <spott_msgs/BumperRing.h>
#include <spott_msgs/GlobalPath.h>
#include <spott_msgs/MissionResult.h>
#include <spott_msgs/NavigateFeedback.h>
#include <spott_msgs/NavigateResult.h>
#include <spott_msgs/TaskResult.h>

#include "demo_report.h"
#include "spott_launch/leg_metrics.h"

namespace spott_launch {

/// A segment of the ring is pressed (`/bumper`), or the body touches (`/sim/contact`).
bool AnyPressed(const spott_msgs::BumperRing& ring);

/// "hall_w -> d_lab_w -> lab": the rooms and doors of a global plan; "(no path)" when empty.
std::string GlobalPathText(const spott_msgs::GlobalPath& path);

/// What Navigate's feedback told during a leg: the first global path summary and each
/// RECOVERING episode with its note. Not thread-safe.
struct NavigateFeedbackLog {
  std::string path_summary;
  std::vector<std::string> recoveries;
  bool recovering = false;
  void On(const spott_msgs::NavigateFeedback& feedback);
};

/// Navigate ended FAILED "not localized" (it arrived on an estimate the localization calls
/// lost): a plain Navigate client localizes actively and sends the goal again (RunNavigation;
/// bag_report reads the same leg from the bag).
bool NotLocalized(const spott_msgs::NavigateResult& result);
/// The recovery the leg reports for it, live and from the bag alike.
inline const char* const kActiveLocalizationNote =
    "not localized: active localization, then the goal again";
constexpr int kMaxActiveLocalizations = 2;  ///< Per leg.

/// The TR+ controller's result into `leg`: interpretation, trace, task outcome, the features it
/// added since `features_before` (updated), the goal point it sent. True when it says reached
/// (a find: found; a tele-operation: stopped).
bool ApplyTaskResult(const spott_msgs::TaskResult& result,
                     std::vector<std::string>& features_before, NavigationLeg& leg);

/// rpl_executive's result into `leg`: its outcome, the monitors that fired (conditions, in
/// order), the outcome with the message as the report shows it. Returns why the mission did not
/// go as `spec` says ("" = as it says), from MissionMismatch.
std::string ApplyMissionResult(const spott_msgs::MissionResult& result, const MissionSpec& spec,
                               NavigationLeg& leg);

/// robot_sim's /sim/faults message as the report's faults.
std::vector<DemoReport::Fault> FaultsFrom(const diagnostic_msgs::DiagnosticArray& message);

}  // namespace spott_launch
