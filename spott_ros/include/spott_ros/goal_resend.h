// The ROS side of GoalAckWatch (goal_ack_watch.h), one place for every goal sender: the clock
// (wall time: a goal lost in transport is lost whatever the simulation's pace), the client's
// state and the warning.
#pragma once

#include <ros/console.h>
#include <ros/time.h>

#include <string>

#include "spott_ros/goal_ack_watch.h"

namespace spott_ros {

/// The goal was sent now.
inline void MarkGoalSent(GoalAckWatch& watch) { watch.Sent(ros::WallTime::now().toSec()); }

/// True when the goal of `client` (an actionlib::SimpleActionClient) has stayed PENDING past the
/// watch's timeout: logged as `who`'s warning naming `action`; the caller sends it again.
template <class Client>
bool GoalLostInTransport(GoalAckWatch& watch, const Client& client, const std::string& who,
                         const std::string& action) {
  if (!watch.watching()) return false;
  using State = decltype(client.getState());
  if (!watch.ShouldResend(client.getState() == State::PENDING, ros::WallTime::now().toSec())) {
    return false;
  }
  ROS_WARN("%s: %s did not acknowledge the goal within %.1f s (lost in transport): sent again",
           who.c_str(), action.c_str(), watch.timeout_s());
  return true;
}

}  // namespace spott_ros
