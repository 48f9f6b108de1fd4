// How fast the robot may drive towards what its range ring sees (ROS-free): Nav2's collision
// monitor for the arbiter. Each reading puts an echo somewhere on its cone's arc; the echoes in
// the corridor the round body sweeps ahead (or behind) bound the speed so that the robot, braking
// at `deceleration_mps2` after `latency_s`, stops `stop_margin_m` before the nearest one:
// v * latency + v^2 / (2 a) = gap - margin. A planner whose pose is wrong (a kidnapped robot, a
// localization that has not yet noticed) is stopped by what the sensors see, not by its map.
#pragma once

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace cmd_vel_arbiter {

struct ClearanceParameters {
  double deceleration_mps2 = 0.5;   ///< Braking the limit assumes (m/s^2), > 0.
  double latency_s = 0.2;           ///< Reading to braking (s), [0, 5].
  double stop_margin_m = 0.05;      ///< Left between the body and an echo (m), [0, 2].
  double corridor_margin_m = 0.02;  ///< Added to the radius for the swept corridor (m), [0, 1].
  /// The body's radius (m); 0 = the farthest transducer from the centre (they sit on the body).
  double footprint_radius_m = 0.0;
  /// A reading of a ring's minimum range itself (drivers and robot_sim clamp what lies closer)
  /// or -Inf (REP 117: too close to measure), from a transducer whose cone holds the line of
  /// motion, is an echo at its face: no speed towards it. For a robot whose ring is its only
  /// sense of contact (the B-12: 12 sonars blind to 0.15 m, no bumper, no infrared). Off, the
  /// minimum is read as a gap of min_range: a Nomad's sonars are blind to 0.43 m, and stopped
  /// there its controller's tele-operation never reaches its own stop (teleop_bumper.test).
  bool min_range_at_face = false;
};

/// Every violation, named as in config/cmd_vel_arbiter.yaml (clearance/...).
std::vector<std::string> ValidateParameters(const ClearanceParameters& p);

/// One transducer: position (m) and axis (rad) in the robot's frame.
struct Transducer {
  double x = 0.0, y = 0.0, yaw = 0.0;
};

struct SpeedBounds {
  double forward_mps = std::numeric_limits<double>::infinity();
  double backward_mps = std::numeric_limits<double>::infinity();   ///< Magnitude.
  double forward_gap_m = std::numeric_limits<double>::infinity();  ///< Body to nearest echo.
  double backward_gap_m = std::numeric_limits<double>::infinity();
};

/// The bounds from one reading of the ring. `ranges_m` one per transducer; NaN, readings
/// below `min_range_m` and at or beyond `max_range_m` (no echo) bound nothing; a reading of
/// `min_range_m` itself is an echo there, or (`min_range_at_face`, also for -Inf) at the face
/// of a transducer whose cone holds the straight line ahead or behind.
SpeedBounds BoundsFromRing(const std::vector<Transducer>& transducers, double field_of_view_rad,
                           double min_range_m, double max_range_m,
                           const std::vector<double>& ranges_m, const ClearanceParameters& p);

/// A planar scanner (a laser: one ray per reading, no cone) mounted at `mount` in the robot's
/// frame; reading i looks along angle_min_rad + i * angle_increment_rad of the mount.
struct ScanGeometry {
  Transducer mount;
  double angle_min_rad = 0.0;
  double angle_increment_rad = 0.0;
  double range_min_m = 0.0;
  double range_max_m = 0.0;
};

/// The bounds from one scan: every reading in [range_min, range_max) is an echo at its point;
/// NaN, +-Inf and readings outside bound nothing. The body is round with `radius_m` (the laser
/// sits inside it, so unlike a ring's it cannot give the radius: footprint_radius_m or the
/// robot description's). The sonar misses a wall met obliquely and reads its minimum (0.15 m
/// on the B21) however close the wall is: the B21, turned 70 degrees towards a hallway wall,
/// drove into it at 0.23 m/s while its laser read 0.09 m (bonn_kidnap).
SpeedBounds BoundsFromScan(const ScanGeometry& scan, const std::vector<double>& ranges_m,
                           double radius_m, const ClearanceParameters& p);

/// The largest speed that stops `margin` before a gap (m/s); 0 when the gap is within it.
double StoppingSpeed(double gap_m, const ClearanceParameters& p);

/// Several rings at once (the sonar and the low infrared ring, which sees what passes under the
/// sonar's cones: a crate, a chair's seat): each ring's latest bounds, and the tightest of those
/// at most `max_age_s` old. A ring that fell silent bounds nothing.
class RingBoundsSet {
 public:
  RingBoundsSet(std::size_t rings, double max_age_s);
  void Set(std::size_t ring, const SpeedBounds& bounds, double now_s);
  /// The tightest bounds of the rings heard within max_age_s; `went_silent` (optional) gets the
  /// rings that aged out since the previous call, each once.
  SpeedBounds Tightest(double now_s, std::vector<std::size_t>* went_silent);

 private:
  struct Entry {
    SpeedBounds bounds;
    double time_s = 0.0;
    bool fresh = false;
  };
  std::vector<Entry> rings_;
  double max_age_s_;
};

}  // namespace cmd_vel_arbiter
