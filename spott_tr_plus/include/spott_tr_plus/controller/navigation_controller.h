// SPOTT's behavioural controller (Zelek and Levine, section III-C, Figs. 3-13) on the robot:
// the TR+ navigation program (programs/spott_navigation.tr) run by the interpreter, its
// conditions and actions bound in C++ through the Registry. ROS-free: the node feeds it the
// robot's pose, the sensors, the map database's messages and Navigate's answers, and carries out
// what it asks through ControllerIo (Navigate goals, velocity commands on the arbiter's inputs,
// the wheels valve, map updates, task feedback and results). Every call takes the caller's
// clock; the controller never reads one.
//
// What the controller owns (README "The controller on the robot"):
// - Tasks (III-B): a command is parsed (a malformed one is refused with its column), and once
//   the robot has stopped (a new task preempts the running one: the robot stops first) it is
//   interpreted from the robot's pose against the map database (goal regions in the free,
//   reachable space of the right room; direction biases; speeds to speed modes).
// - The map database's sensed part (III-A): sonar and QUADRIS features that are not already in
//   the map, bumper and infrared contacts, door states; each change is applied to its own copy
//   and sent to every other copy (MapChange -> spott_msgs/MapUpdate).
// - The reflexes (Figs. 7-8): take the wheels as source `reflex`, move away, hand them back,
//   always from within a TR+ rule (move_away_from).
// - Intelligent tele-operation (VI-A) on source `teleop`.
// - LOCALIZE_THE_ROBOT (Fig. 4): the pose of markov_localization taken into the world model at
//   the rates of footnote 19 (time, distance travelled, predefined places).
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "spott_map/map_database.h"
#include "spott_tr_plus/ast.h"
#include "spott_tr_plus/controller/motions.h"
#include "spott_tr_plus/controller/object_recognition.h"
#include "spott_tr_plus/controller/sensor_mapper.h"
#include "spott_tr_plus/controller/sonar_scan.h"
#include "spott_tr_plus/diagnostic.h"
#include "spott_tr_plus/interpreter.h"
#include "spott_tr_plus/task_command.h"

