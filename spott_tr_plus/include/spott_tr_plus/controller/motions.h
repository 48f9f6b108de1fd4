// The motions the TR+ controller drives itself (SPOTT III-C.3: "the exceptions to the rule are
// the two programs that specify a reaction when collision has been detected via the bumper or
// infrared sensors"; VI-A: intelligent tele-operation). ROS-free: each step takes the robot's
// pose and the time from the caller and returns a velocity command.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "spott_map/map_database.h"
#include "spott_map/occupancy_raster.h"

namespace spott_tr_plus::controller {

using spott_map::Pose2;
using spott_map::Vec2;

struct Velocity {
  double linear_mps = 0.0;
  double angular_rps = 0.0;
};

struct ReflexParameters {
  double speed_mps = 0.1;  ///< Moving away (m/s), > 0.
  double turn_rps = 0.5;   ///< Turning to move away along the robot's axis (rad/s), > 0.
  double align_rad = 0.6;  ///< Drive once the axis is this close to "away" (rad), (0, pi/2).
  double timeout_s = 8.0;  ///< Give up moving away after this long (s), > 0.
  double infrared_close_m = 0.12;  ///< An infrared reading below this: impending obstacle (m).
  /// A contact this close to a map feature is that feature (m): the localization error the
  /// padding allows (0.075 m), half a bumper segment along the shell (0.036 m of the Nomad's 20)
  /// and the bumper's travel, rounded up. At 0.1 m contacts at door jambs were mapped as new
  /// obstacles that closed the door.
  double known_tolerance_m = 0.15;
  /// A contact still pressed this long after its reflex ended fires the reflex again (s), > 0:
  /// the condition holds, so the rule fires again (teleop_bumper: the robot's side stayed on the
  /// box, the arbiter refused every forward command and nothing moved for 90 s).
  double repeat_s = 1.0;
};

std::vector<std::string> ValidateParameters(const ReflexParameters& p);

class KnownStructure;

/// SPOTT Figs. 7-8, "move away from the source of collision": drives the robot along its own
/// axis (forwards or backwards, whichever moves it away; turning in place first when the
/// source is at its side) until its centre is `distance` farther from the source than at the
/// start, or the timeout. With the map's known structure it never drives the body into it:
/// in a doorway "away" from one jamb can be straight at the other, and a misplaced source can
/// put "away" into a wall; it then takes the other end of its axis if that still moves away,
/// or stops where it is (`blocked`).
class MoveAway {
 public:
  /// `known` (may be null: no check) must outlive the motion; `radius_m` is the body's.
  MoveAway(const Vec2& source, double distance_m, const Pose2& start, double now_s,
           const ReflexParameters& params, const KnownStructure* known = nullptr,
           double radius_m = 0.0);
  /// The command at `pose` (map frame); nullopt once moved away, or timed out (`timed_out`),
  /// or with no way away that is clear of the known structure (`blocked`).
  std::optional<Velocity> Step(const Pose2& pose, double now_s);
  bool timed_out() const { return timed_out_; }
  bool blocked() const { return blocked_; }
  const Vec2& source() const { return source_; }

 private:
  /// How far (up to `length_m`) the body can drive from `at` along `heading` without meeting
  /// known structure.
  double FreeRun(const Vec2& at, double heading, double length_m) const;
  bool Clear(const Vec2& at, double heading, double length_m) const {
    return FreeRun(at, heading, length_m) >= length_m;
  }

  Vec2 source_;
  double start_distance_m_;  ///< From the source when the motion started.
  double asked_m_;           ///< The distance to move away.
  double target_distance_m_;
  double started_s_;
  ReflexParameters params_;
  const KnownStructure* known_;
  double radius_m_;
  bool timed_out_ = false;
  bool blocked_ = false;
};

struct TeleopParameters {
  double stop_distance_m = 0.3;     ///< Stop when a known structure ahead is this close (m), > 0.
  double lookahead_m = 1.2;         ///< New obstacles this far ahead are avoided (m), > 0.
  double clearance_m = 0.08;        ///< Margin beside the robot's body when avoiding (m), >= 0.
  double max_deviation_rad = 1.2;   ///< Largest turn off the commanded direction (rad), [0, pi/2].
  double heading_gain_per_s = 2.0;  ///< omega = gain * heading error (1/s), > 0.
  double blocked_timeout_s = 10.0;  ///< No way for this long: the tele-operation stops (s), > 0.
};

std::vector<std::string> ValidateParameters(const TeleopParameters& p);

/// The known structures of the map (SPOTT VI-A: "stopping when a previously known structure is
/// present in the original path"): the CAD features and the closed doors' leaves.
class KnownStructure {
 public:
  void Build(const spott_map::MapDatabase& db);
  /// Distance (m) the robot's centre can travel from `from` along `heading` before its body
  /// (a disc of `radius_m`) meets a known structure, to 1 mm; `max_m` when none within it.
  double FreeRun(const Vec2& from, double heading, double radius_m, double max_m) const;
  /// Distance (m) from `at` to the nearest known structure; `max_m` when none within it.
  double Clearance(const Vec2& at, double max_m) const;
  bool built() const { return built_; }

 private:
  spott_map::MapDatabase structure_;
  bool built_ = false;
};

/// Intelligent tele-operation (SPOTT VI-A): moves in the commanded direction (a heading in the
/// map, fixed when the command was given), avoids newly encountered obstacles by turning off it
/// as little as keeps the body clear, and stops when a known structure lies ahead in the
/// commanded direction within the stop distance. "backward" drives in reverse.
class Teleop {
 public:
  Teleop(double direction_rad, bool reverse, double speed_mps, double max_angular_rps,
         double robot_radius_m, const TeleopParameters& params, double now_s);

  struct Step {
    Velocity command;
    bool stopped = false;    ///< Done: a known structure ahead (or no way for too long).
    std::string why;         ///< What it stopped at.
    double structure_m = 0;  ///< Free run to the known structure ahead (m).
    double heading = 0;      ///< The heading chosen this step (rad, map).
  };
  /// `obstacles`: what is new around the robot (sensed features' points and the latest echoes,
  /// map frame).
  Step Update(const Pose2& pose, const KnownStructure& known, const std::vector<Vec2>& obstacles,
              double now_s);
  double direction() const { return direction_; }

 private:
  bool Clear(const Vec2& from, double heading, const std::vector<Vec2>& obstacles) const;

  double direction_;
  bool reverse_;
  double speed_;
  double max_angular_;
  double radius_;
  TeleopParameters p_;
  double last_progress_s_;
};

}  // namespace spott_tr_plus::controller
