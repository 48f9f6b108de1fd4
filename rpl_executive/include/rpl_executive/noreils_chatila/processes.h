// HILARE's two processes (sections 3.3 and 6.1.1): Docking (wall following) and Local Obstacle
// Avoidance, each a dynamic link from the ultrasonic module to the pilot. As the paper has
// them, a process is never created dynamically: it is built once and activated (with
// parameters) or halted by the control system; it never stops by itself; it reports a failure
// only when its input is insufficient repeatedly (insufficient_data_limit sonar data in a row).
//
// Wall following (side s = +1 left, -1 right, distance d from the robot's side): the wall is
// the sonar interpretation's nearest line whose normal lies within side_window_rad of the side
// (sonar_interpretation.h). With rho its distance from the robot's centre and psi = theta - s pi/2
// the wall's angle, the law is
//     e = (rho - robot_radius_m) - d,   w = k_heading psi + s k_distance e,
//     v = speed max(0, cos psi)
// (psi = 0 when the robot runs parallel; e > 0 turns it towards the wall; the robot slows down
// while it is not parallel and turns in place when the wall is across its way). The window
// (side_window_rad, 60 degrees by default, up to 180) bounds which lines count as the wall; one
// wider than 90 degrees takes a wall reached head-on, and psi = 90 degrees turns the robot in
// place until the wall is on the side. A wall
// ahead nearer than front_distance_m turns it away from the side in place (an inside corner).
// Without a line, the nearest echo within 35 degrees of the side gives rho (psi = 0); without
// either the datum is insufficient.
//
// Obstacle avoidance: an obstacle is an echo of a front sensor (axis within front_half_angle_rad
// of the heading) nearer than detect_distance_m. The robot slows down with the nearest front
// echo (stopping at stop_distance_m) and turns towards the side whose nearest echo is farther.
// A datum without an obstacle is insufficient: the avoidance has nothing to do.
#pragma once

#include <string>
#include <vector>

#include "rpl_executive/noreils_chatila/pilot.h"
#include "rpl_executive/noreils_chatila/robot_modules.h"
#include "rpl_executive/noreils_chatila/sensor_data.h"
#include "rpl_executive/noreils_chatila/sonar_interpretation.h"

namespace rpl_executive::noreils_chatila {

/// What a process gives on each sonar datum.
struct ProcessOutput {
  VelocityCommand command;
  bool insufficient = false;  ///< this datum did not give the process what it needs
  bool failed = false;        ///< insufficient_data_limit data in a row: report to the executive
};

struct WallFollowingParameters {
  double speed_mps = 0.2;            ///< (0, inf)
  double k_distance = 2.0;           ///< rad/s per m of distance error, (0, inf)
  double k_heading = 1.5;            ///< rad/s per rad of wall angle, (0, inf)
  double max_angular_rps = 0.8;      ///< (0, inf)
  double front_distance_m = 0.35;    ///< a front echo nearer (range) is an inside corner, (0, inf)
  double robot_radius_m = 0.4;       ///< centre to side (HILARE's belt radius), [0, inf)
  double side_window_rad = 1.05;     ///< lines whose normal is this near the side, (0, pi]
  int insufficient_data_limit = 10;  ///< [1, inf)
};
std::vector<std::string> ValidateParameters(const WallFollowingParameters& p);

struct ObstacleAvoidanceParameters {
  double speed_mps = 0.15;            ///< (0, inf)
  double detect_distance_m = 0.6;     ///< (stop_distance_m, inf)
  double stop_distance_m = 0.2;       ///< [0, inf)
  double front_half_angle_rad = 1.2;  ///< (0, pi]: 1.2 rad covers sensors 14-16 and 1-4
  double max_angular_rps = 0.8;       ///< (0, inf)
  int insufficient_data_limit = 5;    ///< [1, inf)
  // The elementary task avoid-obstacle (avoid_obstacle.h):
  double robot_radius_m = 0.4;        ///< centre to side (HILARE's belt radius), [0, inf)
  double way_clearance_m = 0.2;       ///< beyond the radius, an echo to the way back, [0, inf)
  double way_check_distance_m = 2.0;  ///< the way back is checked this far, (0, inf)
  double max_travel_m = 4.0;          ///< driven without the way clearing: fails, (0, inf)
  double goal_turn_gain = 1.0;        ///< rad/s per rad towards the way back, (0, inf)
  double forget_margin_m = 0.1;       ///< a beam reading this far past an echo forgets it, [0, inf)
};
std::vector<std::string> ValidateParameters(const ObstacleAvoidanceParameters& p);

/// The nearest echo of the front sensors (axis within `front_half_angle_rad` of the heading),
/// and of those on each side (the sensor on the axis counts for both); infinity when none.
struct FrontEchoes {
  double nearest;
  double left;
  double right;
};
FrontEchoes NearestFrontEchoes(const SonarScan& scan, const SonarRing& ring,
                               double front_half_angle_rad);

/// The avoidance law for a front echo at `nearest` (< detect_distance_m): slower as it nears,
/// stopped at stop_distance_m, turning towards `side` (+1 left, -1 right).
VelocityCommand AvoidanceCommand(const ObstacleAvoidanceParameters& p, double nearest, double side,
                                 double speed_mps);

class WallFollowingProcess {
 public:
  WallFollowingProcess(const WallFollowingParameters& parameters, const SonarRing& ring,
                       const SonarInterpretationParameters& sonar);
  void Activate(WallSide side, double distance_m);
  void Halt();
  bool active() const { return active_; }
  /// One sonar datum; `speed_cap_mps` is the pilot's set speed.
  ProcessOutput Update(const SonarScan& scan, double speed_cap_mps);

 private:
  WallFollowingParameters parameters_;
  SonarRing ring_;
  SonarInterpretationParameters sonar_;
  bool active_ = false;
  WallSide side_ = WallSide::kRight;
  double distance_m_ = 0.25;
  int insufficient_ = 0;
};

class ObstacleAvoidanceProcess {
 public:
  ObstacleAvoidanceProcess(const ObstacleAvoidanceParameters& parameters, const SonarRing& ring);
  void Activate();
  void Halt();
  bool active() const { return active_; }
  ProcessOutput Update(const SonarScan& scan, double speed_cap_mps);

 private:
  ObstacleAvoidanceParameters parameters_;
  SonarRing ring_;
  bool active_ = false;
  int insufficient_ = 0;
};

}  // namespace rpl_executive::noreils_chatila