namespace spott_tr_plus::controller {

/// A goal for the stack's Navigate action (spott_msgs/Navigate).
struct NavigateGoal {
  std::uint64_t seq = 0;  ///< Echoed by NavigateDone / NavigateFeedback.
  double x = 0, y = 0;    ///< Target (m, map).
  double tolerance_m = 0.25;
  int speed_mode = 1;  ///< spott_msgs/Navigate SLOWLY 0, NORMAL 1, QUICKLY 2.
  enum class Bias { kHeading, kToward, kAway, kVia, kAround };
  Bias bias = Bias::kHeading;
  std::optional<double> heading;  ///< kHeading (rad, map); none = no bias.
  double bias_x = 0, bias_y = 0, bias_radius = 0, bias_sense = 1;
};

/// How a Navigate goal ended (spott_msgs/NavigateResult outcome).
enum class NavigateOutcome { kSucceeded = 0, kUnreachable = 1, kPreempted = 2, kFailed = 3 };

/// Navigate's FAILED "not localized: ..." (the harmonic planner arrived on the estimate while the
/// localization said lost, and it stayed lost for navigate/lost_timeout_s): where the robot is,
/// is not known, so the way there did not fail.
bool NavigateNotLocalized(NavigateOutcome outcome, const std::string& reason);

/// A change of the map database for every other copy (spott_msgs/MapUpdate).
struct MapChange {
  std::vector<spott_map::MapFeature> added;
  std::vector<std::pair<std::string, spott_map::DoorState>> doors;
  std::vector<std::string> removed;  ///< Sensed features taken back (ids).
  bool retraction = false;  ///< Takes back what was sensed on an estimate that then jumped.
};

struct TaskFeedback {
  std::int64_t id = 0;
  std::string state;        ///< parsing | interpreting | driving | searching | teleoperating |
                            ///< waiting for the localization
  std::string firing_rule;  ///< "PROGRAM[index]: condition -> action" (index 0-based)
  double distance_remaining = 0;  ///< (m); NaN when unknown
  Pose2 pose;
};

struct TaskResult {
  std::int64_t id = 0;
  bool success = false;
  std::string outcome;  ///< reached | found | stopped | failed | rejected | preempted
  std::string message;
  Pose2 final_pose;
  std::string interpretation;      ///< What the command was taken to mean ("" if never).
  std::optional<Vec2> goal;        ///< The goal point sent to Navigate (map), if any.
  std::vector<std::string> trace;  ///< The firing rules in order (compact TR trace).
  /// FIND: the feature recognised as the object (its id, label, centre and height).
  std::optional<spott_map::MapFeature> found;
};

/// What the controller does to the world.
class ControllerIo {
 public:
  virtual ~ControllerIo() = default;
  virtual void SendNavigate(const NavigateGoal& goal) = 0;
  virtual void CancelNavigate() = 0;
  /// cmd_vel_arbiter's take_wheels / release_wheels for `source`.
  virtual void TakeWheels(const std::string& source) = 0;
  virtual void ReleaseWheels(const std::string& source) = 0;
  /// A velocity command on /cmd_vel/<source>.
  virtual void Drive(const std::string& source, const Velocity& v) = 0;
  virtual void SendMapUpdate(const MapChange& change) = 0;
  /// The pan-tilt heads' scanning pattern (Fig. 10): "room" or "hallway".
  virtual void SetPtuPattern(const std::string& pattern) = 0;
  /// Turns the sensor turret to `yaw` (rad from the base's heading): MAP_OBJECTS_WITH_SONAR's
  /// dense scan (sonar_scan.h).
  virtual void PointTurret(double yaw) = 0;
  virtual void PublishTaskFeedback(const TaskFeedback& feedback) = 0;
  virtual void TaskFinished(const TaskResult& result) = 0;
  /// Starts the localization's active localization (Beetz et al. 2.2, markov_localization's
  /// ActiveLocalize) for at most `timeout_s`; false when there is none (AMCL, dead reckoning).
  /// Its end comes back through NavigationController::ActiveLocalizeDone.
  virtual bool StartActiveLocalize(double timeout_s) = 0;
  virtual void CancelActiveLocalize() = 0;
};

struct LocalizationParameters {
  double period_s = 10.0;        ///< Localize at least this often (s), > 0 (footnote 19: time).
  double distance_m = 2.0;       ///< ... and every this far travelled (m), > 0 (distance).
  double place_radius_m = 0.75;  ///< ... and within this of a localization place (m), >= 0.
  double max_age_s = 2.0;        ///< A localization status older than this is stale (s), > 0.
  /// The estimate jumped: map->odom (the pose against odometry) changed by more than this
  /// between two poses (m, > 0; rad, > 0). What was sensed shortly before was placed with the
  /// wrong pose, and what is sensed next with one that may still settle.
  double jump_m = 0.3;
  double jump_rad = 0.35;
  /// Sensed features added this long before a jump are removed (s), >= 0 ...
  double retract_s = 10.0;
  /// ... but those this close to the robot (in the frame they were placed in: their true
  /// offset from it) are moved with the jump instead (m), >= 0: taken back, an obstacle just
  /// ahead went unmapped for settle_s and a Fig. 18 run drove into the lab's partition.
  double keep_radius_m = 1.0;
  /// Nothing is mapped for this long after a jump (s), >= 0.
  double settle_s = 3.0;
};

struct TaskParameters {
  double goal_tolerance_m = 0.25;  ///< Asked of Navigate (m), > 0.
  int navigate_retries = 2;        ///< Navigate failures retried before the task fails, >= 0.
  double retry_delay_s = 2.0;      ///< Wait before a retry (s), >= 0.
  /// Before a retry, the features the controller sensed within this distance of the robot are
  /// taken back (m), >= 0; 0: none. move_base's clearing recovery: echoes placed under a wrong
  /// estimate, or a door jamb's corner read on a sonar cone's axis, may be what cuts the robot
  /// off; what is really there the sensors put back. Bumper contacts stay until the last retry:
  /// only another collision would put them back (teleop_bumper: cleared at once, the robot hit
  /// the same box face again). When the goal then still cannot be fitted in the free space,
  /// every sensed feature is taken back (move_base's aggressive reset) before the task fails.
  double clear_radius_m = 1.5;
  /// A GO task is done early (before Navigate's success) only when the estimate lies this far
  /// inside its goal region (m), >= 0: the estimate is some cm off, and a robot stopped at the
  /// region's edge on its estimate was 0.36-0.37 m from a point whose region was 0.3 m.
  double arrival_margin_m = 0.1;
  /// A GO is reached only on a trusted estimate (markov_localization certain, fresh, settled
  /// after a jump): Navigate's success while it is not is checked again once it is, and counts
  /// as a Navigate failure after this long (s), > 0; so is Navigate's FAILED "not localized". In
  /// cim_office's lab a relocalization once put the estimate 12 m away and the task was reported
  /// reached there.
  double localized_wait_s = 30.0;
  /// Navigate's "not localized" starts the localization's active localization (it drives to
  /// where the belief's modes can be told apart) at most this often per task, >= 0; 0: never.
  /// Standing, the B21 in bonn_kidnap stayed lost after the unseen 70-degree turn in 2 of 2 runs.
  int active_localizations = 2;
  double active_localize_timeout_s = 120.0;  ///< Longest active localization (s), > 0.
  double stop_speed_mps = 0.02;    ///< Stopped: slower than this (m/s, and 5x in rad/s), > 0.
  double stop_timeout_s = 3.0;     ///< Longest wait for the robot to stop (s), > 0.
  double pose_timeout_s = 60.0;    ///< Longest wait for a pose before interpreting (s), > 0.
  double search_turn_rps = 0.4;    ///< Looking around a room (rad/s), > 0.
  double obstacle_ahead_m = 0.7;   ///< RANDOM_SEARCH: an echo ahead this close (m), > 0.
  double feedback_period_s = 0.5;  ///< Feedback at least this often while a task runs (s), > 0.
};

struct ControllerParameters {
  double robot_radius_m = 0.2285;           ///< From the robot description (not a parameter).
  double max_localization_error_m = 0.075;  ///< Padding = radius + this (m), >= 0.
  double max_linear_mps = 0.5;              ///< The robot's drive limits (m/s), > 0.
  double max_angular_rps = 0.79;            ///< (rad/s), > 0.
  int max_call_depth = 32;                  ///< Interpreter recursion guard, >= 1.
  /// Subroutines of the program switched off (InterpreterOptions::off_subroutines): a robot
  /// without their sensors (the B-12: BUMPER_CHECK, INFRARED_CHECK, MAP_OBJECTS_WITH_QUADRIS,
  /// CONTROL_THE_PTU).
  std::vector<std::string> subroutines_off;
  unsigned seed = 1;  ///< RANDOM_SEARCH's headings.
  MappingParameters mapping;
  SonarScanParameters sonar_scan;
  DoorSensingParameters doors;
  RecognitionParameters recognition;
  ReflexParameters reflex;
  TeleopParameters teleop;
  LocalizationParameters localization;
  TaskParameters tasks;
  TaskInterpretationParameters interpretation;
};

/// Every violation, named as in config/tr_plus_controller.yaml ("mapping/cell_m must be ...").
std::vector<std::string> ValidateParameters(const ControllerParameters& p);

class NavigationController {
 public:
  /// Checks `program`, binds every condition and action it declares to the controller (a name
  /// the controller does not know is an error at its location) and prepares to run `main_name`.
  static std::unique_ptr<NavigationController> Create(const ProgramFile& program,
                                                      const ControllerParameters& params,
                                                      ControllerIo* io,
                                                      std::vector<Diagnostic>* diagnostics,
                                                      const std::string& main_name = "");
  ~NavigationController();

