// The Executive Module (EM) of Noreils and Chatila (section 4.2) with its surveillance manager
// (surveillance_manager.h) and the executive's default diagnostic step (the paper's DM is "not
// implemented yet as such ... the executive system itself includes this function").
//
// The executive runs a mission step by step (README "Semantics" gives every rule):
// - StartMission checks the file (checker.h) and the PRE: clauses on the current variables;
//   a clause that does not hold refuses the mission, naming it. ENV: sets the execution
//   environment (LOA = local obstacle avoidance allowed); LSURV: monitors are active for the
//   whole mission; MAIN: runs command after command.
// - A command sends its execution operator to its module (Fig. 5, 1), then its monitors to the
//   SM (2-4); the control action is stored under the identifier the SM returns. The command
//   ends when its operator completes, kills its monitors and the next command runs.
// - When a monitor fires, the SM runs the reflex at once (6-1) and informs the executive (6-2).
//   A terminal monitor (its reflex holds stop) waits for the module's report that the current
//   action was interrupted (7); then the monitor is destroyed and its control action runs.
//   A non-terminal monitor's control action runs at once, beside the current action, and is
//   killed with it. Long operators of a concurrent action wait while the current action holds
//   the same resource (the wheels).
// - NEXT stops the current action, kills its monitors and runs the next command (NEXT on the last
//   command ends the mission with success). FAIL stops every action, cancels every non-static
//   monitor and runs the diagnostic step, which reports the cause and every monitor fired;
//   the mission then ends failed.
// - An operator that fails (its module reports a failure; a process reports repeatedly
//   insufficient data; a task whose ENV no longer holds is stopped) is a plan failure of the
//   command it belongs to: its actions are cancelled with its non-static monitors, its static
//   monitors stay or become active again and are evaluated at once; if one fires its control
//   action decides (Example 2: FAIL), otherwise the diagnostic step fails the mission.
// - A static monitor becomes active again after its control action ends (next datum); an
//   O-surveillance (robot operation, SetOSurveillances) is always on: re-armed after each
//   firing once its condition has been false.
//
// Deterministic and single-threaded: the caller passes `now` (s) with every call and drives
// time with Step(now); the core reads no clock. Calls made from inside a module call (a module
// reporting synchronously) are queued and handled in order after the current one.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "rpl_executive/noreils_chatila/checker.h"
#include "rpl_executive/noreils_chatila/messages.h"
#include "rpl_executive/noreils_chatila/mission.h"
#include "rpl_executive/noreils_chatila/robot_modules.h"
#include "rpl_executive/noreils_chatila/surveillance_manager.h"
#include "rpl_executive/noreils_chatila/vocabulary.h"

