// Conversions between the TR+ interpreter's core types and spott_msgs messages.
#pragma once

#include <ros/time.h>
#include <spott_msgs/ConditionState.h>
#include <spott_msgs/TRProgramState.h>

#include <string>
#include <vector>

#include "spott_tr_plus/interpreter.h"

namespace spott_tr_plus {
namespace ros_conversions {

/// The live state: the call chain, the firing rule of the deepest active program that has one
/// (the rule whose action is executing), and every condition process.
spott_msgs::TRProgramState ToMsg(const InterpreterState& state, const ProgramFile& program,
                                 const ros::Time& stamp);

/// A condition value pushed from outside. `name` is "name" or "name(input, ...)" with inputs
/// written as values ("\"door\"", 1.5); outputs come from the attributes, in declaration order
/// of the condition's output parameters (matched by key).
struct ConditionUpdate {
  std::string name;
  std::vector<Value> inputs;
  bool value = false;
  std::vector<Value> outputs;
};

/// Nullopt-like: returns false and an error when `msg` does not name a declared condition or its
/// inputs/outputs do not match the declaration.
bool FromMsg(const spott_msgs::ConditionState& msg, const ProgramFile& program,
             ConditionUpdate* update, std::string* error);

}  // namespace ros_conversions
}  // namespace spott_tr_plus