  void Start(double now);

  // --- The map database's messages (world_server: room_door_graph, map_features, world_places)
  void SetGraph(const spott_map::RoomDoorGraph& graph, double now);
  void SetFeatures(const std::vector<spott_map::MapFeature>& features, double now);
  void SetPlaces(const std::vector<spott_map::Place>& places);

  // --- The robot
  /// The localization's estimate (map -> base_link), with the odometry (odom -> base_link) it
  /// was composed with when known (else the last SetOdometry's is compared with it).
  void SetPose(const Pose2& pose, double now,
               const std::optional<Pose2>& odom_at_pose = std::nullopt);
  /// Odometry: the pose in the odom frame and the speeds (m/s, rad/s).
  void SetOdometry(const Pose2& odom, double linear_mps, double angular_rps, double now);
  /// markov_localization's status: certain (TRACKING and not lost).
  void SetLocalization(bool certain, double now);
  void Sonar(const RangeRing& ring, double now);
  void Infrared(const RangeRing& ring, double now);
  /// A QUADRIS horizontal profile: its points (base frame) measured from `origin` (base frame).
  void RangeProfile(const Vec2& origin, const std::vector<Vec2>& points, double now);
  /// Any QUADRIS profile for recognition: its samples and `origin` in the base frame (3-D).
  void RecognitionProfile(const Vec3& origin, const std::vector<ProfileSample>& samples,
                          bool vertical, double now);
  /// The pressed bumper segments as angles about +z from the robot's +x (rad); empty: none.
  void Bumper(const std::vector<double>& pressed_angles_rad, double now);

