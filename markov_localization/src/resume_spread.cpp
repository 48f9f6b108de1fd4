#include "markov_localization/resume_spread.h"

#include <algorithm>
#include <cmath>

namespace markov_localization {

std::optional<Spread> SpreadOf(const Eigen::Matrix3d& c) {
  if (!c.allFinite() || c(0, 0) < 0.0 || c(1, 1) < 0.0 || c(2, 2) < 0.0) return std::nullopt;
  return Spread{std::sqrt(std::max(c(0, 0), c(1, 1))), std::sqrt(c(2, 2))};
}

Spread ResumeSpread(const Spread& saved, const Pose2& odom_at_save, const Pose2& odom_now,
                    const MotionModelParameters& motion, const MotionGateParameters& gate,
                    double cell_m, double heading_bin_rad) {
  const Motion m = MotionBetween(odom_at_save, odom_now);
  const double d = std::hypot(m.dx, m.dy);
  const double a = std::abs(m.dtheta);
  // n = d / step updates of sigma_per_m * step each: variance sigma_per_m^2 * step * d.
  const double step_d = std::max(gate.update_min_d_m, 0.01);
  const double step_a = std::max(gate.update_min_a_rad, 0.01);
  const double var_xy = motion.sigma_xy_per_m * motion.sigma_xy_per_m * step_d * d +
                        motion.sigma_xy_per_rad * motion.sigma_xy_per_rad * step_a * a;
  const double var_theta = motion.sigma_theta_per_m * motion.sigma_theta_per_m * step_d * d +
                           motion.sigma_theta_per_rad * motion.sigma_theta_per_rad * step_a * a;
  Spread s;
  s.xy_m = std::max(std::sqrt(saved.xy_m * saved.xy_m + var_xy), 0.5 * cell_m);
  s.theta_rad = std::max(std::sqrt(saved.theta_rad * saved.theta_rad + var_theta), heading_bin_rad);
  return s;
}

}  // namespace markov_localization
