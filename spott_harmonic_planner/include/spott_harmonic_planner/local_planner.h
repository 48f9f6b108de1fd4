// SPOTT's local dynamic path planner process (III.D.1, steps 1-3 (a)-(f)), ROS-free:
//   1. load the map (a window cut from the map database, spott_map::LocalMap);
//   2. if the goal is outside the window, project it onto the border (the thick line of
//      Fig. 14: as given by the global planner, or without one the window border where the line
//      from the robot to the goal leaves the window);
//   3. loop: (a) iterate the kernel, (b) take a position estimate from localization, replacing
//      the dead-reckoned pose (correcting the accumulated odometry error), (c) ingest map
//      updates (warm start), (d) dead-reckon from odometry, (e) answer steering requests with
//      the gradient at the current estimate, (f) re-centre the window when the robot nears its
//      border and go back to 1.
// The caller drives it (the node from callbacks and a timer; tests directly): no clock, no
// threads. Frames: everything in `map` (REP-105) except odometry poses, in `odom`.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "spott_harmonic_planner/potential_field.h"
#include "spott_harmonic_planner/steering.h"
#include "spott_map/local_map.h"
#include "spott_map/map_database.h"
#include "spott_map/world.h"

namespace spott_harmonic_planner {

struct PlannerParameters {
  spott_map::LocalMapParameters window;  ///< window size, resolution, padding, re-centre margin
  FieldOptions field;                    ///< solver, stencil, omega, tolerance, norm
  SteeringParameters steering;
  /// Most iterations per Cycle(), [1, 10000]; none once the field is converged for the robot.
  int sweeps_per_cycle = 4;
  double goal_tolerance_m = 0.2;          ///< Success radius (m), > 0.
  double border_goal_half_width_m = 0.6;  ///< Half length of a projected border goal (m), > 0.
  /// No map beyond the window (no global planner): a goal the sensed obstacles cut off from the
  /// robot is sought through the reachable border cell nearest it (border_exploration.h).
  bool explore_when_cut_off = false;
};

/// Every violation, named as the parameter is named in config/harmonic_planner.yaml.
std::vector<std::string> ValidateParameters(const PlannerParameters& p);

/// The border goal (a straight-line fallback when no global projection is given, unlike the
/// global planner's ProjectGoalOntoWindow, which follows the room/door path): the window border
/// where the segment from `robot` (inside `window`) to `goal` (outside) leaves it, widened to
/// +-`half_width_m` along that side (clipped to it). nullopt when `goal` is inside the window or
/// `robot` is not.
std::optional<spott_map::Segment> BorderGoalSegment(const Vec2& robot, const Vec2& goal,
                                                    const spott_map::Box& window,
                                                    double half_width_m);

struct PlannerStatus {
  IterationReport iteration;
  bool has_goal = false;
  bool goal_on_border = false;
  bool recentred = false;       ///< This cycle moved the window (step f).
  bool border_widened = false;  ///< The border goal's own cells were blocked: it was widened.
  /// The goal was cut off from the robot: the field leads to the reachable border cell nearest
  /// it (explore_when_cut_off).
  bool exploring = false;
  /// The point goal lay in the padding: aimed at the free cell this far from it (m), else 0.
  double goal_snapped_m = 0.0;
  std::string problem;  ///< Non-empty when the goal cannot be placed (blocked, ...).
};

class LocalPlanner {
 public:
  /// Throws std::invalid_argument listing every violation when `params` are invalid.
  explicit LocalPlanner(const PlannerParameters& params);

  /// (c) A new map database (a priori map plus sensed features); applied at the next Cycle()
  /// with a warm start when the window does not move.
  void SetMap(const spott_map::MapDatabase& db);
  /// The target (map frame). Projected onto the window border while outside it. A target in
  /// the padding is aimed at through the free cell nearest it within `snap_radius_m` (navfn's
  /// default_tolerance: a goal whose tolerance reaches free space is reachable within it).
  void SetGoal(const Vec2& goal, double snap_radius_m = 0.0);
  /// A border goal projected by the global planner (Fig. 14). While one is set it is used even
  /// when the target lies inside the window: the global path says the way to the target leaves
  /// the window (e.g. the target is behind a wall, reached through a door outside the window).
  void SetBorderGoal(const spott_map::Segment& segment);
  /// The global planner's projection ended (the way to the target is inside the window): descend
  /// to the target itself again (or to the planner's own projection when it is outside).
  void ClearBorderGoal();
  void ClearGoal();
  /// (b) A position estimate from localization: replaces the dead-reckoned pose.
  void CorrectPose(const spott_map::Pose2& estimate);
  /// (d) An odometry pose (odom frame): the increment since the last one moves the estimate.
  void Odometry(const spott_map::Pose2& odom_pose);

  /// (f), (c), (a): re-centre if needed, apply map and goal changes, iterate.
  PlannerStatus Cycle();
  /// (e) Steering at the current estimate.
  SteeringCommand Steer(SpeedMode mode, std::optional<double> direction_bias) const;
  /// Steepest descent from the current estimate (the predicted path, map frame).
  PotentialField::Path PredictedPath() const;
  /// Along the predicted path, plus the straight remainder beyond a border goal (m).
  double DistanceToGoal() const;
  bool GoalReached() const;

  const spott_map::Pose2& pose() const { return pose_; }
  const std::optional<Vec2>& goal() const { return goal_; }
  const PotentialField& field() const { return field_; }
  const spott_map::LocalMap& window() const { return window_; }
  const PlannerParameters& parameters() const { return params_; }
  const PlannerStatus& status() const { return status_; }

 private:
  void PlaceGoal();
  void ExploreIfCutOff();
  std::optional<Vec2> NearestFreeCell(const Vec2& p, double radius_m) const;

  PlannerParameters params_;
  spott_map::MapDatabase db_;
  spott_map::LocalMap window_;
  PotentialField field_;
  bool window_cut_ = false;
  bool map_dirty_ = false;
  bool goal_dirty_ = false;
  bool goal_moved_ = true;  // the goal changed in the map since the field was last started
  std::optional<Vec2> goal_;
  double goal_snap_radius_m_ = 0.0;
  std::optional<spott_map::Segment> border_goal_;
  spott_map::Pose2 pose_;
  std::optional<spott_map::Pose2> last_odom_;
  PlannerStatus status_;
};

}  // namespace spott_harmonic_planner