  // --- Navigate's answers
  void NavigateFeedback(std::uint64_t seq, double distance_remaining_m, double now);
  void NavigateDone(std::uint64_t seq, NavigateOutcome outcome, const std::string& reason,
                    double now);
  /// The end of an active localization started through ControllerIo::StartActiveLocalize.
  void ActiveLocalizeDone(bool success, const std::string& reason, double now);

  // --- Tasks
  struct Acceptance {
    bool accepted = false;
    std::string message;  ///< Refused: "task:1:COLUMN: expected ..., found ...".
  };
  /// A new task command. A malformed one is refused (the running task goes on); an accepted
  /// one preempts the running task (finished as "preempted"), waits for the robot to stop,
  /// then is interpreted from the robot's pose.
  Acceptance StartTask(std::int64_t id, const std::string& command, double now);
  /// Cancels task `id` (finished as "preempted"; the robot stops).
  void CancelTask(std::int64_t id, double now);
  /// Parses and interprets `command` from the robot's pose against the map, without running it
  /// (~parse_task). False with the located errors in `message`.
  bool InterpretOnly(const std::string& command, std::string* interpretation,
                     std::string* message) const;

  /// The motions (reflexes, tele-operation, searches), the waits and the feedback. Call at the
  /// controller's tick rate; Advance() at NextWakeTime() for the conditions' frequencies.
  void Tick(double now);
  void Advance(double now);
  double NextWakeTime() const;

  InterpreterState State() const;
  const ProgramFile& program() const;
  const std::string& main_name() const;
  /// The rule that fired last with an action ("" before any): "PROGRAM[index]: cond -> action".
  const std::string& firing_rule() const { return firing_rule_; }
  const spott_map::MapDatabase& map() const { return db_; }
  const std::optional<Pose2>& pose() const { return pose_; }
  /// An object recognition needs a head turned to (ObjectRecognizer::ToLookAt), if any.
  std::optional<LookTarget> ObjectToLookAt() const {
    return pose_ ? recognizer_.ToLookAt(pose_->Position()) : std::nullopt;
  }
  /// The sensor turret's target (rad from the base's heading): 0 but during a dense sonar scan.
  double turret_target() const { return sonar_scan_.target(); }
  int sonar_scans() const { return sonar_scan_.scans_done(); }
  /// Features the controller added to the map so far (ids: sonar_N, quadris_N, contact_N).
  const std::vector<std::string>& added_features() const { return added_ids_; }
  int localization_fixes() const { return fixes_; }
  /// Jumps of the estimate seen so far (each retracted what was sensed just before it).
  int estimate_jumps() const { return estimate_jumps_; }
  bool has_task() const { return task_ != nullptr; }

 private:
  struct Task;
  struct Reflex;
  struct Drive;
  NavigationController(const ControllerParameters& params, ControllerIo* io);
  void Bind(Registry& registry);
  void Settle(double now);
  void Complete(Ticket ticket, bool ok) { completions_.emplace_back(ticket, ok); }
  void Finish(const std::string& outcome, bool success, const std::string& message, double now,
              bool defer = false);
  /// A change with `retraction` set is not itself retracted later.
  void ApplyChange(MapChange change, double now);
  /// `before`: the robot's pose now by the correction before the jump; `after`: the new one.
  void EstimateJumped(const Pose2& before, const Pose2& after, double now);
  /// Takes back the sensed features within `radius` of `at`, bumper contacts only if
  /// `contacts`; returns how many.
  int ClearSensedNear(const Vec2& at, double radius, bool contacts, double now);
  /// The estimate may be acted on (sensed features placed with it, a GO judged reached on it):
  /// certain, fresh and settled after the last jump.
  bool PoseTrusted(double now) const;
  /// A Navigate failure of the task's goal: retried after retry_delay_s, or the task fails.
  void NavigateFailed(Ticket owner, const std::string& message, double now);
  /// See `unconfirmed_`.
  void ConfirmArrival(double now);
  /// Cancels the active localization `unconfirmed_` started, if it runs.
  void StopActiveLocalize();
  void MapChanged();
  void UpdateFiringRule();
  void SendFeedback(double now);
  bool Interpret(Task& task, double now, std::string* why);
  bool SendGoalFor(Ticket ticket, const GoalRegion& goal, const TaskInterpretation& in, Speed speed,
                   double now);
  Task* TaskByStatus(const Value& status) const;
  /// FIND: a feature labelled as `t`'s object within the sensors' reach of the robot.
  const spott_map::MapFeature* FoundObject(const Task* t) const;
  std::vector<Vec2> NewObstaclesNear(const Vec2& at, double radius) const;
  bool Localized(double now) const;
  bool InGoalRegion(const GoalRegion& region, const Vec2& p) const;
  void ForgetPlacesLeft();
  void StopDrive(Ticket ticket);
  void DriveMotions(double now);
  std::string PointToText(const Vec2& p) const;

