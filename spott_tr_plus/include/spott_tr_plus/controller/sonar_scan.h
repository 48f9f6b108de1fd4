// MAP_OBJECTS_WITH_SONAR's dense scan (SPOTT section VI: "a dense scan equivalent to a ring of
// 144 ultrasonic sensors"): the Nomad's turret, which carries the 16 sonars, is stepped through
// 9 angles 2.5 degrees apart and the ring is read at each, so that a wall's echoes cover its
// region of constant depth at 2.5-degree steps. Heard head on from the driving robot alone (the
// ring's 22.5-degree spacing), a wall's direction is fixed only to the cone's width and the
// fusion kept cim_office's hallway ends as points; from a scan its direction is the middle of
// the echoes' run (sonar_echo_fit.h). The rings read on the way are mapped like any other (their
// mounts carry the turret's angle). ROS-free; the caller owns time and sends the turret's
// targets (robot_sim's /turret/command).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace spott_tr_plus::controller {

struct SonarScanParameters {
  /// A dense scan this often while the condition runs (s), >= 0; 0 never. 5 s: Experiment 1's
  /// "updated its map of the environment from sonar data every 5 seconds".
  double period_s = 5.0;
  int steps = 9;                   ///< Ring readings per scan (turret angles), in [2, 64].
  double step_rad = 0.0436332313;  ///< Between them (rad), in (0, pi/4]: 2.5 degrees.
  double settle_rad = 0.005;       ///< A ring this close to the step's angle is its reading (rad).
  /// A step whose angle is not reached this long after it was asked ends the scans: the robot
  /// has no turret (s), > 0.
  double step_timeout_s = 1.5;
};

std::vector<std::string> ValidateParameters(const SonarScanParameters& p);

class SonarScan {
 public:
  explicit SonarScan(const SonarScanParameters& p) : p_(p) {}

  /// A sonar ring read at `now` whose transducers point along `axes` (rad, the base's frame, the
  /// turret's angle included); `wanted`: the sonar's condition process runs (the scan is its data
  /// collection). Returns the turret's new target (rad from the base's heading) when it changes.
  std::optional<double> Ring(const std::vector<double>& axes, bool wanted, double now);

  bool scanning() const { return state_ == State::kStepping; }
  /// The turret's target (rad): 0 but during a scan.
  double target() const { return target_; }
  /// False once a step timed out (no turret): no scan is asked again.
  bool available() const { return available_; }
  int scans_done() const { return scans_; }

 private:
  enum class State { kHoming, kIdle, kStepping, kReturning };
  /// The turret's angle for a ring (rad), relative to the axes read at home.
  double TurretAngle(const std::vector<double>& axes) const;
  std::optional<double> Ask(double target, double now);

  SonarScanParameters p_;
  State state_ = State::kHoming;
  std::vector<double> home_, last_;  ///< Axes at home; of the previous ring.
  double target_ = 0.0;
  double asked_at_ = -1e300;
  double last_end_ = -1e300;
  int step_ = 0;
  int scans_ = 0;
  bool available_ = true;
};

}  // namespace spott_tr_plus::controller
