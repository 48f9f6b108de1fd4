// The heading from the building's rectilinear walls, for a robot without an a priori map. Walls
// of an office floor are parallel or orthogonal to each other; RHINO's map learning used that to
// take the rotational error out of odometry (Thrun, "Learning metric-topological maps for indoor
// mobile robot navigation", Artificial Intelligence 99, 1998, section on position estimation:
// the walls' main orientations are found and the robot's heading is corrected against them).
// SPOTT's sensed map cannot hold the heading on its own: every segment is mapped with the heading
// the robot had then, so a turn's drift is never seen again (Experiment 1: 2-5 deg, 0.3-0.9 m at
// the goal).
//
// How: each horizontal range profile (QUADRIS: 64 samples, 5 mm noise) placed in the odom frame
// is cut into straight runs (a gap or a corner breaks a run); a run long and straight enough is a
// wall line. At a fix, each line of the window is turned into the map by map -> odom; its
// deviation from the nearest lattice direction (axis_rad + k pi/2) is the heading's error when it
// is within `gate_rad` (a chair or a crate at another angle says nothing). The lines agreeing with
// the length-weighted median within `agree_rad` give the correction. ROS-free; the caller owns
// time.
#pragma once

#include <cmath>
#include <deque>
#include <string>
#include <vector>

#include "spott_map/geometry.h"

namespace markov_localization {

struct WallLatticeParameters {
  bool enabled = true;  ///< Set false where walls are not parallel or orthogonal.
  /// Between heading fixes (s), > 0. Shorter than the echoes' period: a fix is cheap, and the
  /// odometry's heading wanders 0.3-0.8 deg in 10 s of driving.
  double period_s = 2.0;
  /// The lines of this last stretch vote (s), > 0: each line is the heading's error when it was
  /// seen, so an old one is off by the wandering since.
  double window_s = 2.0;
  double axis_rad = 0.0;  ///< The walls' main direction in the map frame (rad).
  /// A line further from every lattice direction is not a wall (rad), (0, pi/4).
  double gate_rad = 4.0 * M_PI / 180.0;
  /// Lines this close to the median are averaged (rad), > 0.
  double agree_rad = 1.15 * M_PI / 180.0;
  double min_length_m = 0.4;  ///< A shorter run fixes no direction (m), > 0.
  int min_points = 12;        ///< A run with fewer samples is no line, >= 3.
  double max_rms_m = 0.01;    ///< A run whose samples stray more is no line (a drum) (m), > 0.
  double break_m = 0.1;       ///< Samples further apart start a new run (m), > 0.
  double min_total_m = 1.0;   ///< Less agreeing line length in the window: no correction (m).
};

std::vector<std::string> ValidateParameters(const WallLatticeParameters& p);

/// A straight run of one profile, in the frame its points came in.
struct ProfileLine {
  double time_s = 0.0;
  double direction_rad = 0.0;  ///< In [0, pi): a line has no sense.
  double length_m = 0.0;
  double rms_m = 0.0;
  int points = 0;
};

/// The straight runs of a profile's echoes given in scan order: runs broken at gaps over
/// `break_m`, then split at the sample furthest from the fit while the fit's rms exceeds
/// `max_rms_m`; runs with `min_points` samples, `min_length_m` and rms within `max_rms_m` kept.
std::vector<ProfileLine> FitProfileLines(double time_s, const std::vector<spott_map::Vec2>& points,
                                         const WallLatticeParameters& p);

/// The correction one window's lines give.
struct WallLatticeCorrection {
  bool ok = false;
  bool applied = false;  ///< Turned (the tracker: ok and within max_correction_rad).
  std::string why;       ///< Why not ok.
  double dyaw = 0.0;     ///< To add to map -> odom's heading (rad).
  int lines = 0;         ///< Lines in the window.
  int agreeing = 0;      ///< Lines averaged.
  double length_m = 0;   ///< Their length.
};

class WallLatticeHeading {
 public:
  explicit WallLatticeHeading(const WallLatticeParameters& p);

  /// One profile's echoes in the odom frame, in scan order.
  void AddProfile(double time_s, const std::vector<spott_map::Vec2>& odom_points);
  /// The heading correction from the lines of [now - window_s, now] with map -> odom's heading
  /// `map_to_odom_yaw`; older lines are dropped.
  WallLatticeCorrection Estimate(double now_s, double map_to_odom_yaw);
  void Clear() { lines_.clear(); }

  const WallLatticeParameters& parameters() const { return p_; }
  std::size_t lines() const { return lines_.size(); }

 private:
  WallLatticeParameters p_;
  std::deque<ProfileLine> lines_;
};

}  // namespace markov_localization
