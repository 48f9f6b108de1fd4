// Drive kinematics and dead reckoning. The base is a unicycle (synchro drive: all wheels steer
// together; differential drive: two driven wheels, each with its own speed limit). Odometry
// integrates what the wheels report, with systematic errors (scale, drift per metre, per
// radian) and random errors whose variance grows with distance and rotation, so dead reckoning
// drifts as a real base does. Callers own time (dt) and the random generator.
#pragma once

#include <random>

#include "robot_sim/robot_spec.h"
#include "spott_map/world.h"

namespace robot_sim {

using Rng = std::mt19937_64;

/// Linear (m/s, along base_link +x) and angular (rad/s, about +z) velocity.
struct Twist2 {
  double v = 0.0;
  double w = 0.0;
};

/// True when a command is usable: finite and within `absurd_factor` times the robot's limits
/// (a larger command is refused rather than clamped: it is a bug upstream, not a wish).
bool CommandIsSane(const Twist2& cmd, const DriveSpec& drive, double absurd_factor = 10.0);

/// The velocity the base reaches after `dt` seconds from `current` towards `command`: the
/// command clamped to the speed limits (per wheel for a differential drive, keeping the
/// curvature), approached at most at the acceleration limits.
Twist2 LimitVelocity(const Twist2& current, const Twist2& command, const DriveSpec& drive,
                     double dt);

/// Exact unicycle integration over `dt` at constant velocity (arc of a circle).
spott_map::Pose2 Integrate(const spott_map::Pose2& pose, const Twist2& twist, double dt);

/// Dead-reckoning errors. Systematic: measured distance = linear_scale * true distance;
/// measured rotation = angular_scale * true rotation (the drift per radian is angular_scale - 1)
/// + drift_rad_per_m * distance travelled (a heading drift per metre, e.g. from unequal wheel
/// diameters). Random: zero-mean Gaussian with variance linear_noise^2 * |distance| on the
/// distance and angular_noise^2 * |rotation| + angular_noise_per_m^2 * |distance| on the
/// rotation (standard deviations grow with the square root of the motion).
struct OdometryErrorModel {
  double linear_scale = 1.0;         ///< (m/m) in (0.5, 1.5)
  double angular_scale = 1.0;        ///< (rad/rad) in (0.5, 1.5)
  double drift_rad_per_m = 0.0;      ///< (rad/m), |.| < 1
  double linear_noise = 0.0;         ///< (m/sqrt(m)) >= 0
  double angular_noise = 0.0;        ///< (rad/sqrt(rad)) >= 0
  double angular_noise_per_m = 0.0;  ///< (rad/sqrt(m)) >= 0
};

std::vector<std::string> ValidateParameters(const OdometryErrorModel& m);

/// Dead reckoning in the odom frame.
class Odometry {
 public:
  explicit Odometry(const OdometryErrorModel& model = {}) : model_(model) {}
  /// Accounts for the base moving by `distance` (m, signed) and `rotation` (rad, signed) in one
  /// step; `slip_linear` and `slip_angular` multiply what the encoders measure (slip faults).
  void Update(double distance, double rotation, Rng& rng, double slip_linear = 1.0,
              double slip_angular = 1.0);
  const spott_map::Pose2& pose() const { return pose_; }
  const Twist2& twist() const { return twist_; }
  void set_twist(const Twist2& t) { twist_ = t; }
  void Reset(const spott_map::Pose2& pose) { pose_ = pose; }
  const OdometryErrorModel& model() const { return model_; }

 private:
  OdometryErrorModel model_;
  spott_map::Pose2 pose_;
  Twist2 twist_;
};

}  // namespace robot_sim
