#include "rpl_executive/noreils_chatila/processes.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rpl_executive::noreils_chatila {

std::vector<std::string> ValidateParameters(const WallFollowingParameters& p) {
  std::vector<std::string> v;
  if (!(p.speed_mps > 0.0)) v.push_back("speed_mps: must be above 0");
  if (!(p.k_distance > 0.0)) v.push_back("k_distance: must be above 0");
  if (!(p.k_heading > 0.0)) v.push_back("k_heading: must be above 0");
  if (!(p.max_angular_rps > 0.0)) v.push_back("max_angular_rps: must be above 0");
  if (!(p.front_distance_m > 0.0)) v.push_back("front_distance_m: must be above 0");
  if (!(p.robot_radius_m >= 0.0)) v.push_back("robot_radius_m: must be 0 or more");
  if (!(p.side_window_rad > 0.0 && p.side_window_rad <= kPi)) {
    v.push_back("side_window_rad: must be in (0, pi]");
  }
  if (p.insufficient_data_limit < 1) v.push_back("insufficient_data_limit: must be 1 or more");
  return v;
}

std::vector<std::string> ValidateParameters(const ObstacleAvoidanceParameters& p) {
  std::vector<std::string> v;
  if (!(p.speed_mps > 0.0)) v.push_back("speed_mps: must be above 0");
  if (!(p.stop_distance_m >= 0.0)) v.push_back("stop_distance_m: must be 0 or more");
  if (!(p.detect_distance_m > p.stop_distance_m)) {
    v.push_back("detect_distance_m: must be above stop_distance_m");
  }
  if (!(p.front_half_angle_rad > 0.0 && p.front_half_angle_rad <= kPi)) {
    v.push_back("front_half_angle_rad: must be in (0, pi]");
  }
  if (!(p.max_angular_rps > 0.0)) v.push_back("max_angular_rps: must be above 0");
  if (p.insufficient_data_limit < 1) v.push_back("insufficient_data_limit: must be 1 or more");
  if (!(p.robot_radius_m >= 0.0)) v.push_back("robot_radius_m: must be 0 or more");
  if (!(p.way_clearance_m >= 0.0)) v.push_back("way_clearance_m: must be 0 or more");
  if (!(p.way_check_distance_m > 0.0)) v.push_back("way_check_distance_m: must be above 0");
  if (!(p.max_travel_m > 0.0)) v.push_back("max_travel_m: must be above 0");
  if (!(p.goal_turn_gain > 0.0)) v.push_back("goal_turn_gain: must be above 0");
  if (!(p.forget_margin_m >= 0.0)) v.push_back("forget_margin_m: must be 0 or more");
  return v;
}

namespace {

constexpr double kNoEcho = std::numeric_limits<double>::infinity();

// The nearest echo among sensors whose axis is within `half_angle` of `direction`.
double NearestEcho(const SonarScan& scan, const SonarRing& ring, double direction,
                   double half_angle) {
  double nearest = kNoEcho;
  const size_t n = std::min(scan.ranges_m.size(), ring.mounts.size());
  for (size_t i = 0; i < n; ++i) {
    if (!ring.IsEcho(scan.ranges_m[i])) continue;
    if (std::fabs(WrapAngle(ring.mounts[i].yaw_rad - direction)) > half_angle + 1e-9) continue;
    nearest = std::min(nearest, scan.ranges_m[i]);
  }
  return nearest;
}

}  // namespace

WallFollowingProcess::WallFollowingProcess(const WallFollowingParameters& parameters,
                                           const SonarRing& ring,
                                           const SonarInterpretationParameters& sonar)
    : parameters_(parameters), ring_(ring), sonar_(sonar) {}

void WallFollowingProcess::Activate(WallSide side, double distance_m) {
  active_ = true;
  side_ = side;
  distance_m_ = distance_m;
  insufficient_ = 0;
}

void WallFollowingProcess::Halt() { active_ = false; }

