// One leg of a run (a task or a place) measured on the simulator's ground truth, and judged on
// it: what the demo's subscribers feed live and bag_report feeds from a recorded bag, so that
// both give the same figures. ROS-free.
#pragma once

#include <deque>
#include <limits>
#include <string>
#include <vector>

#include "spott_launch/scenario.h"
#include "spott_map/world.h"

namespace spott_launch {

struct NavigationLeg {
  std::string goal;  ///< Place name from the world file (RunNavigation).
  /// RunTasks: the task command sent to /task, what the TR+ controller made of it, the TR+
  /// rules that fired in order, its outcome and the features it had added to the map.
  std::string task;
  std::string interpretation;
  std::vector<std::string> trace;
  std::string task_outcome;  ///< "reached", "failed: ...", "rejected: ...", "timed out ..."
  std::vector<std::string> features_added;  ///< During this leg.
  /// RunTasks, `find`: what the controller recognised as the object (label, centre in the map);
  /// empty label when nothing.
  std::string found_label;
  spott_map::Vec2 found_at{0.0, 0.0};
  double found_nearest_m = 0.0;  ///< From found_at to the world's nearest object of that kind.
  /// RunMissions: the mission's name, what rpl_executive answered ("completed", "failed: ..."),
  /// and the conditions of the surveillance monitors that fired, in order.
  std::string mission;
  std::string mission_outcome;
  std::vector<std::string> monitors_fired;
  bool has_target = true;   ///< RunTasks: the task had a goal point (`target`).
  spott_map::Pose2 target;  ///< (m, rad) in the map frame.
  /// "reached" only when Navigate succeeded, the robot really is within the goal tolerance of
  /// the target (ground truth) and no bumper was pressed; else "not reached: <why>".
  std::string outcome;
  std::string navigate_outcome;  ///< What Navigate said: "succeeded", "unreachable: ..." ...
  bool reached = false;
  std::string global_path;  ///< Rooms and doors of the global plan, "hall_w -> d_lab_w -> lab".
  std::vector<std::string> recoveries;  ///< RECOVERING episodes, each with its note.
  double start_sim_s = 0.0;             ///< Simulated time the leg began (s since the clock's 0).
  double sim_time_s = 0.0;              ///< Simulated time the leg took (s).
  double wall_time_s = 0.0;             ///< Wall time the leg took (s).
  double path_length_m = 0.0;           ///< Distance the robot really drove (ground truth, m).
  double final_error_m = 0.0;           ///< Ground-truth distance from the target at the end (m).
  spott_map::Vec2 final_position{0.0, 0.0};  ///< Ground truth at the end (m, map).
  double min_wall_distance_m = 0.0;  ///< Closest approach of the robot's centre to a wall or
                                     ///< object of the simulated world (m).
  int bumper_hits = 0;               ///< Bumper messages with a pressed segment.
  /// /sim/contact messages with the body touching a solid (ground truth: every robot, with or
  /// without a bumper, whatever the bumper's faults).
  int body_contacts = 0;
  /// Localization (markov_localization's status against the ground truth); 0 estimates when
  /// the stack runs on the simulator's map->odom.
  int estimates = 0;
  double mean_position_error_m = 0.0;
  double max_position_error_m = 0.0;
  double mean_heading_error_rad = 0.0;
  double max_heading_error_rad = 0.0;
  int lost_reports = 0;  ///< Statuses that said lost.
  /// When (simulated s) the localization began to say lost, and a contact began (the bumper
  /// pressed or the body touching, whichever said it first): a fault campaign measures
  /// detection latency and collisions against a fault's time.
  std::vector<double> lost_onsets_s;
  std::vector<double> contact_onsets_s;
};

struct NavigationReport {
  bool by_task = false;                     ///< RunTasks (else RunNavigation or RunMissions).
  bool by_mission = false;                  ///< RunMissions.
  bool ran = false;                         ///< The navigation stack was up and took goals.
  std::string skipped;                      ///< Why not, when !ran.
  double requested_real_time_factor = 0.0;  ///< The simulator's ~real_time_factor (0 = unknown).
  /// Whose estimate the legs' localization error is: markov_localization's statuses, or tf's
  /// map -> base_link for a stack without them (demo_report ~estimate_from_tf).
  std::string estimate_source = "markov_localization";
  std::vector<NavigationLeg> legs;
};

/// What the simulator says during a leg: ground truth, bumpers and the localization's statuses
/// against the truth. Times are simulated seconds.
class LegMetrics {
 public:
  explicit LegMetrics(const spott_map::World& world) : world_(&world) {}

  /// A new leg begins at `t`: the sums start again; the last ground truth is kept (the path
  /// continues from it). Messages count by their stamps, not by when they arrive, so that a
  /// live run and its bag give the same figures: from `t` to the end set by EndAt.
  void Reset(double t);
  /// The leg's window closes at `t` (the result's time plus kSettleS): later stamps are ignored.
  void EndAt(double t) { leg_end_ = t; }
  void OnTruth(double t, double x, double y, double yaw);
  /// A localization status stamped `t`, compared with the ground truth at `t` (interpolated
  /// between the samples around it; the status comes some time after the reading it was
  /// computed from) once the truth has passed `t`: the pairing does not depend on the order the
  /// two topics arrive in, nor much on a dropped truth message.
  void OnStatus(double t, double estimate_x, double estimate_y, double estimate_yaw, bool lost);
  void OnBumper(double t, bool any_pressed);
  /// The simulator's /sim/contact: the body touches a solid (ground truth).
  void OnBodyContact(double t, bool touching);

