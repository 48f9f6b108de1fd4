#include "spott_tr_plus/controller/motions.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "spott_map/geometry.h"
#include "spott_map/local_map.h"
#include "violation.h"

namespace spott_tr_plus::controller {

namespace {

using spott_map::NormalizeAngle;

}  // namespace

std::vector<std::string> ValidateParameters(const ReflexParameters& p) {
  std::vector<std::string> v;
  if (!(p.speed_mps > 0 && p.speed_mps <= 2))
    v.push_back(Violation("speed_mps", "in (0, 2]", p.speed_mps));
  if (!(p.turn_rps > 0 && p.turn_rps <= 5))
    v.push_back(Violation("turn_rps", "in (0, 5]", p.turn_rps));
  if (!(p.align_rad > 0 && p.align_rad < M_PI / 2))
    v.push_back(Violation("align_rad", "in (0, pi/2)", p.align_rad));
  if (!(p.timeout_s > 0)) v.push_back(Violation("timeout_s", "> 0", p.timeout_s));
  if (!(p.infrared_close_m > 0))
    v.push_back(Violation("infrared_close_m", "> 0", p.infrared_close_m));
  if (!(p.known_tolerance_m >= 0))
    v.push_back(Violation("known_tolerance_m", ">= 0", p.known_tolerance_m));
  if (!(p.repeat_s > 0 && p.repeat_s <= 60))
    v.push_back(Violation("repeat_s", "in (0, 60]", p.repeat_s));
  return v;
}

std::vector<std::string> ValidateParameters(const TeleopParameters& p) {
  std::vector<std::string> v;
  if (!(p.stop_distance_m > 0)) v.push_back(Violation("stop_distance_m", "> 0", p.stop_distance_m));
  if (!(p.lookahead_m > 0)) v.push_back(Violation("lookahead_m", "> 0", p.lookahead_m));
  if (!(p.clearance_m >= 0)) v.push_back(Violation("clearance_m", ">= 0", p.clearance_m));
  if (!(p.max_deviation_rad >= 0 && p.max_deviation_rad <= M_PI / 2))
    v.push_back(Violation("max_deviation_rad", "in [0, pi/2]", p.max_deviation_rad));
  if (!(p.heading_gain_per_s > 0))
    v.push_back(Violation("heading_gain_per_s", "> 0", p.heading_gain_per_s));
  if (!(p.blocked_timeout_s > 0))
    v.push_back(Violation("blocked_timeout_s", "> 0", p.blocked_timeout_s));
  return v;
}

// --- MoveAway ------------------------------------------------------------------------------------

MoveAway::MoveAway(const Vec2& source, double distance_m, const Pose2& start, double now_s,
                   const ReflexParameters& params, const KnownStructure* known, double radius_m)
    : source_(source),
      start_distance_m_((start.Position() - source).norm()),
      asked_m_(std::max(0.0, distance_m)),
      target_distance_m_((start.Position() - source).norm() + std::max(0.0, distance_m)),
      started_s_(now_s),
      params_(params),
      known_(known),
      radius_m_(radius_m) {}

double MoveAway::FreeRun(const Vec2& at, double heading, double length_m) const {
  if (!known_) return length_m;
  // A body already touching (the contact's own wall, or one the estimate puts it into) is
  // checked with the radius it has room for: moving off the structure stays possible, moving
  // further into it does not.
  const double radius = std::min(radius_m_, known_->Clearance(at, radius_m_ + 0.1) - 0.01);
  if (radius <= 0.0) return length_m;  // the centre on the structure: the estimate is no help
  return known_->FreeRun(at, heading, radius, length_m);
}

std::optional<Velocity> MoveAway::Step(const Pose2& pose, double now_s) {
  const Vec2 away = pose.Position() - source_;
  const double d = away.norm();
  if (d >= target_distance_m_) return std::nullopt;
  if (blocked_) return std::nullopt;
  if (now_s - started_s_ > params_.timeout_s) {
    timed_out_ = true;
    return std::nullopt;
  }
  const double want = d > 1e-6 ? std::atan2(away.y(), away.x()) : pose.yaw + M_PI;
  // Forwards or backwards, whichever axis direction is closer to "away".
  const double forward_error = NormalizeAngle(want - pose.yaw);
  const double backward_error = NormalizeAngle(want - (pose.yaw + M_PI));
  const bool forwards = std::abs(forward_error) <= std::abs(backward_error);
  const double error = forwards ? forward_error : backward_error;
  const bool aligned = std::abs(error) <= params_.align_rad;
  const double axis = pose.yaw + (forwards ? 0.0 : M_PI);
  // The way still to go (plus a step) must be clear of the known structure, on the heading the
  // robot will drive: "away" itself when it turns first.
  const double run = std::max(0.05, target_distance_m_ - d + 0.02);
  Velocity v;
  if (!Clear(pose.Position(), aligned ? axis : want, run)) {
    // Turning towards "away" is what is not clear: straight along the axis, which still moves
    // away while "away" is less than 90 degrees off it, if that is clear.
    if (!aligned && std::abs(error) < M_PI / 2 - 0.05 &&
        Clear(pose.Position(), axis, std::min(1.0, run / std::cos(error)))) {
      v.linear_mps = (forwards ? 1.0 : -1.0) * params_.speed_mps;
      return v;
    }
    // Neither: as far "away" as is clear, if that is half the distance asked (teleop_bumper: the
    // box at the robot's side, the hallway's wall 0.27 m off its other side; blocked, the reflex
    // left it touching the box).
    const double free = FreeRun(pose.Position(), aligned ? axis : want, run) - 0.02;
    if (d + free - start_distance_m_ < 0.5 * asked_m_) {
      blocked_ = true;
      return std::nullopt;
    }
    if (free < 0.01) return std::nullopt;  // as far as was clear
    target_distance_m_ = d + free;
  }
  if (!aligned) {
    v.angular_rps = std::copysign(params_.turn_rps, error);  // turn in place first
    return v;
  }
  v.linear_mps = (forwards ? 1.0 : -1.0) * params_.speed_mps;
  v.angular_rps = std::clamp(2.0 * error, -params_.turn_rps, params_.turn_rps);
  return v;
}

// --- KnownStructure ------------------------------------------------------------------------------

void KnownStructure::Build(const spott_map::MapDatabase& db) {
  structure_ = spott_map::MapDatabase();
  for (const spott_map::MapFeature& f : db.features()) {
    if (f.source == spott_map::FeatureSource::kCad) structure_.AddFeature(f);
  }
  for (const spott_map::Door& door : db.graph().doors()) {
    if (door.state != spott_map::DoorState::kClosed) continue;
    structure_.AddFeature(spott_map::MakeSegment("door:" + door.id, door.opening, "door", 0.05));
  }
  built_ = true;
}

double KnownStructure::Clearance(const Vec2& at, double max_m) const {
  double best = max_m;
  if (!built_) return best;
  for (const spott_map::MapFeature* f :
       structure_.FeaturesIn({at - Vec2(max_m, max_m), at + Vec2(max_m, max_m)})) {
    best = std::min(best, f->DistanceTo(at));
  }
  return best;
}

double KnownStructure::FreeRun(const Vec2& from, double heading, double radius_m,
                               double max_m) const {
  if (!built_) return max_m;
  const Vec2 dir(std::cos(heading), std::sin(heading));
  const Vec2 end = from + max_m * dir;
  const spott_map::Box swept =
      spott_map::Box{from.cwiseMin(end), from.cwiseMax(end)}.Inflated(radius_m + 0.01);
  const std::vector<const spott_map::MapFeature*> near = structure_.FeaturesIn(swept);
  if (near.empty()) return max_m;
  const auto touches = [&](double s) {
    const Vec2 c = from + s * dir;
    for (const spott_map::MapFeature* f : near) {
      if (f->DistanceTo(c) <= radius_m) return true;
    }
    return false;
  };
  if (touches(0.0)) return 0.0;
  const double step = 0.02;
  for (double s = step; s < max_m + step; s += step) {
    const double at = std::min(s, max_m);
    if (!touches(at)) continue;
    double lo = at - step, hi = at;  // free at lo, touching at hi
    while (hi - lo > 1e-3) {
      const double mid = 0.5 * (lo + hi);
      (touches(mid) ? hi : lo) = mid;
    }
    return lo;
  }
  return max_m;
}

// --- Teleop --------------------------------------------------------------------------------------

Teleop::Teleop(double direction_rad, bool reverse, double speed_mps, double max_angular_rps,
               double robot_radius_m, const TeleopParameters& params, double now_s)
    : direction_(NormalizeAngle(direction_rad)),
      reverse_(reverse),
      speed_(speed_mps),
      max_angular_(max_angular_rps),
      radius_(robot_radius_m),
      p_(params),
      last_progress_s_(now_s) {}

bool Teleop::Clear(const Vec2& from, double heading, const std::vector<Vec2>& obstacles) const {
  const Vec2 dir(std::cos(heading), std::sin(heading));
  const double half = radius_ + p_.clearance_m;
  for (const Vec2& o : obstacles) {
    const Vec2 d = o - from;
    const double along = d.dot(dir);
    if (along < 0.0 || along > p_.lookahead_m + radius_) continue;
    const double across = std::abs(d.x() * dir.y() - d.y() * dir.x());
    if (across < half) return false;
  }
  return true;
}

Teleop::Step Teleop::Update(const Pose2& pose, const KnownStructure& known,
                            const std::vector<Vec2>& obstacles, double now_s) {
  Step step;
  const Vec2 at = pose.Position();
  // The known structure in the commanded direction (the "original path").
  step.structure_m = known.FreeRun(at, direction_, radius_, p_.stop_distance_m + 5.0);
  if (step.structure_m <= p_.stop_distance_m) {
    step.stopped = true;
    std::ostringstream why;
    why.precision(2);
    why << std::fixed << "a known structure " << step.structure_m << " m ahead (stop distance "
        << p_.stop_distance_m << " m)";
    step.why = why.str();
    return step;
  }
  // The heading closest to the commanded direction whose way is clear of new obstacles (and of
  // known structure within the look-ahead). Known structure beside the way keeps clearance_m
  // from the body as new obstacles do (a commanded direction a few degrees off a hallway ran the
  // Nomad's bumper onto its wall); what lies ahead in the commanded direction is left to the
  // stop. A body already nearer than clearance_m may go on as long as it gets no nearer.
  const double margin = std::max(
      0.0,
      std::min(p_.clearance_m, known.Clearance(at, radius_ + p_.clearance_m) - radius_ - 1e-3));
  const double beside = std::min(p_.lookahead_m, step.structure_m - p_.stop_distance_m);
  std::optional<double> chosen;
  const double step_rad = M_PI / 36;
  for (double off = 0.0; off <= p_.max_deviation_rad + 1e-9 && !chosen; off += step_rad) {
    for (const double sign : {1.0, -1.0}) {
      if (off == 0.0 && sign < 0) continue;
      const double h = NormalizeAngle(direction_ + sign * off);
      if (!Clear(at, h, obstacles)) continue;
      if (off > 0.0 && known.FreeRun(at, h, radius_, p_.lookahead_m) < p_.lookahead_m) continue;
      if (known.FreeRun(at, h, radius_ + margin, beside) < beside) continue;
      chosen = h;
      break;
    }
  }
  if (!chosen) {
    step.heading = direction_;
    if (now_s - last_progress_s_ > p_.blocked_timeout_s) {
      step.stopped = true;
      step.why = "new obstacles block every way within the deviation allowed";
    }
    return step;  // wait for the way to clear
  }
  last_progress_s_ = now_s;
  step.heading = *chosen;
  const double facing = reverse_ ? pose.yaw + M_PI : pose.yaw;
  const double error = NormalizeAngle(*chosen - facing);
  step.command.angular_rps = std::clamp(p_.heading_gain_per_s * error, -max_angular_, max_angular_);
  if (std::abs(error) < 0.6) {
    // Slow down as the structure ahead comes near.
    const double room = step.structure_m - p_.stop_distance_m;
    const double v = std::min(speed_, std::max(0.05, room)) * std::cos(error);
    step.command.linear_mps = reverse_ ? -v : v;
  }
  return step;
}

}  // namespace spott_tr_plus::controller
