// The start of every rviz marker the nodes publish, so that each package's markers look alike
// (frame, stamp, identity orientation, a visible default size and colour).
#pragma once

#include <ros/time.h>
#include <std_msgs/ColorRGBA.h>
#include <visualization_msgs/Marker.h>

#include <string>

namespace spott_ros {

/// A marker colour; components in [0, 1].
std_msgs::ColorRGBA Colour(float r, float g, float b, float a = 1.0f);

/// A marker to fill in: action ADD, identity orientation, scale 0.1 m, white, never expiring.
visualization_msgs::Marker MakeMarker(const std::string& ns, int id, int type,
                                      const std::string& frame_id, const ros::Time& stamp);

}  // namespace spott_ros
