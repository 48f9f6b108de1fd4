#include "rpl_executive/noreils_chatila/pilot.h"

#include <algorithm>
#include <cmath>

namespace rpl_executive::noreils_chatila {

std::vector<std::string> ValidateParameters(const PilotParameters& p) {
  std::vector<std::string> v;
  if (!(p.max_speed_mps > 0.0)) v.push_back("max_speed_mps: must be above 0");
  if (!(p.default_speed_mps > 0.0 && p.default_speed_mps <= p.max_speed_mps)) {
    v.push_back("default_speed_mps: must be in (0, max_speed_mps]");
  }
  if (!(p.max_angular_rps > 0.0)) v.push_back("max_angular_rps: must be above 0");
  if (!(p.lookahead_m >= 0.0)) v.push_back("lookahead_m: must be 0 or more");
  if (!(p.k_x > 0.0)) v.push_back("k_x: must be above 0");
  if (!(p.k_y > 0.0)) v.push_back("k_y: must be above 0");
  if (!(p.k_theta > 0.0)) v.push_back("k_theta: must be above 0");
  if (!(p.goal_tolerance_m > 0.0)) v.push_back("goal_tolerance_m: must be above 0");
  if (!(p.heading_tolerance_rad > 0.0 && p.heading_tolerance_rad < kPi)) {
    v.push_back("heading_tolerance_rad: must be in (0, pi)");
  }
  if (!(p.turn_in_place_rad > 0.0 && p.turn_in_place_rad <= kPi)) {
    v.push_back("turn_in_place_rad: must be in (0, pi]");
  }
  if (!(p.k_turn > 0.0)) v.push_back("k_turn: must be above 0");
  if (!(p.slow_down_distance_m >= 0.0)) v.push_back("slow_down_distance_m: must be 0 or more");
  for (const std::string& s : ValidateParameters(p.smoothing)) v.push_back("smoothing." + s);
  return v;
}

Pilot::Pilot(const PilotParameters& parameters)
    : parameters_(parameters), speed_mps_(parameters.default_speed_mps) {}

void Pilot::Start(const Pose2& pose, const std::vector<Point2>& vertices,
                  std::optional<double> final_yaw_rad) {
  vertices_ = vertices;
  final_yaw_ = final_yaw_rad;
  first_vertex_ = 0;
  std::vector<Point2> line = {Point2{pose.x, pose.y}};
  line.insert(line.end(), vertices_.begin(), vertices_.end());
  path_ = SmoothBrokenLine(line, parameters_.smoothing);
  vertex_s_.clear();
  double s = 0.0;
  for (size_t i = 0; i < vertices_.size(); ++i) {
    s += Distance(line[i], line[i + 1]);
    vertex_s_.push_back(s);
  }
  progress_ = 0;
  state_ =
      path_.samples.size() < 2 ? (final_yaw_ ? State::kFinalTurn : State::kDone) : State::kTracking;
}

size_t Pilot::NextVertexIndex() const {
  // The vertices not passed yet: those beyond the progress made along the path.
  const double s_now = path_.samples.empty() ? 0.0 : path_.samples[progress_].s;
  size_t next = first_vertex_;
  for (size_t i = 0; i < vertex_s_.size(); ++i) {
    if (vertex_s_[i] > s_now + parameters_.goal_tolerance_m) {
      next = first_vertex_ + i;
      break;
    }
    next = first_vertex_ + i + 1;
  }
  return std::min(next, vertices_.size() - 1);
}

std::vector<Point2> Pilot::RemainingVertices() const {
  if (vertices_.empty()) return {};
  return std::vector<Point2>(vertices_.begin() + NextVertexIndex(), vertices_.end());
}

bool Pilot::Resume(const Pose2& pose) {
  if (vertices_.empty()) return false;
  const size_t next = NextVertexIndex();
  const std::vector<Point2> rest(vertices_.begin() + next, vertices_.end());
  const std::vector<Point2> all = vertices_;
  const std::optional<double> yaw = final_yaw_;
  Start(pose, rest, yaw);
  vertices_ = all;
  first_vertex_ = next;
  return true;
}

void Pilot::SetSpeed(double speed_mps) {
  speed_mps_ = std::clamp(speed_mps, 0.0, parameters_.max_speed_mps);
}

void Pilot::Stop() {
  if (state_ == State::kTracking || state_ == State::kFinalTurn) state_ = State::kIdle;
}

VelocityCommand Pilot::Update(const Pose2& pose) {
  VelocityCommand cmd;
  if (state_ == State::kTracking) cmd = Track(pose);
  if (state_ == State::kFinalTurn) {
    const double e = WrapAngle(*final_yaw_ - pose.yaw);
    if (std::fabs(e) <= parameters_.heading_tolerance_rad) {
      state_ = State::kDone;
      return VelocityCommand{};
    }
    cmd.linear_mps = 0.0;
    cmd.angular_rps = std::clamp(parameters_.k_turn * e, -parameters_.max_angular_rps,
                                 parameters_.max_angular_rps);
  }
  return cmd;
}

VelocityCommand Pilot::Track(const Pose2& pose) {
  const auto& samples = path_.samples;
  // Nearest sample ahead of the progress made (a window, so that a path coming back near
  // itself is not short-cut).
  const double window_m = 1.0 + 2.0 * parameters_.lookahead_m;
  size_t best = progress_;
  double best_d = 1e300;
  for (size_t i = progress_; i < samples.size() && samples[i].s <= samples[progress_].s + window_m;
       ++i) {
    const double d = std::hypot(samples[i].x - pose.x, samples[i].y - pose.y);
    if (d < best_d) {
      best_d = d;
      best = i;
    }
  }
  progress_ = best;
  const PathSample& end = samples.back();
  const double remaining = end.s - samples[progress_].s;
  const double to_end = std::hypot(end.x - pose.x, end.y - pose.y);
  // Past the end's normal line, or within tolerance of it: arrived.
  const double along_end =
      std::cos(end.yaw) * (pose.x - end.x) + std::sin(end.yaw) * (pose.y - end.y);
  if (to_end <= parameters_.goal_tolerance_m ||
      (remaining <= parameters_.goal_tolerance_m && along_end >= 0.0)) {
    state_ = final_yaw_ ? State::kFinalTurn : State::kDone;
    return VelocityCommand{};
  }
  size_t ref = progress_;
  while (ref + 1 < samples.size() &&
         samples[ref].s < samples[progress_].s + parameters_.lookahead_m) {
    ++ref;
  }
  const PathSample& r = samples[ref];
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  const double ex = c * (r.x - pose.x) + s * (r.y - pose.y);
  const double ey = -s * (r.x - pose.x) + c * (r.y - pose.y);
  const double et = WrapAngle(r.yaw - pose.yaw);
  // Turn in place when the path's heading (or the direction to the reference, at the start)
  // is far from ours.
  const double bearing = std::atan2(ey, ex);
  const double heading_error = std::hypot(ex, ey) > 0.05 ? bearing : et;
  if (std::fabs(heading_error) > parameters_.turn_in_place_rad) {
    return VelocityCommand{
        0.0, std::clamp(parameters_.k_turn * heading_error, -parameters_.max_angular_rps,
                        parameters_.max_angular_rps)};
  }
  double vr = speed_mps_;
  if (parameters_.slow_down_distance_m > 0.0 && remaining < parameters_.slow_down_distance_m) {
    vr *= std::max(0.2, remaining / parameters_.slow_down_distance_m);
  }
  const double wr = r.curvature * vr;
  VelocityCommand cmd;
  // e_x is measured from the reference, which is ahead by (at most) the lookahead: the
  // longitudinal error is what is left after that offset.
  const double offset = r.s - samples[progress_].s;
  cmd.linear_mps = std::clamp(vr * std::cos(et) + parameters_.k_x * (ex - offset), 0.0,
                              parameters_.max_speed_mps);
  cmd.angular_rps =
      std::clamp(wr + vr * (parameters_.k_y * ey + parameters_.k_theta * std::sin(et)),
                 -parameters_.max_angular_rps, parameters_.max_angular_rps);
  return cmd;
}

}  // namespace rpl_executive::noreils_chatila
