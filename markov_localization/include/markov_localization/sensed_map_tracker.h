// SPOTT's LOCALIZE_THE_ROBOT without an a priori map (Zelek and Levine, Fig. 4 and Experiment 1:
// "the robot was localized every 10 seconds"; the condition "collects sonar data and correlates it
// with the existing map to determine pose"). The existing map is what the robot sensed: the line
// segments its mapping put into the map database. Between fixes the pose is odometry's.
//
// How: the sonar echoes of the last `window_s` (their transducers placed by odometry, consistent
// over seconds) are matched to the segments by the echo's physics (Leonard and Durrant-Whyte, the
// paper's reference [30]; spott_map/sonar_echo.h, the model the controller's sonar mapping fits
// walls with): a specular wall answers from the foot of the perpendicular when it lies in the
// beam's cone, else from where the cone's edge meets it up to the critical incidence. The
// correction of map -> odom (x, y and heading about the echoes' centroid) minimises the range
// residuals by Gauss-Newton with re-association and Huber weights. Directions the echoes do not
// constrain (along a corridor) are left alone: only eigen-directions of the information above
// `min_information` move. A fix beyond `max_correction_m` / `max_correction_rad` is refused: a
// wrong association is likelier than that much drift within a period. ROS-free; the caller owns
// time.
#pragma once

#include <deque>
#include <string>
#include <vector>

#include "markov_localization/wall_lattice_heading.h"
#include "spott_map/geometry.h"
#include "spott_map/sonar_echo.h"
#include "spott_map/world.h"

namespace markov_localization {

struct SensedMapTrackerParameters {
  double period_s = 10.0;             ///< Between fixes (s), > 0: Experiment 1's 10 s.
  double window_s = 10.0;             ///< Echoes of this last stretch are matched (s), > 0.
  double max_range_m = 3.0;           ///< Echoes farther away are not used (m), > 0.
  double min_segment_length_m = 0.5;  ///< Shorter segments fix no direction (m), >= 0.
  double extend_m = 0.5;              ///< A segment's line is matched this far past its ends (m).
  /// Beyond this incidence outside the cone a wall sends no echo back (rad; robot_sim's sonar
  /// critical_angle, and the controller's sonar mapping's), >= 0.
  double max_incidence_rad = 20.0 * M_PI / 180.0;
  double gate_m = 0.25;   ///< An echo further than this from its prediction: none (m).
  double huber_m = 0.05;  ///< Residuals beyond this weigh less (m), > 0.
  int iterations = 8;     ///< Gauss-Newton steps with re-association, >= 1.
  int min_echoes = 10;    ///< Fewer matched echoes: no fix, >= 3.
  /// A direction of the correction (x, y, heading times 1 m) moves only with at least this much
  /// information: the weight of this many echoes whose wall faces that way, > 0.
  double min_information = 5.0;
  /// Whether a fix turns the heading too. Off by default: on cim_office's lab the heading from a
  /// window's echoes on short sensed segments came out 1.5-5 degrees wrong in 4 of 10 fixes (the
  /// odometry's own heading drifts about 0.5 degrees in 10 s), and features then mapped with it
  /// fed the error back (1.6 m off at the goal in one run).
  bool correct_heading = false;
  double max_correction_m = 0.5;     ///< A larger fix is refused (m), > 0.
  double max_correction_rad = 0.15;  ///< A larger fix is refused (rad), > 0.
  /// The heading from rectilinear walls in the range profiles (wall_lattice_heading.h): every
  /// wall_lattice.period_s map -> odom turns about the robot by its lines' correction.
  WallLatticeParameters wall_lattice;
};

std::vector<std::string> ValidateParameters(const SensedMapTrackerParameters& p);

/// The outcome of one matching.
struct SensedMapFix {
  bool applied = false;
  std::string why;                               ///< Why not applied; empty when applied.
  int echoes = 0;                                ///< In the window.
  int matched = 0;                               ///< Associated with a segment at the end.
  int constrained = 0;                           ///< Directions (0-3) the echoes constrained.
  double dx = 0.0, dy = 0.0, dyaw = 0.0;         ///< The correction (map frame, about the robot).
  double rms_before_m = 0.0, rms_after_m = 0.0;  ///< Matched echoes' residuals.
  /// The heading's information (m^2: the matched echoes' squared lever across their walls);
  /// its standard error is rms_after_m / sqrt(it) rad. 0 without correct_heading.
  double heading_information = 0.0;
};

class SensedMapTracker {
 public:
  SensedMapTracker(const SensedMapTrackerParameters& p, const spott_map::Pose2& map_to_odom);

  /// The sensed map's walls (map frame); segments shorter than min_segment_length_m are dropped.
  void SetSegments(const std::vector<spott_map::Segment>& segments);
  /// One ring read at `time_s` with the base at `odom_base` (odom frame): each transducer's mount
  /// (base frame) and range; NaN, <= min_range_m (clamped) or >= max_range_m (no echo) are skipped.
  void AddRing(double time_s, const spott_map::Pose2& odom_base,
               const std::vector<spott_map::Pose2>& mounts, const std::vector<double>& ranges,
               double min_range_m, double max_range_m, double field_of_view_rad);
  /// One horizontal range profile's echoes at `time_s`, in the odom frame and in scan order (for
  /// wall_lattice; nothing when it is off).
  void AddProfile(double time_s, const std::vector<spott_map::Vec2>& odom_points) {
    lattice_.AddProfile(time_s, odom_points);
  }
  /// A fix is due `period_s` after the last one (or the start).
  bool Due(double now_s) const { return now_s - last_fix_s_ >= p_.period_s; }
  /// A heading fix from the wall lattice is due (on, and wall_lattice.period_s after the last).
  bool LatticeDue(double now_s) const {
    return p_.wall_lattice.enabled && now_s - last_lattice_s_ >= p_.wall_lattice.period_s;
  }
  /// Turns map -> odom about the robot (`odom_base_now`) by the wall lattice's correction when
  /// it has one within max_correction_rad. Restarts the lattice's period.
  WallLatticeCorrection TurnToLattice(double now_s, const spott_map::Pose2& odom_base_now);
  /// Matches the echoes of the window ending at `now_s` to the segments; on success map_to_odom
  /// moves (the heading turns about the echoes' centroid; `odom_base_now`, the robot, when there
  /// are none). Restarts the period.
  SensedMapFix Localize(double now_s, const spott_map::Pose2& odom_base_now);
  /// Starts over at `map_to_odom` (a new initial pose): the echoes are dropped.
  void Reset(const spott_map::Pose2& map_to_odom, double now_s);

  const spott_map::Pose2& map_to_odom() const { return map_to_odom_; }
  const SensedMapTrackerParameters& parameters() const { return p_; }
  std::size_t echoes() const { return echoes_.size(); }

 private:
  struct Echo {
    double time_s;
    spott_map::SonarEcho echo;  ///< Odom frame.
  };
  struct Wall {
    spott_map::Vec2 a, u, n;  ///< Start, unit direction, unit normal.
    double length;
  };

  SensedMapTrackerParameters p_;
  spott_map::Pose2 map_to_odom_;
  std::vector<Wall> walls_;
  std::deque<Echo> echoes_;
  WallLatticeHeading lattice_;
  double last_fix_s_ = 0.0;
  double last_lattice_s_ = 0.0;
};

}  // namespace markov_localization
