#include "spott_harmonic_planner/ros/conversions.h"

#include "spott_ros/pose_conversions.h"

#include <algorithm>
#include <cmath>

#include "spott_map/ros/conversions.h"

namespace spott_harmonic_planner::ros_conversions {

namespace conv = spott_map::ros_conversions;

nav_msgs::OccupancyGrid ToPotentialImage(const PotentialField& field, const std::string& frame_id,
                                         const ros::Time& stamp) {
  nav_msgs::OccupancyGrid g = conv::MakeGrid(field.origin(), field.width(), field.height(),
                                             field.resolution(), frame_id, stamp);
  for (int y = 0; y < field.height(); ++y) {
    for (int x = 0; x < field.width(); ++x) {
      std::int8_t v;
      const FieldCell c = field.cell(x, y);
      const double p = field.GoalProbability(x, y);
      if (c == FieldCell::kGoal) {
        v = 0;
      } else if (c != FieldCell::kFree || p <= 0.0) {
        v = 100;
      } else {
        const double decades = std::clamp(-std::log10(p) / kDecades, 0.0, 1.0);
        v = static_cast<std::int8_t>(1 + std::lround(98.0 * decades));
      }
      g.data[static_cast<std::size_t>(y) * field.width() + x] = v;
    }
  }
  return g;
}

visualization_msgs::Marker ToContours(const PotentialField& field, const std::string& frame_id,
                                      const ros::Time& stamp) {
  visualization_msgs::Marker m =
      conv::MakeMarker("equipotentials", 0, visualization_msgs::Marker::LINE_LIST, frame_id, stamp);
  m.scale.x = 0.02;  // line width
  m.color = conv::Colour(0.9f, 0.6f, 0.1f);
  // Contours of log10(p) (the same curves as u = 1 - 10^-k), at the cell centres.
  const auto level_value = [&](int x, int y) {
    const double p = field.GoalProbability(x, y);
    return p > 0.0 ? std::log10(p) : -1e9;
  };
  const auto point = [&](double gx, double gy) {
    geometry_msgs::Point q;
    q.x = field.origin().x() + (gx + 0.5) * field.resolution();
    q.y = field.origin().y() + (gy + 0.5) * field.resolution();
    return q;
  };
  for (int k = 1; k <= kDecades; ++k) {
    const double level = -k;
    for (int y = 0; y + 1 < field.height(); ++y) {
      for (int x = 0; x + 1 < field.width(); ++x) {
        const double v[4] = {level_value(x, y), level_value(x + 1, y), level_value(x + 1, y + 1),
                             level_value(x, y + 1)};
        const double cx[4] = {0, 1, 1, 0}, cy[4] = {0, 0, 1, 1};
        std::vector<geometry_msgs::Point> crossings;
        for (int e = 0; e < 4; ++e) {
          const int a = e, b = (e + 1) % 4;
          if ((v[a] < level) == (v[b] < level)) continue;
          const double t = (level - v[a]) / (v[b] - v[a]);
          crossings.push_back(
              point(x + cx[a] + t * (cx[b] - cx[a]), y + cy[a] + t * (cy[b] - cy[a])));
        }
        for (std::size_t i = 0; i + 1 < crossings.size(); i += 2) {
          m.points.push_back(crossings[i]);
          m.points.push_back(crossings[i + 1]);
        }
      }
    }
  }
  return m;
}

nav_msgs::Path ToPath(const PotentialField::Path& path, const std::string& frame_id,
                      const ros::Time& stamp) {
  nav_msgs::Path msg;
  msg.header.frame_id = frame_id;
  msg.header.stamp = stamp;
  for (const Vec2& p : path.points) {
    geometry_msgs::PoseStamped ps;
    ps.header = msg.header;
    ps.pose.position.x = p.x();
    ps.pose.position.y = p.y();
    ps.pose.orientation.w = 1.0;
    msg.poses.push_back(ps);
  }
  return msg;
}

spott_msgs::PotentialFieldStatus ToStatus(const LocalPlanner& planner, double solve_time_s,
                                          const std::string& frame_id, const ros::Time& stamp) {
  spott_msgs::PotentialFieldStatus s;
  s.header.frame_id = frame_id;
  s.header.stamp = stamp;
  const auto& o = planner.parameters().field;
  s.solver = std::string(ToString(o.solver.kind)) + "/" + ToString(o.solver.stencil);
  s.sweeps = static_cast<std::uint32_t>(std::max(0, planner.status().iteration.sweeps));
  s.residual = planner.status().iteration.residual;
  s.converged = planner.status().iteration.converged;
  s.solve_time = solve_time_s;
  s.window_origin.x = planner.field().origin().x();
  s.window_origin.y = planner.field().origin().y();
  s.window_size = planner.field().width() * planner.field().resolution();
  s.resolution = planner.field().resolution();
  s.goal_on_border = planner.status().goal_on_border;
  s.robot_radius = planner.parameters().window.robot_radius_m;
  s.padding = planner.parameters().window.padding_m();
  return s;
}

spott_msgs::SteeringStatus ToSteering(const SteeringCommand& cmd, SpeedMode mode,
                                      double distance_to_goal_m, const std::string& frame_id,
                                      const ros::Time& stamp) {
  spott_msgs::SteeringStatus s;
  s.header.frame_id = frame_id;
  s.header.stamp = stamp;
  s.gradient.x = cmd.descent.x();
  s.gradient.y = cmd.descent.y();
  s.heading = cmd.heading;
  s.linear = cmd.linear;
  s.angular = cmd.angular;
  s.speed_mode = static_cast<std::uint8_t>(mode);
  s.clearance = cmd.clearance;
  s.distance_to_goal = distance_to_goal_m;
  return s;
}

std::optional<NavigateRequest> FromGoal(const spott_msgs::NavigateGoal& goal,
                                        const std::string& frame_id, double default_tolerance_m,
                                        double default_heading_tolerance_rad, std::string* error) {
  const auto& t = goal.target;
  if (!std::isfinite(t.pose.position.x) || !std::isfinite(t.pose.position.y)) {
    *error = "target.pose.position must be finite";
    return std::nullopt;
  }
  if (!t.header.frame_id.empty() && t.header.frame_id != frame_id) {
    *error = "target.header.frame_id '" + t.header.frame_id + "' is not '" + frame_id + "'";
    return std::nullopt;
  }
  if (goal.speed_mode > spott_msgs::NavigateGoal::QUICKLY) {
    *error = "speed_mode must be SLOWLY (0), NORMAL (1) or QUICKLY (2), not " +
             std::to_string(goal.speed_mode);
    return std::nullopt;
  }
  const auto tolerance_ok = [](double v) { return std::isfinite(v) && v >= 0.0; };
  if (!tolerance_ok(goal.position_tolerance) || !tolerance_ok(goal.heading_tolerance)) {
    *error = "position_tolerance and heading_tolerance must be finite and >= 0 (0 = default)";
    return std::nullopt;
  }
  // A wider tolerance would end the goal where the robot stands: it is not a goal any more.
  if (goal.position_tolerance > kMaxPositionToleranceM || goal.heading_tolerance > M_PI) {
    *error = "position_tolerance must be at most " + std::to_string(kMaxPositionToleranceM) +
             " m and heading_tolerance at most pi";
    return std::nullopt;
  }
  NavigateRequest r;
  r.target = Vec2(t.pose.position.x, t.pose.position.y);
  if (!goal.ignore_heading) {
    r.yaw = spott_ros::YawOf(t.pose.orientation);
    if (!r.yaw) {
      *error = "target.pose.orientation has no yaw (not finite or zero); set ignore_heading";
      return std::nullopt;
    }
  }
  r.mode = static_cast<SpeedMode>(goal.speed_mode);
  using Bias = DirectionBias::Kind;
  switch (goal.bias_kind) {
    case spott_msgs::NavigateGoal::BIAS_HEADING:
      r.bias.kind = Bias::kHeading;
      if (std::isfinite(goal.direction_bias)) r.bias.heading = goal.direction_bias;
      break;
    case spott_msgs::NavigateGoal::BIAS_TOWARD:
    case spott_msgs::NavigateGoal::BIAS_AWAY:
    case spott_msgs::NavigateGoal::BIAS_VIA:
    case spott_msgs::NavigateGoal::BIAS_AROUND:
      if (!std::isfinite(goal.bias_point.x) || !std::isfinite(goal.bias_point.y)) {
        *error = "bias_point must be finite for bias_kind " + std::to_string(goal.bias_kind);
        return std::nullopt;
      }
      r.bias.kind = goal.bias_kind == spott_msgs::NavigateGoal::BIAS_TOWARD ? Bias::kToward
                    : goal.bias_kind == spott_msgs::NavigateGoal::BIAS_AWAY ? Bias::kAway
                    : goal.bias_kind == spott_msgs::NavigateGoal::BIAS_VIA  ? Bias::kVia
                                                                            : Bias::kAround;
      r.bias.point = Vec2(goal.bias_point.x, goal.bias_point.y);
      if (r.bias.kind == Bias::kVia &&
          !(std::isfinite(goal.bias_radius) && goal.bias_radius >= 0)) {
        *error = "bias_radius must be finite and >= 0 for BIAS_VIA";
        return std::nullopt;
      }
      if (r.bias.kind == Bias::kAround && !(goal.bias_sense == 1.0 || goal.bias_sense == -1.0)) {
        *error = "bias_sense must be +1 or -1 for BIAS_AROUND";
        return std::nullopt;
      }
      r.bias.radius = goal.bias_radius;
      r.bias.sense = goal.bias_sense;
      break;
    default:
      *error = "bias_kind must be BIAS_HEADING (0) .. BIAS_AROUND (4), not " +
               std::to_string(goal.bias_kind);
      return std::nullopt;
  }
  r.tolerance_m = goal.position_tolerance > 0.0 ? goal.position_tolerance : default_tolerance_m;
  r.heading_tolerance_rad =
      goal.heading_tolerance > 0.0 ? goal.heading_tolerance : default_heading_tolerance_rad;
  return r;
}

}  // namespace spott_harmonic_planner::ros_conversions
