// The office robot's behaviour modules as the stack runs them (Beetz et al. section 3): the logic
// of NAVIGATION, ACTIVE-LOCALIZATION and POSITION-TRACKING, ROS-free. The node gives each module a
// small client interface (Navigate goals, the ActiveLocalize action, the travel-mode switch) and
// passes it the messages; the modules keep the fluents of section 3's table up to date and report
// to the executive. Tests drive them with scripted clients.
//
// NAVIGATION (NavigationModule): activated with a destination (X Y), it generates the structured
// reactive navigation plan (navigation_plan.h) from the robot's estimated position, sends its
// target points one Navigate goal after the other, keeps NR-OF-NAV-GOALS* (target points not yet
// reached) and NAVIGATION-ACTIVE?*, sets the travel mode of the region the robot is in, succeeds
// once the last target point is reached within goal_tolerance_m and fails with the planner's
// reason when a target cannot be reached. Deactivating it cancels the goal and deletes every
// target point (NR-OF-NAV-GOALS* drops to 0: "a process has to delete all target points before it
// can cause the robot to move somewhere else").
//
// Ordering with the executive: a report is processed in the next Executive::Step before the
// threads woken by fluent changes, and EXECUTION-INTERRUPTED? pulses when NR-OF-NAV-GOALS* drops
// to 0. If a failing (or finished) NAVIGATION dropped its count to 0 together with its report,
// the pulse would end the routine's TRY-ALL before the failure is counted. So on its own end the
// module reports first and deletes its target points in AfterStep, which the caller runs after the
// Step that processed the report, unless the plan activated the module again meanwhile.
//
// Not thread-safe: call from the executive's thread. Time is passed in.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "rpl_executive/rpl/behaviour_module.h"
#include "rpl_executive/rpl/executive.h"
#include "rpl_executive/rpl/navigation_plan.h"

namespace rpl_executive {
namespace rpl {
namespace office {

/// The path planner's entry on the stack (Navigate): the node implements it.
class NavigateClient {
 public:
  virtual ~NavigateClient() = default;
  /// Sends one target point (m, map) reached within `tolerance_m`; replaces a goal in flight.
  virtual void SendGoal(const Point& target, double tolerance_m, double now_s) = 0;
  virtual void CancelGoal(double now_s) = 0;
};

/// What the stack's collision avoidance and localization do in each travel mode (the arbiter's
/// speed limits, the localization's sensor selection): the node implements it.
class TravelModeSwitch {
 public:
  virtual ~TravelModeSwitch() = default;
  /// kNone: no navigation plan runs (the robot's own limits).
  virtual void SetTravelMode(TravelMode mode, const std::string& region, double now_s) = 0;
};

enum class GoalOutcome { kSucceeded, kUnreachable, kPreempted, kFailed };
const char* GoalOutcomeName(GoalOutcome outcome);

struct NavigationModuleParameters {
  NavigationPlanParameters plan;
  /// NAVIGATION succeeds within this of the destination (m); the office plan's
  /// AT-DESTINATION-RADIUS-M (0.5 m) must be larger. (0, 5].
  double goal_tolerance_m = 0.3;
  /// An intermediate target point counts as reached within this (m). (0, 5].
  double target_tolerance_m = 0.4;
};
std::vector<std::string> ValidateParameters(const NavigationModuleParameters& p);

class NavigationModule : public BehaviourModule {
 public:
  /// `executive`, `client` and `travel` (may be null) outlive the module.
  NavigationModule(Executive* executive, NavigateClient* client, TravelModeSwitch* travel,
                   const NavigationModuleParameters& parameters);

  ModuleSpec Spec() const override;
  void Activate(ActivationId id, const std::vector<Value>& args, double now_s) override;
  void Deactivate(ActivationId id, double now_s) override;

  /// The building (world_server's room/door graph); used by the next activation.
  void SetMap(const BuildingMap& map);
  bool has_map() const { return has_map_; }
  /// The position estimate (m, map): plans start here; the travel mode follows it.
  void OnPose(const Point& position, double now_s);
  /// The Navigate result of the target point in flight.
  void OnGoalDone(GoalOutcome outcome, const std::string& reason, double now_s);
  /// After the Step that processed this module's report: deletes the target points of an
  /// activation that ended by itself. True when it changed a fluent (the caller Steps again).
  bool AfterStep(double now_s);