ProcessOutput WallFollowingProcess::Update(const SonarScan& scan, double speed_cap_mps) {
  ProcessOutput out;
  if (!active_) return out;
  const double s = side_ == WallSide::kLeft ? 1.0 : -1.0;
  const double side_direction = s * kPi / 2;
  const double speed = std::min(parameters_.speed_mps, speed_cap_mps);
  // An inside corner: a wall ahead.
  const double front = NearestEcho(scan, ring_, 0.0, kPi / 6);
  if (front < parameters_.front_distance_m) {
    insufficient_ = 0;
    out.command.angular_rps = -s * parameters_.max_angular_rps;
    return out;
  }
  double rho = -1.0, psi = 0.0;
  for (const SonarLine& line : InterpretLines(scan, ring_, sonar_)) {
    if (std::fabs(WrapAngle(line.theta_rad - side_direction)) > parameters_.side_window_rad)
      continue;
    if (rho < 0.0 || line.rho_m < rho) {
      rho = line.rho_m;
      psi = WrapAngle(line.theta_rad - side_direction);
    }
  }
  if (rho < 0.0) {
    // No line: the nearest side echo, seen from the centre, and the wall taken as parallel.
    const size_t n = std::min(scan.ranges_m.size(), ring_.mounts.size());
    for (size_t i = 0; i < n; ++i) {
      const SonarMount& m = ring_.mounts[i];
      if (!ring_.IsEcho(scan.ranges_m[i])) continue;
      if (std::fabs(WrapAngle(m.yaw_rad - side_direction)) > 35.0 * kPi / 180.0) continue;
      const double r = scan.ranges_m[i] + s * m.y_m;
      if (rho < 0.0 || r < rho) rho = r;
    }
  }
  if (rho < 0.0) {
    out.insufficient = true;
    out.failed = ++insufficient_ >= parameters_.insufficient_data_limit;
    out.command.linear_mps = 0.5 * speed;  // on, straight, while the wall is lost
    return out;
  }
  insufficient_ = 0;
  const double e = (rho - parameters_.robot_radius_m) - distance_m_;
  out.command.linear_mps = speed * std::max(0.0, std::cos(psi));  // slow while not parallel
  out.command.angular_rps = std::clamp(parameters_.k_heading * psi + s * parameters_.k_distance * e,
                                       -parameters_.max_angular_rps, parameters_.max_angular_rps);
  return out;
}

ObstacleAvoidanceProcess::ObstacleAvoidanceProcess(const ObstacleAvoidanceParameters& parameters,
                                                   const SonarRing& ring)
    : parameters_(parameters), ring_(ring) {}

void ObstacleAvoidanceProcess::Activate() {
  active_ = true;
  insufficient_ = 0;
}

void ObstacleAvoidanceProcess::Halt() { active_ = false; }

FrontEchoes NearestFrontEchoes(const SonarScan& scan, const SonarRing& ring,
                               double front_half_angle_rad) {
  FrontEchoes f{kNoEcho, kNoEcho, kNoEcho};
  const size_t n = std::min(scan.ranges_m.size(), ring.mounts.size());
  for (size_t i = 0; i < n; ++i) {
    const double r = scan.ranges_m[i];
    const double a = WrapAngle(ring.mounts[i].yaw_rad);
    if (!ring.IsEcho(r) || std::fabs(a) > front_half_angle_rad + 1e-9) continue;
    f.nearest = std::min(f.nearest, r);
    if (a >= -1e-9) f.left = std::min(f.left, r);
    if (a <= 1e-9) f.right = std::min(f.right, r);
  }
  return f;
}

VelocityCommand AvoidanceCommand(const ObstacleAvoidanceParameters& p, double nearest, double side,
                                 double speed_mps) {
  const double span = p.detect_distance_m - p.stop_distance_m;
  const double closeness = std::clamp((p.detect_distance_m - nearest) / span, 0.0, 1.0);
  VelocityCommand c;
  c.linear_mps = speed_mps * std::clamp((nearest - p.stop_distance_m) / span, 0.0, 1.0);
  c.angular_rps = side * p.max_angular_rps * std::max(0.3, closeness);
  return c;
}

ProcessOutput ObstacleAvoidanceProcess::Update(const SonarScan& scan, double speed_cap_mps) {
  ProcessOutput out;
  if (!active_) return out;
  const double speed = std::min(parameters_.speed_mps, speed_cap_mps);
  const FrontEchoes f = NearestFrontEchoes(scan, ring_, parameters_.front_half_angle_rad);
  if (!(f.nearest < parameters_.detect_distance_m)) {
    out.insufficient = true;
    out.failed = ++insufficient_ >= parameters_.insufficient_data_limit;
    out.command.linear_mps = speed;
    return out;
  }
  insufficient_ = 0;
  // Towards the freer side; left on a tie.
  out.command = AvoidanceCommand(parameters_, f.nearest, f.left >= f.right ? 1.0 : -1.0, speed);
  return out;
}

}  // namespace rpl_executive::noreils_chatila
