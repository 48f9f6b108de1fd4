// Template part of parameter_reader.h (needs rosconsole, kept out of the reader's own header).
#pragma once

#include <ros/console.h>
#include <ros/node_handle.h>

namespace spott_ros {

template <class Params, class ReadFn>
std::optional<Params> ReadNodeParameters(const ros::NodeHandle& pnh, const char* node,
                                         ReadFn read) {
  ParameterReader reader = ParameterReader::FromNode(pnh);
  Params params;
  read(reader, params);
  const std::vector<std::string> problems = reader.Finish();
  for (const std::string& w : reader.Warnings()) ROS_WARN("%s: %s", node, w.c_str());
  if (!problems.empty()) {
    for (const std::string& p : problems) ROS_FATAL("%s: parameter %s", node, p.c_str());
    return std::nullopt;
  }
  return params;
}

}  // namespace spott_ros
