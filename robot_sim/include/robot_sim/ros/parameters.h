// Reading the node's private parameters: every known name, its type, and unknown names.
#pragma once

#include <string>
#include <vector>

#include <ros/node_handle.h>

#include "robot_sim/node_parameters.h"

namespace robot_sim::ros_parameters {

/// Reads every parameter under `pnh` into `p` (defaults stay where a parameter is unset) and
/// returns one message per problem: a wrong type, an unknown name (a typo would otherwise be
/// silently ignored), then every violation ValidateParameters finds.
std::vector<std::string> Read(const ros::NodeHandle& pnh, SimNodeParameters& p);

/// The `faults` parameter (a list of events, see fault_events.h) as YAML text for
/// ParseFaultSchedule; "" when unset.
std::string FaultScheduleYaml(const ros::NodeHandle& pnh);

}  // namespace robot_sim::ros_parameters