  /// After a leg's result the last ground truth and bumper messages still count for this long
  /// (simulated s): the robot stops.
  static constexpr double kSettleS = 0.8;
  /// How late (simulated s) a status may come and still meet the truth of its stamp.
  static constexpr double kTruthHistoryS = 10.0;

  bool has_pose() const { return have_pose_; }
  spott_map::Pose2 pose() const { return {position_.x(), position_.y(), yaw_}; }
  double leg_start() const { return leg_start_; }

  /// Copies the leg's figures into `leg`: path, final position and error from `target`,
  /// clearance, bumper contacts, localization errors (statuses still waiting for a later
  /// truth are compared with the newest one).
  void Measure(const spott_map::Vec2& target, NavigationLeg& leg);

 private:
  struct Sample {
    double t;
    spott_map::Vec2 position;
    double yaw;
  };
  struct Status {
    double t, x, y, yaw;
    bool lost;
  };
  /// Compares the waiting statuses whose time the truth has reached (all: every one).
  void Evaluate(bool all);
  const spott_map::World* world_;
  bool have_pose_ = false;
  spott_map::Vec2 position_{0.0, 0.0};
  double yaw_ = 0.0;
  double leg_start_ = 0.0;
  double leg_end_ = std::numeric_limits<double>::infinity();
  double path_length_m_ = 0.0;
  double min_wall_distance_m_ = std::numeric_limits<double>::infinity();
  int bumper_hits_ = 0, body_contacts_ = 0, estimates_ = 0, lost_reports_ = 0;
  bool lost_ = false, pressed_ = false;  ///< The last status / bumper message in the leg.
  bool touching_ = false;                ///< The last /sim/contact message in the leg.
  std::vector<double> lost_onsets_s_, contact_onsets_s_;
  double sum_position_error_m_ = 0.0, max_position_error_m_ = 0.0;
  double sum_heading_error_rad_ = 0.0, max_heading_error_rad_ = 0.0;
  std::deque<Sample> history_;  ///< The last kTruthHistoryS of ground truth.
  std::deque<Status> pending_;  ///< Statuses newer than the newest truth.
};

/// Closest distance from `p` to a wall or an object footprint of `world` (m).
double DistanceToNearestSolid(const spott_map::World& world, const spott_map::Vec2& p);

/// The leg's verdict, on the ground truth and never on the stack's belief: reached when whoever
/// drove says so (`refusal` empty), the robot really is at the goal (`off_goal` empty) and no
/// bumper was pressed nor did the body touch anything. Sets leg.outcome and leg.reached.
void JudgeLeg(const std::string& refusal, const std::string& off_goal, NavigationLeg& leg);

/// Why a Navigate leg to a place is off its goal ("" = within `tolerance_m`; leg measured).
std::string OffPlace(const NavigationLeg& leg, double tolerance_m);

/// A mission leg's name and goal from its scenario entry (a place of `world` or a point; none:
/// `has_target` false).
void SetMissionTarget(const MissionSpec& spec, const spott_map::World& world, NavigationLeg& leg);

/// Why a mission leg that went as its scenario says is still not done: the robot is not within
/// `tolerance_m` of the mission's goal (ground truth). "" when it is, or the mission has none.
std::string OffMissionGoal(const NavigationLeg& leg, double tolerance_m);

/// JudgeLeg for a mission: `mismatch` (MissionMismatch, or why it never ended), then its goal
/// and the contacts; a leg that passes is "as the scenario says".
void JudgeMissionLeg(const std::string& mismatch, double tolerance_m, NavigationLeg& leg);

/// Why a mission did not go as its scenario says ("" = as said): the executive's outcome
/// (`outcome`, with `message`), the monitors that fired (their conditions, in order) and the
/// text the message must contain.
std::string MissionMismatch(const MissionSpec& spec, const std::string& outcome,
                            const std::string& message, const std::vector<std::string>& fired);

/// A `find` is judged by the object the controller reports: a world object of the same kind
/// (spott_map::ToString of its kind = the label) whose footprint lies within this of the reported
/// centre (issue 19: "a chair within 0.5 m of a real one"; a 3 m table found at one end is
/// found, as recognition_score.py counts it).
constexpr double kFoundToleranceM = 0.5;

/// The distance from `at` to the footprint of `world`'s nearest object whose kind is `label` (0
/// inside it; infinity when the world has none).
double NearestObjectOfKind(const spott_map::World& world, const std::string& label,
                           const spott_map::Vec2& at);

/// "" when `leg`'s found object matches a world object (kFoundToleranceM), else why not.
std::string OffFoundObject(const spott_map::World& world, const NavigationLeg& leg);

/// A tele-operation (`go forward`, `go east`, ...; SPOTT's intelligent tele-operation, which
/// has no goal) counts when the robot went at least this far the way it was sent (m) and
/// stopped (the controller's "stopped": before a known structure or on the operator's word);
/// contacts are judged as for every leg.
constexpr double kTeleopAdvanceM = 0.5;

/// "" when `leg` ended at least kTeleopAdvanceM from `start` along `direction` (map frame, rad),
/// else why not.
std::string OffTeleoperation(const spott_map::Pose2& start, double direction,
                             const NavigationLeg& leg);

/// Why a task leg is off its goal ("" = in the command's goal region, interpreted on `world`'s
/// CAD map from where the robot really started, or within `tolerance_m` of the goal point the
/// controller sent; a find by OffFoundObject, a tele-operation by OffTeleoperation; leg
/// measured, target set from the controller's result).
std::string OffTaskGoal(const spott_map::World& world, const std::string& command,
                        const spott_map::Pose2& start, const NavigationLeg& leg,
                        double tolerance_m);

}  // namespace spott_launch
