// The main demo's report: what the running stack says about the world, gathered through its
// topics and services only, as a user's tool would.
#pragma once

#include <string>
#include <vector>

#include <ros/ros.h>

#include "demo_navigation.h"
#include "spott_map/local_map.h"

namespace spott_launch {

struct DemoReport {
  bool ok = false;      ///< Every step answered.
  std::string failure;  ///< Why not, when !ok.
  std::string world;
  int rooms = 0;
  int hallways = 0;
  int doors_open = 0, doors_closed = 0, doors_unknown = 0, openings = 0;
  int cad_features = 0;
  int map_width = 0, map_height = 0, map_occupied = 0;
  double map_resolution = 0.0;
  int objects_not_in_cad = 0;
  std::string start_room;
  std::vector<std::string> reachable;    ///< Rooms reachable from the start room.
  std::vector<std::string> unreachable;  ///< With the reason: "office_102 (behind closed d_102)".
  struct DoorExperiment {
    std::string door;
    bool accepted = false;
    std::string message;
    std::vector<std::string> newly_unreachable;
  };
  std::vector<DoorExperiment> door_experiments;
  std::vector<std::string> local_window;  ///< ASCII rows, north first.
  /// (m) The robot's footprint radius from robot_description, padding the window above.
  double robot_radius_m = spott_map::LocalMapParameters{}.robot_radius_m;
  double elapsed_s = 0.0;
  std::vector<std::string> stack_packages_running;  ///< Run by demo.launch.
  std::vector<std::string> stack_packages_missing;  ///< Packages of the stack not in this build.
  std::vector<std::string> stack_packages_not_run;  ///< Built, but demo.launch does not run them.
  NavigationReport navigation;
  /// The simulator's scheduled faults as they happened (/sim/faults), in order.
  struct Fault {
    double sim_time_s = 0.0;
    std::string kind;  ///< The schedule's kind: kidnap, door, sensor, ...
    std::string what;  ///< "door d_lab_w closed", with the refusal when refused
    bool applied = false;
  };
  std::vector<Fault> faults;
};

struct DemoOptions {
  std::string world_file;  ///< What a scenario knows but the stack does not (start, objects).
  std::vector<std::string> doors_to_close;
  double timeout_s = 30.0;           ///< For each answer of the running nodes (s).
  std::vector<std::string> running;  ///< Stack packages demo.launch runs (for the report).
  std::vector<std::string> goals;    ///< Places to drive to through Navigate, in order.
  /// Task commands for the TR+ controller (/task), in order; they replace `goals`.
  std::vector<std::string> tasks;
  /// Missions for rpl_executive (/mission), in order, from a scenario file; they replace both.
  std::vector<MissionSpec> missions;
  double leg_timeout_s = 300.0;    ///< Simulated time allowed per leg (s).
  double goal_tolerance_m = 0.25;  ///< Asked of Navigate and judged on ground truth (m).
  /// A recorder (rosbag record) takes the legs' goals: the first leg waits until it is connected.
  bool wait_for_recorder = false;
  /// No localization_status (localization truth or odometry): the estimate judged against the
  /// ground truth is tf's map -> base_link, sampled at 5 Hz.
  bool estimate_from_tf = false;
};

/// Runs the demo against the running stack: reads the world server's latched topics, closes
/// each door of `doors_to_close` in turn through its service and reports reachability, then
/// reopens them; then gives the TR+ controller each of `tasks` (RunTasks), or drives the robot
/// to each of `goals` through Navigate (RunNavigation).
DemoReport RunDemo(ros::NodeHandle& nh, const DemoOptions& options);
/// RunDemo without the fault log.
DemoReport RunDemoSteps(ros::NodeHandle& nh, const DemoOptions& options);

/// The report as a user reads it.
std::string FormatReport(const DemoReport& report);

/// The report as JSON (./spott run writes it beside the bag): outcome, per-leg time, path,
/// bumper contacts, clearance, localization error against the ground truth, the faults and the
/// leg each fell in. `scenario` names the scenario file ("" = none).
std::string FormatReportJson(const DemoReport& report, const std::string& scenario);

}  // namespace spott_launch