  bool active() const { return id_ != 0; }
  /// The plan of the current (or last) activation.
  const std::optional<NavigationPlan>& plan() const { return plan_; }
  /// Plans generated so far (one per activation that planned).
  int plans_generated() const { return plans_generated_; }
  /// Target points not reached yet (NR-OF-NAV-GOALS*).
  std::size_t remaining() const { return remaining_.size(); }
  TravelMode travel_mode() const { return mode_; }
  /// What the module did last ("target 2 of 5 (17.50, 8.20)", "reached the destination").
  const std::string& note() const { return note_; }

 private:
  void PublishFluents(double now_s);
  void SendNext(double now_s);
  void SetMode(TravelMode mode, const std::string& region, double now_s);

  Executive* executive_;
  NavigateClient* client_;
  TravelModeSwitch* travel_;
  NavigationModuleParameters params_;
  BuildingMap map_;
  bool has_map_ = false;
  std::optional<Point> pose_;
  ActivationId id_ = 0;
  Point destination_;
  std::optional<NavigationPlan> plan_;
  std::vector<Point> remaining_;
  int plans_generated_ = 0;
  bool clear_after_step_ = false;
  TravelMode mode_ = TravelMode::kNone;
  std::string mode_region_;
  std::string note_;
};

/// markov_localization's ActiveLocalize (and its uniform reset): the node implements it.
class ActiveLocalizeClient {
 public:
  virtual ~ActiveLocalizeClient() = default;
  /// Resets the belief to uniform (/global_localization) when `uniform_start`, then sends the
  /// ActiveLocalize goal (threshold in (0, 1), timeout s, 0 = none).
  virtual void Start(bool uniform_start, double certainty_threshold, double timeout_s,
                     double now_s) = 0;
  virtual void Cancel(double now_s) = 0;
};

struct ActiveLocalizationParameters {
  /// "The localization module re-localize[s] the robot, which starts with uniform distribution
  /// over all possible positions" (section 4).
  bool uniform_start = true;
  double certainty_threshold = 0.8;  ///< (0, 1), the policy's 0.8
  double timeout_s = 0.0;            ///< [0, 1e5], 0 = no limit
};
std::vector<std::string> ValidateParameters(const ActiveLocalizationParameters& p);

/// ACTIVE-LOCALIZATION: drives to target points that minimize the expected entropy plus travel
/// cost until the position is certain (markov_localization's ActiveLocalize action). Reports
/// success when the action succeeds, failure with its reason when it gives up; the office plan
/// deactivates it as soon as POS-CERTAINTY* > 0.8 (which cancels the action).
class ActiveLocalizationModule : public BehaviourModule {
 public:
  ActiveLocalizationModule(Executive* executive, ActiveLocalizeClient* client,
                           const ActiveLocalizationParameters& parameters);
  ModuleSpec Spec() const override;
  void Activate(ActivationId id, const std::vector<Value>& args, double now_s) override;
  void Deactivate(ActivationId id, double now_s) override;
  /// The action's result.
  void OnDone(bool success, const std::string& reason, double now_s);
  bool active() const { return id_ != 0; }
  int activations() const { return activations_; }

 private:
  Executive* executive_;
  ActiveLocalizeClient* client_;
  ActiveLocalizationParameters params_;
  ActivationId id_ = 0;
  int activations_ = 0;
};

/// POSITION-TRACKING: passive tracking of the pose (section 2). markov_localization tracks
/// whenever it runs and has no switch to start or stop it; the module supervises it: its
/// activation fails when no localization status has come for `status_timeout_s`, and while active
/// it fails when the status stops coming for that long. Deactivating it leaves the tracking on.
class PositionTrackingModule : public BehaviourModule {
 public:
  PositionTrackingModule(Executive* executive, double status_timeout_s);
  ModuleSpec Spec() const override;
  void Activate(ActivationId id, const std::vector<Value>& args, double now_s) override;
  void Deactivate(ActivationId id, double now_s) override;
  /// A localization status arrived.
  void OnStatus(double now_s);
  /// Checks the status' age (call at the node's rate).
  void OnTime(double now_s);
  bool active() const { return id_ != 0; }

 private:
  Executive* executive_;
  double status_timeout_s_;
  std::optional<double> last_status_s_;
  ActivationId id_ = 0;
};

}  // namespace office
}  // namespace rpl
}  // namespace rpl_executive