namespace rpl_executive::noreils_chatila {

struct ExecutiveParameters {
  /// How long a terminal monitor waits for the module's report that the current action was
  /// interrupted (Fig. 5, 7) before its control action runs anyway, s, (0, inf).
  double interruption_report_timeout_s = 2.0;
  /// Messages kept in the log (0: none, as the benchmark runs), [0, inf).
  size_t message_capacity = 100000;
};
std::vector<std::string> ValidateParameters(const ExecutiveParameters& p);

enum class MissionState { kIdle, kRunning, kSucceeded, kFailed, kAborted };
const char* MissionStateName(MissionState state);

/// A fired monitor, as a node publishes it (spott_msgs/MonitorEvent).
struct MonitorEvent {
  double time_s = 0.0;
  MonitorId id = 0;
  std::string label;      ///< "MNTR STATIC (S_us-threshold sensors-list) at file:17:5"
  std::string condition;  ///< as written
  std::string reflex;     ///< the reflex commands sent
  bool o_surveillance = false;
  bool terminal = false;
  bool is_static = false;
  std::string control;  ///< the control action as written ("(NEXT)"; "" when none)
  std::string command;  ///< the command it acts on, "smooth-move 3 points at file:15:3" ("" none)
};

/// The diagnostic step's report (section 4.2).
struct Diagnosis {
  double time_s = 0.0;
  std::string cause;  ///< "FAIL in the control action of MNTR STATIC ... at file:17:5"
  std::string where;  ///< file:line:column of the FAIL or of the failed operator
  std::vector<MonitorEvent> fired;              ///< every monitor fired in the mission
  std::vector<std::string> halted;              ///< operators the failure halted
  std::vector<std::string> cancelled_monitors;  ///< non-static monitors cancelled
  std::vector<std::string> static_monitors;     ///< static monitors that stayed active
  std::string ToString() const;
};

struct StartResult {
  bool accepted = false;
  std::vector<Diagnostic> errors;  ///< the checker's errors and warnings
  /// Why a PRE: clause refused the mission: "PRE: (eq motor ON) does not hold (motor is OFF)".
  std::string refusal;
  Location refusal_where;
};

class Executive {
 public:
  /// `modules` receives every operator (it outlives the executive). Parameters must be valid
  /// (ValidateParameters): std::invalid_argument otherwise.
  Executive(const ExecutiveParameters& parameters, const SurveillanceParameters& surveillance,
            const SonarRing& ring, RobotModules* modules);
  ~Executive();
  Executive(const Executive&) = delete;
  Executive& operator=(const Executive&) = delete;

  /// A variable served by the world (world_server's zones and paths), in mission units.
  void SetWorldVariable(const std::string& name, Value value);
  /// A zone given in metres (map frame), stored in mission units (cm).
  void SetWorldZone(const std::string& name, const std::vector<Point2>& polygon_m);
  /// The robot's state variables (motors ON/OFF; `motor` reads the same variable).
  void SetRobotState(const std::string& name, Value value);

  /// Installs the O-surveillances of `file` (its (OSURV: ...) monitors), replacing any
  /// previous ones. Returns the checker's diagnostics; nothing is installed on an error.
  std::vector<Diagnostic> SetOSurveillances(const MissionFile& file, double now);

  /// Starts a mission: refused while one runs, on a checker error, or on a PRE: clause.
  StartResult StartMission(const MissionFile& file, double now);
  /// Stops the running mission (the caller's cancel): halts every action, removes its monitors.
  void Abort(const std::string& reason, double now);

  void OnSonar(const SonarScan& scan, double now);
  void OnPose(const PoseDatum& pose, double now);
  void OnLaser(const LaserScan& scan, double now);
  void OnBattery(const BatteryDatum& battery, double now);
  /// A module's report on a long operator (Fig. 5, 7): completed, interrupted or failed.
  void OnOperatorReport(OperatorHandle handle, const OperatorReply& reply, double now);
  /// Advances time: WHILE loops run one iteration per step; interruption reports time out.
  void Step(double now);

  MissionState state() const;
  const std::string& mission_name() const;
  /// The last failure's diagnosis (valid after kFailed).
  const Diagnosis& diagnosis() const;
  /// Monitors fired in the current (or last) mission and by O-surveillances, in order.
  const std::vector<MonitorEvent>& fired() const;
  /// Fired monitors not taken yet (a node publishes them).
  std::vector<MonitorEvent> TakeMonitorEvents();
  /// A variable's value (mission, robot state or world), nullopt when none has it.
  std::optional<Value> Variable(const std::string& name) const;
  const MessageLog& log() const;
  MessageLog& log();
  const SurveillanceManager& surveillance() const;
  size_t active_monitors() const;
  /// The command the mission waits on, "smooth-move 3 points at mission.nc:14:3" ("" when none):
  /// a node's feedback.
  std::string CurrentCommand() const;
  /// The active monitors, "<id>: MNTR (S_zone IN ZONE109) at mission.nc:16:5", O-surveillances
  /// included.
  std::vector<std::string> ActiveMonitors() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rpl_executive::noreils_chatila
