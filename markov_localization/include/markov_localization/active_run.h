// The sequencing of one active localization run (Beetz et al. section 2.2 and 2.3): from a
// uniform belief a short random motion (about ten metres, as the paper's robot did) before the
// first active choice; then choose a* (ActiveLocalizer), drive there, re-choose after each
// target is reached or failed, until the certainty exceeds the threshold, or give up with a
// reason (timeout, no reachable target, navigation failed N times).
//
// ROS-free and clock-free: the caller passes `now` and the odometry distance with each input,
// and carries out the returned action (wander, choose, cancel the navigation goal, end).
#pragma once

#include <string>
#include <vector>

#include "spott_map/world.h"

namespace markov_localization {

using spott_map::Pose2;

struct ActiveRunParameters {
  double random_motion_m = 10.0;  ///< Random motion before the first choice (m, paper: ~10), >= 0.
  /// When a* is (almost) the robot's own position no target promises more certainty than
  /// staying: wander this far (m) and choose again. > 0.
  double rewander_m = 3.0;
  double min_target_distance_m = 0.5;  ///< a* closer than this counts as "stay" (m), >= 0.
  int max_navigation_failures = 5;     ///< Give up after this many failed targets / stays, >= 1.
  /// A jump of the estimate (the robot's pose through map -> odom now and through map -> odom
  /// when the target was sent) by more than this while driving means the belief changed its
  /// mind: the target was computed in the wrong frame; cancel and re-choose.
  double estimate_jump_m = 2.0;     ///< (m), > 0
  double estimate_jump_rad = 0.5;   ///< (rad), > 0
  double target_timeout_s = 120.0;  ///< Time to reach one target (s), > 0.
  /// The certainty must stay above the threshold this long before the run ends in success
  /// (s, >= 0; 0 = at the first scan above it, as the paper). A twin that crosses the threshold
  /// for a moment while the robot looks through a door does not end the run.
  double confirm_s = 2.0;
};

/// Every violation by parameter name; empty when valid.
std::vector<std::string> ValidateParameters(const ActiveRunParameters& params);

/// What a client asks for (spott_msgs/ActiveLocalize goal).
struct ActiveRequest {
  double certainty_threshold = 0.0;  ///< In (0, 1); 0 = the node's default.
  double timeout_s = 0.0;            ///< >= 0; 0 = no limit.
  bool start_uniform = false;
};

/// Empty when the request can be served, else the reason it is refused.
std::string CheckRequest(const ActiveRequest& request);
/// The threshold the run uses: the request's, or `default_threshold` when it asks for 0.
double EffectiveThreshold(const ActiveRequest& request, double default_threshold);

/// What the caller feeds the run after every localization update.
struct RunInput {
  double now_s = 0.0;            ///< Time (s), any epoch, non-decreasing.
  double certainty = 0.0;        ///< POS-CERTAINTY of the belief.
  double odom_distance_m = 0.0;  ///< Distance driven since any fixed origin (odometry, m).
  Pose2 map_to_odom;             ///< The published estimate's map -> odom transform (x, y, yaw).
  Pose2 odom;                    ///< The robot's odometry pose.
};

enum class RunPhase { kWander, kChoose, kNavigate, kSucceeded, kAborted };

/// What the caller must do now.
enum class RunAction {
  kWander,           ///< Drive the random motion (obstacle-avoiding, no map needed).
  kChoose,           ///< Stop, compute a* and report it with OnChoice.
  kWait,             ///< A navigation goal is under way; nothing to do.
  kCancelAndChoose,  ///< Cancel the navigation goal, then compute a* and call OnChoice.
  kSucceed,          ///< Certain: end with success.
  kAbort,            ///< Give up; reason() says why.
};

const char* ToString(RunPhase phase);

class ActiveLocalizationRun {
 public:
  /// `random_motion_first`: begin with the random motion (from a uniform belief) rather than
  /// with a choice. Throws std::invalid_argument on invalid parameters.
  ActiveLocalizationRun(const ActiveRunParameters& params, double threshold, double timeout_s,
                        bool random_motion_first, const RunInput& start);

  /// The action for this update; terminal actions repeat once reached.
  RunAction Step(const RunInput& in);
  /// The result of a kChoose / kCancelAndChoose: whether a target was found and a* (m ahead,
  /// m left of the robot). A found target is to be driven to (phase kNavigate).
  void OnChoice(bool found, double ahead_m, double left_m, const RunInput& in);
  /// The navigation goal sent after OnChoice ended: reached, or failed with `reason`.
  void OnNavigationDone(bool reached, const std::string& reason, const RunInput& in);

  RunPhase phase() const { return phase_; }
  const std::string& reason() const { return reason_; }
  int targets_visited() const { return targets_visited_; }
  int navigation_failures() const { return failures_; }
  double threshold() const { return threshold_; }

 private:
  RunAction Abort(const std::string& reason);
  RunAction Fail(const std::string& why, const RunInput& in);
  void StartWander(double distance_m, const RunInput& in);

  ActiveRunParameters params_;
  double threshold_;
  double timeout_s_;
  double start_s_;
  RunPhase phase_;
  std::string reason_;
  double wander_start_m_ = 0.0;
  double wander_goal_m_ = 0.0;
  double target_sent_s_ = 0.0;
  Pose2 frame_at_send_;
  int targets_visited_ = 0;
  int failures_ = 0;
  double above_since_s_ = -1.0;  ///< When the certainty went above the threshold (< 0: not).
  std::string last_failure_;
};

}  // namespace markov_localization
