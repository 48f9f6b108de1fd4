#include "markov_localization/active_run.h"
#include "markov_localization/validation.h"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace markov_localization {

std::vector<std::string> ValidateParameters(const ActiveRunParameters& p) {
  std::vector<std::string> errors;
  if (!(p.random_motion_m >= 0.0 && std::isfinite(p.random_motion_m)))
    errors.push_back("random_motion_m must be >= 0 m");
  if (!(p.rewander_m > 0.0 && std::isfinite(p.rewander_m)))
    errors.push_back("rewander_m must be > 0 m");
  if (!(p.min_target_distance_m >= 0.0)) errors.push_back("min_target_distance_m must be >= 0 m");
  if (p.max_navigation_failures < 1) errors.push_back("max_navigation_failures must be >= 1");
  if (!(p.estimate_jump_m > 0.0)) errors.push_back("estimate_jump_m must be > 0 m");
  if (!(p.estimate_jump_rad > 0.0)) errors.push_back("estimate_jump_rad must be > 0 rad");
  if (!(p.target_timeout_s > 0.0)) errors.push_back("target_timeout_s must be > 0 s");
  if (!(p.confirm_s >= 0.0 && std::isfinite(p.confirm_s)))
    errors.push_back("confirm_s must be >= 0 s");
  return errors;
}

std::string CheckRequest(const ActiveRequest& r) {
  char text[160];
  if (!std::isfinite(r.timeout_s) || r.timeout_s < 0.0) {
    std::snprintf(text, sizeof(text), "timeout must be >= 0 s (0 = no limit), got %g", r.timeout_s);
    return text;
  }
  if (r.certainty_threshold != 0.0 &&
      !(r.certainty_threshold > 0.0 && r.certainty_threshold < 1.0)) {
    std::snprintf(text, sizeof(text),
                  "certainty_threshold must be in (0, 1) (0 = the node's default), got %g",
                  r.certainty_threshold);
    return text;
  }
  return "";
}

double EffectiveThreshold(const ActiveRequest& r, double default_threshold) {
  return r.certainty_threshold == 0.0 ? default_threshold : r.certainty_threshold;
}

const char* ToString(RunPhase phase) {
  switch (phase) {
    case RunPhase::kWander:
      return "random motion";
    case RunPhase::kChoose:
      return "choosing a target";
    case RunPhase::kNavigate:
      return "driving to a target";
    case RunPhase::kSucceeded:
      return "succeeded";
    case RunPhase::kAborted:
      return "aborted";
  }
  return "?";
}

ActiveLocalizationRun::ActiveLocalizationRun(const ActiveRunParameters& params, double threshold,
                                             double timeout_s, bool random_motion_first,
                                             const RunInput& start)
    : params_(params),
      threshold_(threshold),
      timeout_s_(timeout_s),
      start_s_(start.now_s),
      phase_(RunPhase::kChoose) {
  auto errors = ValidateParameters(params);
  if (!(threshold > 0.0 && threshold < 1.0)) errors.push_back("threshold must be in (0, 1)");
  if (!(timeout_s >= 0.0)) errors.push_back("timeout_s must be >= 0");
  ThrowIfInvalid(errors);
  if (random_motion_first && params_.random_motion_m > 0.0)
    StartWander(params_.random_motion_m, start);
}

void ActiveLocalizationRun::StartWander(double distance_m, const RunInput& in) {
  phase_ = RunPhase::kWander;
  wander_start_m_ = in.odom_distance_m;
  wander_goal_m_ = distance_m;
}

RunAction ActiveLocalizationRun::Abort(const std::string& reason) {
  phase_ = RunPhase::kAborted;
  reason_ = reason;
  return RunAction::kAbort;
}

RunAction ActiveLocalizationRun::Fail(const std::string& why, const RunInput& in) {
  ++failures_;
  last_failure_ = why;
  if (failures_ >= params_.max_navigation_failures) {
    return Abort("navigation failed " + std::to_string(failures_) + " times (last: " + why + ")");
  }
  (void)in;
  phase_ = RunPhase::kChoose;
  return RunAction::kCancelAndChoose;
}

