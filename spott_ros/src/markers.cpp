#include "spott_ros/markers.h"

namespace spott_ros {

std_msgs::ColorRGBA Colour(float r, float g, float b, float a) {
  std_msgs::ColorRGBA c;
  c.r = r;
  c.g = g;
  c.b = b;
  c.a = a;
  return c;
}

visualization_msgs::Marker MakeMarker(const std::string& ns, int id, int type,
                                      const std::string& frame_id, const ros::Time& stamp) {
  visualization_msgs::Marker m;
  m.header.frame_id = frame_id;
  m.header.stamp = stamp;
  m.ns = ns;
  m.id = id;
  m.type = type;
  m.action = visualization_msgs::Marker::ADD;
  m.pose.orientation.w = 1.0;
  m.scale.x = m.scale.y = m.scale.z = 0.1;
  m.color = Colour(1.0f, 1.0f, 1.0f);
  m.lifetime = ros::Duration(0.0);
  return m;
}

}  // namespace spott_ros
