#include "spott_harmonic_planner/steering.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace spott_harmonic_planner {

namespace {
void Check(bool ok, const std::string& name, double value, const std::string& range,
           std::vector<std::string>& v) {
  if (ok) return;
  std::ostringstream s;
  s << name << " must be " << range << " (got " << value << ")";
  v.push_back(s.str());
}
}  // namespace

std::vector<std::string> ValidateSteeringParameters(const SteeringParameters& p) {
  std::vector<std::string> v;
  Check(p.max_linear_mps > 0.0 && p.max_linear_mps <= 5.0, "max_linear_mps", p.max_linear_mps,
        "in (0, 5] m/s", v);
  Check(p.max_angular_rps > 0.0 && p.max_angular_rps <= 10.0, "max_angular_rps", p.max_angular_rps,
        "in (0, 10] rad/s", v);
  for (const auto& [name, f] :
       {std::pair<const char*, double>{"slowly_fraction", p.slowly_fraction},
        {"normal_fraction", p.normal_fraction},
        {"quickly_fraction", p.quickly_fraction}}) {
    Check(f > 0.0 && f <= 1.0, name, f, "in (0, 1]", v);
  }
  Check(p.heading_gain > 0.0 && p.heading_gain <= 100.0, "heading_gain_per_s", p.heading_gain,
        "in (0, 100] 1/s", v);
  Check(p.max_bias_deviation_rad >= 0.0 && p.max_bias_deviation_rad < M_PI / 2,
        "max_bias_deviation_rad", p.max_bias_deviation_rad, "in [0, pi/2) rad", v);
  Check(p.bias_reverse_fade_rad >= 0.0 && p.bias_reverse_fade_rad <= M_PI / 2,
        "bias_reverse_fade_rad", p.bias_reverse_fade_rad, "in [0, pi/2] rad", v);
  Check(p.bias_clearance_m > 0.0 && p.bias_clearance_m <= 10.0, "bias_clearance_m",
        p.bias_clearance_m, "in (0, 10] m", v);
  Check(p.slow_clearance_m > 0.0, "slow_clearance_m", p.slow_clearance_m, "> 0 m", v);
  Check(p.goal_slowdown_m > 0.0, "goal_slowdown_m", p.goal_slowdown_m, "> 0 m", v);
  Check(p.escape_radius_m >= 0.0 && p.escape_radius_m <= 2.0, "escape_radius_m", p.escape_radius_m,
        "in [0, 2] m", v);
  Check(p.escape_speed_fraction > 0.0 && p.escape_speed_fraction <= 1.0, "escape_speed_fraction",
        p.escape_speed_fraction, "in (0, 1]", v);
  return v;
}

double WrapAngle(double a) { return std::atan2(std::sin(a), std::cos(a)); }

namespace {

// The free cell connected to the goal (p > 0) within `radius_m` of `at` that is closest to the
// goal (largest p). Within the padding's width no free cell lies beyond a wall, so this is the
// way out towards the goal: in a doorway, into the door's channel rather than back into the hall.
std::optional<Vec2> BestEscape(const PotentialField& field, const Vec2& at, double radius_m) {
  const auto c = field.CellOf(at);
  if (!c || radius_m <= 0.0) return std::nullopt;
  const int r = static_cast<int>(std::ceil(radius_m / field.resolution()));
  std::optional<Vec2> best;
  double best_p = 0.0;
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      const int x = c->first + dx, y = c->second + dy;
      if (x < 0 || y < 0 || x >= field.width() || y >= field.height()) continue;
      const FieldCell kind = field.cell(x, y);
      if (kind != FieldCell::kFree && kind != FieldCell::kGoal) continue;
      const Vec2 centre = field.CellCentre(x, y);
      const double p = field.GoalProbability(x, y);
      if ((centre - at).norm() <= radius_m && p > best_p) {
        best_p = p;
        best = centre;
      }
    }
  }
  return best;
}

}  // namespace