RunAction ActiveLocalizationRun::Step(const RunInput& in) {
  if (phase_ == RunPhase::kSucceeded) return RunAction::kSucceed;
  if (phase_ == RunPhase::kAborted) return RunAction::kAbort;
  if (in.certainty > threshold_) {
    if (above_since_s_ < 0.0) above_since_s_ = in.now_s;
    if (in.now_s - above_since_s_ >= params_.confirm_s) {
      phase_ = RunPhase::kSucceeded;
      reason_.clear();
      return RunAction::kSucceed;
    }
  } else {
    above_since_s_ = -1.0;
  }
  const double elapsed = in.now_s - start_s_;
  if (timeout_s_ > 0.0 && elapsed >= timeout_s_) {
    char text[160];
    std::snprintf(text, sizeof(text), "timeout: certainty %.2f is below %.2f after %.1f s (%s)",
                  in.certainty, threshold_, elapsed, ToString(phase_));
    return Abort(text);
  }
  switch (phase_) {
    case RunPhase::kWander:
      if (in.odom_distance_m - wander_start_m_ < wander_goal_m_) return RunAction::kWander;
      phase_ = RunPhase::kChoose;
      return RunAction::kChoose;
    case RunPhase::kChoose:
      return RunAction::kChoose;
    case RunPhase::kNavigate: {
      // Where the robot is by the current frame and by the frame the target was sent in (far
      // from the odometry origin a small turn of map -> odom moves its translation a lot).
      const double c0 = std::cos(frame_at_send_.yaw), s0 = std::sin(frame_at_send_.yaw);
      const double c1 = std::cos(in.map_to_odom.yaw), s1 = std::sin(in.map_to_odom.yaw);
      const double dx = (in.map_to_odom.x + c1 * in.odom.x - s1 * in.odom.y) -
                        (frame_at_send_.x + c0 * in.odom.x - s0 * in.odom.y);
      const double dy = (in.map_to_odom.y + s1 * in.odom.x + c1 * in.odom.y) -
                        (frame_at_send_.y + s0 * in.odom.x + c0 * in.odom.y);
      const double dyaw = std::remainder(in.map_to_odom.yaw - frame_at_send_.yaw, 2.0 * M_PI);
      if (std::hypot(dx, dy) > params_.estimate_jump_m ||
          std::abs(dyaw) > params_.estimate_jump_rad) {
        // Not a failure: the belief moved its maximum, so the target (sent in the map frame
        // through the old estimate) is no longer where a* is. Choose again from the new belief.
        phase_ = RunPhase::kChoose;
        return RunAction::kCancelAndChoose;
      }
      if (in.now_s - target_sent_s_ > params_.target_timeout_s) {
        char text[96];
        std::snprintf(text, sizeof(text), "target not reached within %.0f s",
                      params_.target_timeout_s);
        return Fail(text, in);
      }
      return RunAction::kWait;
    }
    default:
      return RunAction::kWait;
  }
}

void ActiveLocalizationRun::OnChoice(bool found, double ahead_m, double left_m,
                                     const RunInput& in) {
  if (phase_ != RunPhase::kChoose) return;
  if (!found) {
    Abort("no reachable target: every target point is occupied or unreachable under the modes");
    return;
  }
  if (std::hypot(ahead_m, left_m) < params_.min_target_distance_m) {
    // Staying is the best choice: the modes cannot be told apart from anywhere within reach.
    ++failures_;
    last_failure_ = "a* is the robot's own position";
    if (failures_ >= params_.max_navigation_failures) {
      Abort("no informative target: a* was the robot's own position (" + std::to_string(failures_) +
            " failures)");
      return;
    }
    StartWander(params_.rewander_m, in);
    return;
  }
  phase_ = RunPhase::kNavigate;
  target_sent_s_ = in.now_s;
  frame_at_send_ = in.map_to_odom;
}

void ActiveLocalizationRun::OnNavigationDone(bool reached, const std::string& reason,
                                             const RunInput& in) {
  if (phase_ != RunPhase::kNavigate) return;
  if (reached) {
    ++targets_visited_;
    phase_ = RunPhase::kChoose;
    return;
  }
  if (Fail(reason, in) == RunAction::kAbort) return;
  phase_ = RunPhase::kChoose;
}

}  // namespace markov_localization
