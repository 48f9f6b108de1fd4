#include "rpl_executive/noreils_chatila/avoid_obstacle.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>

namespace rpl_executive::noreils_chatila {
namespace {

// A remembered echo nearer than this to another is not kept again (m).
constexpr double kEchoSpacingM = 0.05;
// Echoes up to this range are remembered, each as kArcPoints points across its beam (m).
constexpr double kRememberedRangeM = 1.5;
constexpr int kArcPoints = AvoidObstacleTask::kArcPoints;
// ... over this part of the beam's opening (its edges fall out of the beam's cone at the next
// datum already, where no later reading could forget them).
constexpr double kArcSpan = 0.75;
constexpr int kForgetData = 5;
// A heading is taken when its first kProbeM pass every remembered echo by the robot's radius
// plus way_clearance_m: the obstacle extends beyond the echoes it gave (the sonar is blind to it
// at close range and at grazing angles), and an unseen part of a cylinder touched the robot
// with a 5 cm margin here.
constexpr double kProbeM = 1.0;
// Near the vertex, the way need only pass the echoes by the robot's radius plus this (m).
constexpr double kContactMarginM = 0.05;
// Only echoes this near the heading turn the robot away; wider (the process's 1.2 rad), an
// obstacle beside it turned it back and forth against the steering towards the way back.
constexpr double kFrontHalfAngleRad = 0.8;
// Turning this much in all without the way clearing ends the task too (three full turns).
constexpr double kMaxTurnRad = 6.0 * kPi;
// The way back is taken only facing it within this (rad).
constexpr double kFacingRad = 0.3;

Point2 ToMap(const Pose2& pose, double x, double y) {
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  return Point2{pose.x + c * x - s * y, pose.y + s * x + c * y};
}

}  // namespace

AvoidObstacleTask::AvoidObstacleTask(const ObstacleAvoidanceParameters& parameters,
                                     const SonarRing& ring)
    : parameters_(parameters), ring_(ring) {}

void AvoidObstacleTask::Start(std::vector<Point2> way) {
  way_ = std::move(way);
  echoes_.clear();
  last_pose_.reset();
  travelled_m_ = 0.0;
  turned_rad_ = 0.0;
  side_ = 0.0;
  without_obstacle_ = 0;
}

void AvoidObstacleTask::Remember(const Pose2& pose, const SonarScan& scan) {
  const size_t n = std::min(scan.ranges_m.size(), ring_.mounts.size());
  // Forget what the beams read past: nothing in a beam's cone is nearer than its reading (no
  // echo proves nothing: the sonar's specular reflection).
  // +1 when a beam whose cone holds `e` reads past it, -1 when one reads it or nearer (the
  // count starts again), 0 when no beam's reading says anything about it.
  const auto seen = [&](const Point2& e) {
    int verdict = 0;
    for (size_t i = 0; i < n; ++i) {
      const SonarMount& m = ring_.mounts[i];
      const Point2 origin = ToMap(pose, m.x_m, m.y_m);
      const double bearing =
          WrapAngle(std::atan2(e.y - origin.y, e.x - origin.x) - (pose.yaw + m.yaw_rad));
      const double r = scan.ranges_m[i];
      if (std::fabs(bearing) > ring_.half_field_of_view_rad || !std::isfinite(r)) continue;
      if (r <= Distance(origin, e) + parameters_.forget_margin_m) return -1;
      verdict = 1;
    }
    return verdict;
  };
  // ... on kForgetData data in a row (a beam grazing the obstacle's side reads past it now and
  // then: specular reflection). The echo's arc goes with it.
  for (Remembered& e : echoes_) {
    const int verdict = seen(e.at);
    if (verdict != 0) e.read_past = verdict > 0 ? e.read_past + 1 : 0;
  }
  echoes_.erase(std::remove_if(echoes_.begin(), echoes_.end(),
                               [](const Remembered& e) { return e.read_past >= kForgetData; }),
                echoes_.end());
  for (size_t i = 0; i < n; ++i) {
    const double r = scan.ranges_m[i];
    if (!ring_.IsEcho(r) || r > kRememberedRangeM) continue;
    const SonarMount& m = ring_.mounts[i];
    Remembered e;
    e.at = ToMap(pose, m.x_m + r * std::cos(m.yaw_rad), m.y_m + r * std::sin(m.yaw_rad));
    const bool known = std::any_of(echoes_.begin(), echoes_.end(), [&](const Remembered& k) {
      return Distance(k.at, e.at) < kEchoSpacingM;
    });
    if (known) continue;
    // The arc across the beam the echo may have come from: the way back and the steering keep
    // clear of it.
    for (int k = 0; k < kArcPoints; ++k) {
      const double a =
          m.yaw_rad + kArcSpan * ring_.half_field_of_view_rad * (2.0 * k / (kArcPoints - 1) - 1.0);
      e.arc[k] = ToMap(pose, m.x_m + r * std::cos(a), m.y_m + r * std::sin(a));
    }
    echoes_.push_back(e);
  }
}

AvoidObstacleTask::Window AvoidObstacleTask::WayWindow(const Point2& from) const {
  Window w;
  w.points.push_back(from);
  double left = parameters_.way_check_distance_m;
  for (size_t i = 0; i < way_.size(); ++i) {
    const Point2& a = w.points.back();
    const double d = Distance(a, way_[i]);
    if (d >= left) {
      const double f = d > 0.0 ? left / d : 0.0;
      w.points.push_back(Point2{a.x + f * (way_[i].x - a.x), a.y + f * (way_[i].y - a.y)});
      w.length_m += left;
      w.ends_at_last_vertex = i + 1 == way_.size() && d - left < 1e-9;
      return w;
    }
    w.points.push_back(way_[i]);
    w.length_m += d;
    left -= d;
  }
  w.ends_at_last_vertex = true;
  return w;
}

bool AvoidObstacleTask::WayIsClear(const Window& w) const {
  if (w.length_m < parameters_.way_clearance_m) return true;  // there
  const double needed = parameters_.robot_radius_m + parameters_.way_clearance_m;
  const double touching = parameters_.robot_radius_m + kContactMarginM;
  const auto distance = [&](const Point2& p) {
    double d = std::numeric_limits<double>::infinity();
    for (size_t i = 1; i < w.points.size(); ++i) {
      d = std::min(d, DistanceToSegment(p, w.points[i - 1], w.points[i]));
    }
    return d;
  };
  // The robot must reach the path's end even when the obstacle lies within way_clearance_m of
  // it: there the way need only be free of contact.
  return std::none_of(echoes_.begin(), echoes_.end(), [&](const Remembered& e) {
    return std::any_of(e.arc.begin(), e.arc.end(), [&](const Point2& p) {
      const bool near_end = w.ends_at_last_vertex && Distance(p, w.points.back()) < needed;
      return distance(p) < (near_end ? touching : needed);
    });
  });
}

AvoidObstacleTask::Step AvoidObstacleTask::Update(const Pose2& pose, const SonarScan& scan,
                                                  double speed_cap_mps) {
  Step step;
  if (last_pose_) {
    travelled_m_ += std::hypot(pose.x - last_pose_->x, pose.y - last_pose_->y);
    turned_rad_ += std::fabs(WrapAngle(pose.yaw - last_pose_->yaw));
  }
  last_pose_ = pose;
  Remember(pose, scan);

  const FrontEchoes f = NearestFrontEchoes(scan, ring_, kFrontHalfAngleRad);
  const bool obstacle = f.nearest < parameters_.detect_distance_m;
  without_obstacle_ = obstacle ? 0 : without_obstacle_ + 1;

  const double speed = std::min(parameters_.speed_mps, speed_cap_mps);
  const Point2 from{pose.x, pose.y};
  const Window window = WayWindow(from);
  const Point2& target = window.points.back();  // the end of the way checked
  const double to_way_back = WrapAngle(std::atan2(target.y - from.y, target.x - from.x) - pose.yaw);
  const bool way_clear = !way_.empty() && WayIsClear(window);
  // At the path's end already: nothing to face (the bearing to a point under the robot is noise).
  const bool there = !way_.empty() && window.length_m < parameters_.way_clearance_m;
  if (way_clear && !there && std::fabs(to_way_back) > kFacingRad) {
    // Clear as far as it has seen: it turns to face the way first, so that the sensors look at
    // what lies beside it (a part of the obstacle it never saw).
    step.command.angular_rps =
        std::clamp(parameters_.goal_turn_gain * to_way_back, -parameters_.max_angular_rps,
                   parameters_.max_angular_rps);
  } else if (there || (way_clear && !(f.nearest < std::min(parameters_.detect_distance_m,
                                                           Distance(from, target))))) {
    char where[96];
    std::snprintf(where, sizeof where, "the way to (%.2f, %.2f) m is clear after %.2f m", target.x,
                  target.y, travelled_m_);
    step.status = Status::kCompleted;
    step.message = where;
    return step;
  }
  if (way_.empty() && without_obstacle_ >= parameters_.insufficient_data_limit) {
    step.status = Status::kCompleted;
    step.message = "nothing left to avoid";
    return step;
  }
  if (travelled_m_ > parameters_.max_travel_m || turned_rad_ > kMaxTurnRad) {
    char why[128];
    std::snprintf(why, sizeof why,
                  "no clear way back after %.2f m and %.0f degrees of turning (max_travel_m %.2f)",
                  travelled_m_, turned_rad_ * 180.0 / kPi, parameters_.max_travel_m);
    step.status = Status::kFailed;
    step.message = why;
    return step;
  }
  if (way_clear && !there && std::fabs(to_way_back) > kFacingRad) return step;  // facing it

  if (obstacle && side_ == 0.0) side_ = f.left >= f.right ? 1.0 : -1.0;  // freer; left on a tie
  if (way_.empty()) {
    if (obstacle)
      step.command = AvoidanceCommand(parameters_, f.nearest, side_, speed);
    else
      step.command.linear_mps = speed;
    return step;
  }
  // Slower with the nearest front echo, as the process; no translation within stop_distance_m.
  const double span = parameters_.detect_distance_m - parameters_.stop_distance_m;
  const double slow = std::clamp((f.nearest - parameters_.stop_distance_m) / span, 0.0, 1.0);
  // The heading nearest the way back whose next kProbeM stays clear of every remembered echo
  // (the obstacle's contour, also where the sonar's echo from it flickers).
  const double goal = std::atan2(target.y - from.y, target.x - from.x);
  const double needed = parameters_.robot_radius_m + parameters_.way_clearance_m;
  // Within reach of the path's end the probe is shorter (the obstacle may lie near the end).
  const double probe = window.ends_at_last_vertex
                           ? std::clamp(Distance(from, target) - parameters_.robot_radius_m,
                                        kContactMarginM, kProbeM)
                           : kProbeM;
  const auto clear = [&](double heading) {
    const Point2 to{from.x + probe * std::cos(heading), from.y + probe * std::sin(heading)};
    // An echo already nearer than `needed` (beside the robot) only blocks headings that bring
    // the robot nearer to it.
    return std::none_of(echoes_.begin(), echoes_.end(), [&](const Remembered& e) {
      return std::any_of(e.arc.begin(), e.arc.end(), [&](const Point2& p) {
        return DistanceToSegment(p, from, to) < std::min(needed, Distance(p, from) - 1e-3);
      });
    });
  };
  const double toward_heading = WrapAngle(pose.yaw - goal) >= 0.0 ? 1.0 : -1.0;
  for (int k = 0; k <= 36; ++k) {
    for (const double sign : {toward_heading, -toward_heading}) {
      const double heading = goal + sign * k * kPi / 36.0;
      if (!clear(heading)) continue;
      const double error = WrapAngle(heading - pose.yaw);
      step.command.angular_rps =
          std::clamp(parameters_.goal_turn_gain * error, -parameters_.max_angular_rps,
                     parameters_.max_angular_rps);
      step.command.linear_mps = speed * slow * std::max(0.0, std::cos(error));
      return step;
    }
  }
  // Hemmed in by remembered echoes: turn on the chosen side.
  step.command.linear_mps = 0.0;
  step.command.angular_rps = (side_ == 0.0 ? 1.0 : side_) * parameters_.max_angular_rps;
  return step;
}

}  // namespace rpl_executive::noreils_chatila
