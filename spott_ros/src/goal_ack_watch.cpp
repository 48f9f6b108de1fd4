#include "spott_ros/goal_ack_watch.h"

#include <cmath>
#include <stdexcept>

namespace spott_ros {

GoalAckWatch::GoalAckWatch(double timeout_s) : timeout_s_(timeout_s) {
  if (!(std::isfinite(timeout_s) && timeout_s > 0.0)) {
    throw std::invalid_argument("goal acknowledgement timeout must be > 0 s and finite");
  }
}

void GoalAckWatch::Sent(double now_s) {
  sent_s_ = now_s;
  watching_ = true;
}

bool GoalAckWatch::ShouldResend(bool unacknowledged, double now_s) {
  if (!watching_) return false;
  if (!unacknowledged) {
    watching_ = false;
    return false;
  }
  if (now_s - sent_s_ < timeout_s_) return false;
  sent_s_ = now_s;
  ++resends_;
  return true;
}

}  // namespace spott_ros
