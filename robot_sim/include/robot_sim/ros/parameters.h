// Reading the node's private parameters: every known name, its type, and unknown names.
#pragma once

#include <string>
#include <vector>

#include <ros/node_handle.h>

#include "robot_sim/node_parameters.h"
#include "spott_ros/parameter_reader.h"

namespace robot_sim::ros_parameters {

/// Reads every parameter of config/robot_sim.yaml into `p` (defaults stay where a parameter is
/// unset) and records every problem in `r`: a wrong type, then every violation
/// ValidateParameters finds; r.Finish() adds the unknown names.
void Read(spott_ros::ParameterReader& r, SimNodeParameters& p);

/// The `faults` parameter (a list of events, see fault_events.h) as YAML text for
/// ParseFaultSchedule; "" when unset.
std::string FaultScheduleYaml(const ros::NodeHandle& pnh);
/// The same for the value of the `faults` parameter.
std::string FaultScheduleYaml(const XmlRpc::XmlRpcValue& faults);

}  // namespace robot_sim::ros_parameters
