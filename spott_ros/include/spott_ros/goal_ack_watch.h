// actionlib can lose a goal: the client publishes it, the server never sees it (ros/actionlib
// issue 46, about 1 in 10 goals sent soon after the connection in move_base's case). The
// SimpleActionClient then waits in PENDING for ever and the robot stands still: a 600 s timeout
// on cim_office (2026-12-05) with the server's status list empty throughout. The watch tells
// the goal's sender, from its timer, when the goal has gone unacknowledged (no status from the
// server names it) for too long: the sender sends it again. A copy that did arrive is
// preempted by the new one (SimpleActionServer keeps the newest).
#pragma once

namespace spott_ros {

/// ROS-free: times are seconds of any monotonic clock (the senders use wall time: the loss is
/// the transport's, not the simulation's).
class GoalAckWatch {
 public:
  /// Throws std::invalid_argument unless timeout_s > 0 and finite.
  explicit GoalAckWatch(double timeout_s = 2.0);

  /// A goal was sent at now_s: the watch starts.
  void Sent(double now_s);
  /// The goal ended or was cancelled: nothing to watch.
  void Stop() { watching_ = false; }
  /// One check: `unacknowledged` is whether the client still waits for the server to name the
  /// goal (SimpleClientGoalState::PENDING). True when the goal is to be sent again; the watch
  /// then restarts from now_s. Once acknowledged, the goal is not watched any more.
  bool ShouldResend(bool unacknowledged, double now_s);

  bool watching() const { return watching_; }
  /// Goals sent again since construction.
  int resends() const { return resends_; }
  double timeout_s() const { return timeout_s_; }

 private:
  double timeout_s_;
  double sent_s_ = 0.0;
  bool watching_ = false;
  int resends_ = 0;
};

}  // namespace spott_ros
