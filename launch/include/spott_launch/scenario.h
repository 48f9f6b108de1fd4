// A scenario: one run of a whole stack as a file (issue 20). World, robot, start, seed, the
// tasks (SPOTT task commands for the TR+ controller), the places to drive to (Navigate) or the
// missions (rpl_executive: RPL plans, Noreils-Chatila missions), the simulator's timed faults
// and the limits, read strictly: every error names the file, line and
// column. ROS-free; `scenario_tool` turns a scenario into roslaunch arguments and parameter
// files, `./spott run SCENARIO` runs it. The format is in spott_launch/README.md, "Scenarios".
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "robot_sim/fault_events.h"
#include "spott_map/source_location.h"
#include "spott_map/world.h"

namespace spott_launch {

/// A string of the file with where it stands (for errors found after parsing).
struct Located {
  std::string text;
  spott_map::SourceLocation where;
  int quote = 0;  ///< 1 when the scalar was quoted: its text starts one column later.
};

/// A mission for rpl_executive (/mission): a shipped RPL plan or Noreils-Chatila mission, and
/// what the run must show for it to count as done as the paper says.
struct MissionSpec {
  Located name;                       ///< plans/NAME.rpl or missions/NAME.nc of rpl_executive.
  std::string language = "rpl";       ///< rpl | noreils_chatila
  std::vector<std::string> bindings;  ///< RPL DEFVAR overrides, "NAME value".
  Located goal_place;                 ///< A place the robot must end at ("" none) ...
  std::optional<spott_map::Vec2> goal_point;  ///< ... or a point (m, map); judged on the truth.
  std::string outcome = "completed";          ///< The executive's outcome expected.
  /// The surveillance monitors expected to fire, their conditions in order; none = not judged.
  std::optional<std::vector<std::string>> monitors;
  /// Monitors that must fire in this order, others allowed before, between and after them (a
  /// static monitor that re-fires while the robot passes its obstacle); empty = not judged.
  std::vector<std::string> monitors_include;
  /// A text the executive's result message must contain ("" = not judged).
  std::string message_contains;
};

struct Scenario {
  std::string description;
  Located world;                          ///< A world of spott_worlds (name, no path).
  Located robot;                          ///< "" = the world's robot (stack.launch).
  std::optional<spott_map::Pose2> start;  ///< none = the world's robot_start (m, rad).
  spott_map::SourceLocation start_where;
  int seed = 1;                         ///< The simulator's noise seed.
  double real_time_factor = 4.0;        ///< Simulated s per wall s (0.1 .. 20).
  std::string localization = "markov";  ///< markov | truth | odometry (dead reckoning)
  bool a_priori_map = true;  ///< false: the map database starts empty (SPOTT's Experiment 1).
  /// The localization starts from a uniform belief: it has the map, not the robot's place
  /// (Beetz et al. 2.3, Fig. 2: global localization, then the errand). Markov only.
  bool global_localization = false;
  std::vector<Located> tasks;           ///< Task commands for the TR+ controller, or
  std::vector<Located> goals;           ///< places driven to through Navigate, or
  std::vector<MissionSpec> missions;    ///< missions for rpl_executive.
  std::vector<Located> doors_to_close;  ///< The demo's reachability experiment.
  /// TR+ subroutines switched off (tr_plus_controller ~subroutines_off): a sensor left out,
  /// e.g. MAP_OBJECTS_WITH_QUADRIS for a map from the sonar alone. Tasks only.
  std::vector<Located> subroutines_off;
  /// MAP_OBJECTS_WITH_SONAR's dense turret scan every this many simulated s (tr_plus_controller
  /// ~sonar_scan/period_s; 0 none); negative: the controller's own. Tasks only.
  double sonar_scan_period_s = -1.0;
  double leg_timeout_s = 240.0;    ///< Simulated s per task or goal.
  double goal_tolerance_m = 0.25;  ///< Judged on the ground truth (m).
  double time_limit_s = 0.0;       ///< Simulated s for the whole run (0 = legs x timeout).
  std::vector<robot_sim::FaultEvent> faults;  ///< Sorted by time (simulated s since start).
  std::string faults_yaml;  ///< The `faults:` list as robot_sim reads it ("" none).

  /// "tr_plus" when the scenario gives tasks, "none" when it gives goals or missions.
  std::string Controller() const { return tasks.empty() ? "none" : "tr_plus"; }
  /// "rpl" (rpl_executive serving /mission) when the scenario gives missions, else "none".
  std::string Executive() const { return missions.empty() ? "none" : "rpl"; }
  /// The time limit in effect: time_limit_s, or every leg's timeout plus a minute of start-up.
  double EffectiveTimeLimit() const;
};

struct ScenarioResult {
  std::optional<Scenario> scenario;            ///< Set only when there are no errors.
  std::vector<spott_map::SourceError> errors;  ///< "file:line:column: message"
  bool ok() const { return scenario.has_value(); }
};

/// Parses scenario text; `file` names it in errors. Checks what the file alone can tell: keys,
/// types, ranges, task-command syntax (with the column inside the string), the fault list.
ScenarioResult ParseScenario(const std::string& text, const std::string& file);

/// What only the world can tell: goals and faults' doors name places and doors of `world`,
/// the start and an absolute kidnap lie inside a room, doors_to_close are doors. Empty = fine.
std::vector<spott_map::SourceError> CheckAgainstWorld(const Scenario& scenario,
                                                      const spott_map::World& world);

/// roslaunch arguments of spott_launch/demo.launch for the scenario, "name:=value" each.
std::vector<std::string> LaunchArguments(const Scenario& scenario);

/// The demo_report parameters (the keys of config/demo_<world>.yaml) as YAML text; a scenario
/// with missions names its own file (`missions_file`), which demo_report reads with
/// ParseScenario.
std::string DemoParametersYaml(const Scenario& scenario, const std::string& file = "");

/// "a, b, c": the names NAME of the files NAME<ext> in `dir`, sorted ("" when there are none).
std::string FileStems(const std::string& dir, const std::string& ext);

/// Errors for missions whose NAME has no file in `rpl_dir` (rpl_executive's directory:
/// plans/NAME.rpl, missions/NAME.nc), listing the shipped ones.
std::vector<spott_map::SourceError> CheckMissionNames(const Scenario& scenario,
                                                      const std::string& rpl_dir);

}  // namespace spott_launch
