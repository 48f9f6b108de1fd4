#include "spott_move_base/conversions.h"

#include <limits>

namespace spott_move_base {

spott_msgs::NavigateGoal ToNavigateGoal(const move_base_msgs::MoveBaseGoal& goal) {
  spott_msgs::NavigateGoal g;
  g.target = goal.target_pose;
  g.speed_mode = spott_msgs::NavigateGoal::NORMAL;
  g.direction_bias = std::numeric_limits<double>::quiet_NaN();
  g.position_tolerance = 0.0;  // the server's defaults
  g.heading_tolerance = 0.0;
  g.ignore_heading = false;
  return g;
}

MoveBaseEnd EndOf(const spott_msgs::NavigateResult& result) {
  switch (result.outcome) {
    case spott_msgs::NavigateResult::SUCCEEDED:
      return MoveBaseEnd::kSucceeded;
    case spott_msgs::NavigateResult::PREEMPTED:
      return MoveBaseEnd::kPreempted;
    default:
      return MoveBaseEnd::kAborted;
  }
}

std::string TextOf(const spott_msgs::NavigateResult& result) {
  switch (result.outcome) {
    case spott_msgs::NavigateResult::SUCCEEDED:
      return "goal reached";
    case spott_msgs::NavigateResult::UNREACHABLE:
      return "unreachable: " + result.reason;
    case spott_msgs::NavigateResult::PREEMPTED:
      return "preempted";
    default:
      return "failed: " + result.reason;
  }
}

}  // namespace spott_move_base
