// move_base <-> Navigate: what the adapter maps, kept apart from the node so it is tested alone.
// A move_base goal is a Navigate goal at NORMAL speed that keeps the heading (move_base always
// turns to the goal's orientation), with the Navigate server's default tolerances.
#pragma once

#include <string>

#include <move_base_msgs/MoveBaseGoal.h>
#include <spott_msgs/NavigateGoal.h>
#include <spott_msgs/NavigateResult.h>

namespace spott_move_base {

spott_msgs::NavigateGoal ToNavigateGoal(const move_base_msgs::MoveBaseGoal& goal);

/// How a finished Navigate goal ends the move_base goal (actionlib terminal states).
enum class MoveBaseEnd { kSucceeded, kAborted, kPreempted };
MoveBaseEnd EndOf(const spott_msgs::NavigateResult& result);
/// The text move_base clients see with the end ("unreachable: doors d_lab_w are closed").
std::string TextOf(const spott_msgs::NavigateResult& result);

}  // namespace spott_move_base
