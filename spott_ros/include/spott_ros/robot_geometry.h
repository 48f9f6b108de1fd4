// The robot's footprint radius from its robot description (URDF): the one place every node
// takes it from, so that robot:=b21 pads obstacles for a B21 in every planner and in the
// localization alike (padding = radius + localization error).
#pragma once

#include <optional>
#include <string>

namespace ros {
class NodeHandle;
}

namespace spott_ros {

/// Radius (m) of the circle about `base_link`'s z axis that holds the base link's collision
/// geometry: a cylinder's radius, a box's half diagonal in x-y, a sphere's radius (plus the
/// collision origin's x-y offset). nullopt with `error` when the URDF does not parse, has no
/// such link, or the link has no collision geometry of those kinds.
std::optional<double> FootprintRadiusFromUrdf(const std::string& urdf_xml,
                                              const std::string& base_link, std::string* error);

/// The same, from the parameter `param` (e.g. "robot_description", resolved against `nh` and
/// its parents like robot_state_publisher does).
std::optional<double> FootprintRadiusFromParameter(const ros::NodeHandle& nh,
                                                   const std::string& param,
                                                   const std::string& base_link,
                                                   std::string* error);

}  // namespace spott_ros
