#include "robot_sim/drive.h"

#include <algorithm>
#include <cmath>

#include "spott_map/geometry.h"

namespace robot_sim {

namespace {

double Approach(double current, double target, double max_step) {
  return current + std::clamp(target - current, -max_step, max_step);
}

using spott_map::NormalizeAngle;

}  // namespace

bool CommandIsSane(const Twist2& cmd, const DriveSpec& drive, double absurd_factor) {
  return std::isfinite(cmd.v) && std::isfinite(cmd.w) &&
         std::abs(cmd.v) <= absurd_factor * drive.max_linear_mps &&
         std::abs(cmd.w) <= absurd_factor * drive.max_angular_rps;
}

Twist2 LimitVelocity(const Twist2& current, const Twist2& command, const DriveSpec& drive,
                     double dt) {
  Twist2 target = command;
  if (drive.kind == DriveKind::kDifferential) {
    // Each wheel is limited to max_linear_mps; scale both down to keep the curvature.
    const double half = drive.wheel_separation_m / 2;
    const double left = target.v - target.w * half, right = target.v + target.w * half;
    const double worst = std::max(std::abs(left), std::abs(right));
    if (worst > drive.max_linear_mps) {
      const double k = drive.max_linear_mps / worst;
      target.v *= k;
      target.w *= k;
    }
  }
  target.v = std::clamp(target.v, -drive.max_linear_mps, drive.max_linear_mps);
  target.w = std::clamp(target.w, -drive.max_angular_rps, drive.max_angular_rps);
  return {Approach(current.v, target.v, drive.max_linear_accel * dt),
          Approach(current.w, target.w, drive.max_angular_accel * dt)};
}

spott_map::Pose2 Integrate(const spott_map::Pose2& pose, const Twist2& t, double dt) {
  spott_map::Pose2 out = pose;
  const double dtheta = t.w * dt;
  if (std::abs(dtheta) < 1e-9) {
    out.x += t.v * dt * std::cos(pose.yaw + dtheta / 2);
    out.y += t.v * dt * std::sin(pose.yaw + dtheta / 2);
  } else {
    const double r = t.v / t.w;
    out.x += r * (std::sin(pose.yaw + dtheta) - std::sin(pose.yaw));
    out.y -= r * (std::cos(pose.yaw + dtheta) - std::cos(pose.yaw));
  }
  out.yaw = NormalizeAngle(pose.yaw + dtheta);
  return out;
}

std::vector<std::string> ValidateParameters(const OdometryErrorModel& m) {
  std::vector<std::string> e;
  if (!(m.linear_scale > 0.5 && m.linear_scale < 1.5))
    e.push_back("odometry/linear_scale must be in (0.5, 1.5)");
  if (!(m.angular_scale > 0.5 && m.angular_scale < 1.5))
    e.push_back("odometry/angular_scale must be in (0.5, 1.5)");
  if (!(std::abs(m.drift_rad_per_m) < 1))
    e.push_back("odometry/drift_rad_per_m must be in (-1, 1)");
  if (!(m.linear_noise >= 0 && m.linear_noise < 1))
    e.push_back("odometry/linear_noise must be in [0, 1)");
  if (!(m.angular_noise >= 0 && m.angular_noise < 1))
    e.push_back("odometry/angular_noise must be in [0, 1)");
  if (!(m.angular_noise_per_m >= 0 && m.angular_noise_per_m < 1)) {
    e.push_back("odometry/angular_noise_per_m must be in [0, 1)");
  }
  return e;
}

void Odometry::Update(double distance, double rotation, Rng& rng, double slip_linear,
                      double slip_angular) {
  std::normal_distribution<double> unit(0.0, 1.0);
  // Always draw both numbers so the random stream does not depend on whether the base moved.
  const double n_lin = unit(rng), n_ang = unit(rng);
  double ds = model_.linear_scale * slip_linear * distance;
  double dth =
      model_.angular_scale * slip_angular * rotation + model_.drift_rad_per_m * std::abs(distance);
  ds += n_lin * model_.linear_noise * std::sqrt(std::abs(distance));
  dth += n_ang *
         std::sqrt(model_.angular_noise * model_.angular_noise * std::abs(rotation) +
                   model_.angular_noise_per_m * model_.angular_noise_per_m * std::abs(distance));
  // Midpoint rule: the heading halfway through the step.
  pose_.x += ds * std::cos(pose_.yaw + dth / 2);
  pose_.y += ds * std::sin(pose_.yaw + dth / 2);
  pose_.yaw = NormalizeAngle(pose_.yaw + dth);
}

}  // namespace robot_sim