double BiasedHeading(const Vec2& descent, std::optional<double> bias, double max_deviation,
                     double reverse_fade) {
  const double g = std::atan2(descent.y(), descent.x());
  if (!bias || !std::isfinite(*bias)) return g;
  const double off = WrapAngle(*bias - g);
  const double from_behind = M_PI - std::abs(off);
  if (reverse_fade > 0.0 && from_behind < reverse_fade) {
    max_deviation *= from_behind / reverse_fade;
  }
  return WrapAngle(g + std::clamp(off, -max_deviation, max_deviation));
}

SteeringCommand ComputeSteering(const PotentialField& field, const spott_map::Pose2& pose,
                                SpeedMode mode, std::optional<double> direction_bias,
                                double distance_to_goal_m, const SteeringParameters& params) {
  SteeringCommand cmd;
  const Vec2 at(pose.x, pose.y);
  cmd.clearance = field.Clearance(at);
  const auto descent = field.DescentDirection(at);
  if (!descent) {
    const auto c = field.CellOf(at);
    if (!c) {
      cmd.reason = "the robot is outside the planning window";
    } else if (const FieldCell kind = field.cell(c->first, c->second);
               kind == FieldCell::kObstacle || kind == FieldCell::kUnreachable) {
      // In the padding, or in a free pocket the padding cuts off from the goal (a doorway
      // whose jambs' padding meets behind the robot): out by the nearest connected cell.
      const auto escape = BestEscape(field, at, params.escape_radius_m);
      if (!escape) {
        cmd.reason = kind == FieldCell::kObstacle
                         ? "the robot is inside a padded obstacle"
                         : "the goal cannot be reached from the robot's position";
        return cmd;
      }
      // Out of the padding towards the goal, slowly.
      const Vec2 d = (*escape - at).normalized();
      cmd.valid = true;
      cmd.escaping = true;
      cmd.reason = kind == FieldCell::kObstacle ? "escaping the padding of an obstacle"
                                                : "escaping a pocket cut off from the goal";
      cmd.descent = d;
      cmd.heading = std::atan2(d.y(), d.x());
      const double error = WrapAngle(cmd.heading - pose.yaw);
      cmd.angular =
          std::clamp(params.heading_gain * error, -params.max_angular_rps, params.max_angular_rps);
      cmd.linear = params.escape_speed_fraction * params.slowly_fraction * params.max_linear_mps *
                   std::max(0.0, std::cos(error));
      return cmd;
    } else {
      cmd.reason = "the goal cannot be reached from the robot's position";
    }
    return cmd;
  }
  cmd.valid = true;
  cmd.descent = *descent;
  // The bias yields to descent near obstacles: the robot's heading lags the command while it
  // turns, and at a padded corner only descent keeps it out of the padding.
  const double room = std::clamp(cmd.clearance / params.bias_clearance_m, 0.0, 1.0);
  cmd.heading = BiasedHeading(*descent, direction_bias, params.max_bias_deviation_rad * room,
                              params.bias_reverse_fade_rad);
  const double error = WrapAngle(cmd.heading - pose.yaw);
  cmd.angular =
      std::clamp(params.heading_gain * error, -params.max_angular_rps, params.max_angular_rps);
  const double fraction = mode == SpeedMode::kSlowly   ? params.slowly_fraction
                          : mode == SpeedMode::kNormal ? params.normal_fraction
                                                       : params.quickly_fraction;
  double v = fraction * params.max_linear_mps;
  v *= std::max(0.0, std::cos(error));  // no forward motion while facing more than 90 deg off
  v *= std::clamp(cmd.clearance / params.slow_clearance_m, 0.1, 1.0);
  v *= std::clamp(distance_to_goal_m / params.goal_slowdown_m, 0.0, 1.0);
  cmd.linear = std::clamp(v, 0.0, params.max_linear_mps);
  return cmd;
}

SteeringCommand TurnInPlace(double yaw, double target_yaw, double tolerance_rad,
                            const SteeringParameters& params, bool* done) {
  SteeringCommand cmd;
  cmd.valid = true;
  cmd.heading = target_yaw;
  const double error = WrapAngle(target_yaw - yaw);
  *done = std::abs(error) <= tolerance_rad;
  if (!*done) {
    cmd.angular =
        std::clamp(params.heading_gain * error, -params.max_angular_rps, params.max_angular_rps);
  }
  return cmd;
}

}  // namespace spott_harmonic_planner
