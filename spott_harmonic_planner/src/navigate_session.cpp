#include "spott_harmonic_planner/navigate_session.h"

#include <cmath>
#include <sstream>

namespace spott_harmonic_planner {

std::optional<double> DirectionBias::HeadingAt(const Vec2& position) const {
  const Vec2 d = point - position;
  switch (kind) {
    case Kind::kHeading:
      return heading && std::isfinite(*heading) ? heading : std::nullopt;
    case Kind::kToward:
      if (d.norm() < 1e-6) return std::nullopt;
      return std::atan2(d.y(), d.x());
    case Kind::kAway:
      if (d.norm() < 1e-6) return std::nullopt;
      return std::atan2(-d.y(), -d.x());
    case Kind::kVia:
      if (d.norm() <= radius || d.norm() < 1e-6) return std::nullopt;
      return std::atan2(d.y(), d.x());
    case Kind::kAround: {
      if (d.norm() < 1e-6) return std::nullopt;
      // The radial direction (from the point to the robot) turned by +-90 degrees.
      const Vec2 r = -d / d.norm();
      const double s = sense >= 0.0 ? 1.0 : -1.0;
      return std::atan2(s * r.x(), -s * r.y());
    }
  }
  return std::nullopt;
}

std::vector<std::string> ValidateParameters(const NavigateSessionParameters& p) {
  std::vector<std::string> v;
  if (!(p.planning_timeout_s > 0.0 && p.planning_timeout_s <= 600.0))
    v.push_back("navigate/planning_timeout_s must be in (0, 600]");
  if (p.unreachable_cycles < 1) v.push_back("navigate/unreachable_cycles must be >= 1");
  if (!(p.backoff_distance_m > 0.0 && p.backoff_distance_m <= 2.0))
    v.push_back("navigate/backoff_distance_m must be in (0, 2]");
  if (!(p.backoff_speed_mps > 0.0 && p.backoff_speed_mps <= 1.0))
    v.push_back("navigate/backoff_speed_mps must be in (0, 1]");
  if (!(p.arrival_stall_s > 0.0 && p.arrival_stall_s <= 60.0))
    v.push_back("navigate/arrival_stall_s must be in (0, 60]");
  if (!(p.planner_patience_s >= 0.0 && p.planner_patience_s <= 600.0))
    v.push_back("navigate/planner_patience_s must be in [0, 600]");
  if (!(p.settle_timeout_s >= 0.0 && p.settle_timeout_s <= 60.0))
    v.push_back("navigate/settle_timeout_s must be in [0, 60]");
  if (p.max_settle_drive_ons < 0) v.push_back("navigate/max_settle_drive_ons must be >= 0");
  if (!(p.settle_max_offset_m > 0.0 && p.settle_max_offset_m <= 100.0))
    v.push_back("navigate/settle_max_offset_m must be in (0, 100]");
  if (!(p.lost_timeout_s >= 0.0 && p.lost_timeout_s <= 600.0))
    v.push_back("navigate/lost_timeout_s must be in [0, 600]");
  if (!(p.progress_radius_m > 0.0 && p.progress_radius_m <= 10.0))
    v.push_back("navigate/progress_radius_m must be in (0, 10]");
  if (!(p.progress_timeout_s >= 0.0 && p.progress_timeout_s <= 600.0))
    v.push_back("navigate/progress_timeout_s must be in [0, 600]");
  return v;
}

NavigateSession::NavigateSession(const NavigateSessionParameters& params, double now_s)
    : params_(params), started_s_(now_s) {
  note_ = "waiting for the robot's pose";
}

void NavigateSession::Answer(const GlobalAnswer& answer) {
  if (finished()) return;
  const bool driving = phase_ == NavigatePhase::kDriving || phase_ == NavigatePhase::kRecovering;
  const bool had_way = answer_ && answer_->state == GlobalAnswer::State::kPlanned;
  answer_ = answer;
  switch (answer.state) {
    case GlobalAnswer::State::kPlanned:
      path_summary_ = answer.path_summary;
      if (lost_way_) {  // the way is back
        lost_way_.reset();
        lost_way_since_s_.reset();
        note_.clear();
        bad_cycles_ = 0;
        if (!backoff_) SetPhase(NavigatePhase::kDriving);
      }
      break;
    case GlobalAnswer::State::kFailed:
      if (driving && had_way && params_.planner_patience_s > 0.0) {
        lost_way_ = answer;  // waited for in Update
        note_ = "the global planner finds no way (" + answer.message + "): waiting for one";
        SetPhase(NavigatePhase::kRecovering);
        break;
      }
      Finish(NavigateOutcome::kUnreachable, answer.message);
      break;
    case GlobalAnswer::State::kRefused:
      Finish(NavigateOutcome::kFailed, "the global planner refused the goal: " + answer.message);
      break;
  }
}

void NavigateSession::Update(double now_s) {
  if (lost_way_ && !finished()) {
    if (!lost_way_since_s_) lost_way_since_s_ = now_s;
    if (now_s - *lost_way_since_s_ >= params_.planner_patience_s) {
      std::ostringstream why;
      why << lost_way_->message << " (no way for " << params_.planner_patience_s << " s)";
      Finish(NavigateOutcome::kUnreachable, why.str());
    }
    return;
  }
  if (phase_ != NavigatePhase::kPlanning) return;
  const bool global_ready =
      !params_.use_global_planner ||
      (answer_ && answer_->state == GlobalAnswer::State::kPlanned && have_projection_);
  if (have_pose_ && global_ready) {
    SetPhase(NavigatePhase::kDriving);
    return;
  }
  note_ = !have_pose_ ? "waiting for the robot's pose (tf map -> base_link)"
          : !answer_  ? "waiting for the global planner's answer"
                      : "waiting for the global planner's projected goal";
  if (now_s - started_s_ > params_.planning_timeout_s) {
    std::ostringstream why;
    why << "no start after " << params_.planning_timeout_s << " s: still " << note_;
    Finish(NavigateOutcome::kFailed, why.str());
  }
}

void NavigateSession::Steered(bool valid, bool escaping, bool border_widened,
                              const std::string& reason, bool exploring) {
  if (phase_ != NavigatePhase::kDriving && phase_ != NavigatePhase::kRecovering) return;
  if (backoff_) return;
  bad_cycles_ = valid ? 0 : bad_cycles_ + 1;
  if (bad_cycles_ >= params_.unreachable_cycles) {
    Finish(NavigateOutcome::kUnreachable, reason);
    return;
  }
  if (valid && (escaping || border_widened)) {
    note_ = escaping ? "escaping the padding of an obstacle"
                     : "the projected border goal was blocked: widened";
    SetPhase(NavigatePhase::kRecovering);
  } else {
    note_ = valid && exploring ? "exploring: the goal is cut off by sensed obstacles in the "
                                 "window; heading for the reachable border nearest it"
                               : "";
    SetPhase(NavigatePhase::kDriving);
  }
}

void NavigateSession::Contact(double angle_rad, const spott_map::Pose2& odom) {
  if (phase_ != NavigatePhase::kDriving && phase_ != NavigatePhase::kRecovering) return;
  ++contacts_;
  if (backoff_) return;  // already backing off
  // Move along the robot's axis away from the contact (a side contact: backwards).
  backoff_ = BackOffState{
      odom, std::cos(angle_rad) > 0.0 || std::abs(std::cos(angle_rad)) < 0.2 ? -1.0 : 1.0};
  note_ = "backing off a bumper contact";
  SetPhase(NavigatePhase::kRecovering);
}

std::optional<double> NavigateSession::BackOff(const spott_map::Pose2& odom) {
  if (!backoff_) return std::nullopt;
  const double moved = std::hypot(odom.x - backoff_->start.x, odom.y - backoff_->start.y);
  if (moved >= params_.backoff_distance_m || finished()) {
    backoff_.reset();
    bad_cycles_ = 0;
    note_.clear();
    if (!finished()) SetPhase(lost_way_ ? NavigatePhase::kRecovering : NavigatePhase::kDriving);
    return std::nullopt;
  }
  return backoff_->direction * params_.backoff_speed_mps;
}

bool NavigateSession::Arrived(double distance_m, double tolerance_m, double now_s) {
  if (distance_m < closest_m_ - 0.01) {
    closest_m_ = distance_m;
    closer_at_s_ = now_s;
  }
  if (distance_m <= 0.5 * tolerance_m) return true;
  return distance_m <= tolerance_m && now_s - closer_at_s_ >= params_.arrival_stall_s;
}

void NavigateSession::LocalizationUpdated(double stamp_s) {
  if (!localization_stamp_s_ || stamp_s > *localization_stamp_s_) localization_stamp_s_ = stamp_s;
}

NavigateSession::Settle NavigateSession::Settled(double distance_m, double tolerance_m,
                                                 double now_s) {
  if (lost_) {
    if (!lost_since_s_) {
      lost_since_s_ = now_s;
      note_ = "arrived on the estimate, but the localization is lost: standing until it is certain";
    }
    if (now_s - *lost_since_s_ < params_.lost_timeout_s) return Settle::kWait;
    std::ostringstream reason;
    reason << "not localized: arrived on the estimate, but the localization has been lost for "
           << now_s - *lost_since_s_ << " s (navigate/lost_timeout_s)";
    Finish(NavigateOutcome::kFailed, reason.str());
    return Settle::kNotLocalized;
  }
  if (lost_since_s_) {  // certain again: judged on the relocalized estimate
    settle_since_s_ = *lost_since_s_;
    lost_since_s_.reset();
    relocalized_ = true;
  }
  if (!localization_stamp_s_ || params_.settle_timeout_s <= 0.0 ||
      (drive_ons_ >= params_.max_settle_drive_ons && !relocalized_))
    return Settle::kArrived;
  if (!settle_since_s_) {
    settle_since_s_ = now_s;
    note_ = "arrived on the estimate: waiting for the localization's update of the standing robot";
  }
  const bool updated = *localization_stamp_s_ >= *settle_since_s_;
  if (!updated && now_s - *settle_since_s_ < params_.settle_timeout_s) return Settle::kWait;
  settle_since_s_.reset();
  note_.clear();
  const bool relocalized = relocalized_;
  relocalized_ = false;
  if (!updated || distance_m <= tolerance_m ||
      (distance_m > params_.settle_max_offset_m && !relocalized))
    return Settle::kArrived;
  ++drive_ons_;  // the estimate moved: approach again, judged afresh
  closest_m_ = 1e300;
  return Settle::kDriveOn;
}

void NavigateSession::Succeed() { Finish(NavigateOutcome::kSucceeded, "goal reached"); }

void NavigateSession::Preempt() { Finish(NavigateOutcome::kPreempted, "preempted"); }

void NavigateSession::Finish(NavigateOutcome outcome, const std::string& reason) {
  if (finished()) return;
  outcome_ = outcome;
  reason_ = reason;
  backoff_.reset();
  phase_ = NavigatePhase::kFinished;
}

void NavigateSession::SetPhase(NavigatePhase phase) {
  if (phase == NavigatePhase::kRecovering && phase_ != NavigatePhase::kRecovering) ++recoveries_;
  phase_ = phase;
}

void NavigateSession::Descending(const spott_map::Pose2& odom, double now_s) {
  if (finished() || params_.progress_timeout_s <= 0.0) return;
  if (!progress_ref_ || std::hypot(odom.x - progress_ref_->x, odom.y - progress_ref_->y) >=
                            params_.progress_radius_m) {
    progress_ref_ = odom;
    progress_since_s_ = now_s;
    return;
  }
  if (now_s - progress_since_s_ < params_.progress_timeout_s) return;
  std::ostringstream reason;
  reason << "no progress: the robot moved less than " << params_.progress_radius_m << " m in "
         << params_.progress_timeout_s
         << " s of descent (navigate/progress_timeout_s): held by an obstacle, or driven "
            "toward one on a wrong estimate";
  Finish(NavigateOutcome::kFailed, reason.str());
}

}  // namespace spott_harmonic_planner