  ControllerParameters params_;
  ControllerIo* io_;
  std::unique_ptr<Interpreter> interpreter_;
  spott_map::MapDatabase db_;
  bool have_graph_ = false, have_features_ = false;
  bool mapless_ = false;  ///< The served map has no rooms: no a priori map (SPOTT's Experiment 1).
  std::vector<spott_map::Place> places_;
  SensorMapper sonar_mapper_, quadris_mapper_, infrared_mapper_;
  SonarScan sonar_scan_;
  double sonar_wanted_at_ = -1e300;  ///< MAP_OBJECTS_WITH_SONAR's condition last evaluated (s).
  ObjectRecognizer recognizer_;
  bool profiles_seen_ = false;  ///< QUADRIS profiles arrived: they sense the doors.
  KnownStructure known_;
  std::map<int, SensedBatch> batches_;
  int next_batch_ = 0;
  std::map<std::string, int> next_id_;
  std::vector<std::string> added_ids_;
  std::deque<std::pair<double, std::string>> recent_ids_;  ///< (time added, id), for retraction.
  /// Door states the controller changed (time, door, state before, the robot's position by
  /// the estimate then), for retraction alike.
  struct DoorChange {
    double time;
    std::string door;
    spott_map::DoorState before;
    std::optional<Vec2> robot;
  };
  std::deque<DoorChange> recent_doors_;
  /// After an estimate jump that moves what was sensed by `move`: the door's state stands.
  bool StillOnTheDoor(const DoorChange& c, const std::function<Vec2(const Vec2&)>& move) const;
  std::optional<Pose2> correction_;  ///< map->odom of the last pose (pose composed with odom^-1).
  double mapping_resumes_ = -1e300;  ///< After an estimate jump: no mapping before this time.
  int estimate_jumps_ = 0;

  std::optional<Pose2> pose_;
  double pose_time_ = -1e300;
  std::optional<Pose2> odom_;
  double odom_distance_m_ = 0.0;
  double linear_mps_ = 0.0, angular_rps_ = 0.0;
  bool certain_ = false;
  double localization_time_ = -1e300;
  double last_fix_time_ = -1e300;
  double localized_at_ = -1e300;  ///< When `localized` was last computed TRUE.
  double last_fix_odom_m_ = 0.0;
  std::set<std::string> places_fixed_;  ///< Localization places the last fix was taken at.
  int fixes_ = 0;
  RangeRing sonar_, infrared_;
  Pose2 sonar_pose_, infrared_pose_;
  double sonar_time_ = -1e300, infrared_time_ = -1e300;
  std::vector<Vec2> contact_;         ///< The pressed contact point (map), empty when none.
  double contact_raised_s_ = -1e300;  ///< bumper_contact last set true.
  double reflex_ended_s_ = -1e300;    ///< A reflex's motion last ended.

  std::unique_ptr<Task> task_;
  std::vector<std::unique_ptr<Task>> finishing_;  ///< Ended: reported once their scan settled.
  std::vector<std::pair<Ticket, bool>> completions_;
  std::map<Ticket, double> delayed_;  ///< Completions due later (retries).
  /// Navigate succeeded on an estimate not trusted: (ticket, since), re-sent once it is.
  std::optional<std::pair<Ticket, double>> unconfirmed_;
  bool active_localizing_ = false;  ///< An active localization for `unconfirmed_` runs.
  bool dirty_ = false;              ///< A model change the conditions must see: scan.

  std::uint64_t nav_seq_ = 0;
  Ticket nav_owner_ = 0;
  std::vector<std::unique_ptr<Reflex>> reflexes_;
  bool wheels_taken_ = false;
  std::map<Ticket, std::unique_ptr<Drive>> drives_;  ///< Tele-operation, searches.
  std::string ptu_pattern_;
  std::set<std::string> searched_;
  std::pair<Ticket, std::string> search_goto_{0, ""};  ///< goto_room's Navigate and its room.
  std::string search_at_;      ///< The room goto_room last arrived in (in_that_room).
  std::string search_target_;  ///< The room room_to_search chose, until it is searched.
  std::mt19937 rng_;

  std::string firing_rule_;
  std::map<std::string, int> frame_rules_;  ///< Last firing rule of each active frame.
  double last_feedback_s_ = -1e300;
  std::string last_feedback_rule_;
  std::string last_feedback_state_;
};

}  // namespace spott_tr_plus::controller
