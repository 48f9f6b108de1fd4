#include "spott_ros/robot_geometry.h"

#include <cmath>

#include <ros/node_handle.h>
#include <urdf_model/model.h>
#include <urdf_parser/urdf_parser.h>

namespace spott_ros {

std::optional<double> FootprintRadiusFromUrdf(const std::string& urdf_xml,
                                              const std::string& base_link, std::string* error) {
  urdf::ModelInterfaceSharedPtr model;
  try {
    model = urdf::parseURDF(urdf_xml);
  } catch (const std::exception& e) {
    *error = std::string("cannot parse the robot description: ") + e.what();
    return std::nullopt;
  }
  if (!model) {
    *error = "cannot parse the robot description (not a valid URDF <robot>)";
    return std::nullopt;
  }
  const urdf::LinkConstSharedPtr link = model->getLink(base_link);
  if (!link) {
    *error = "the robot description has no link '" + base_link + "'";
    return std::nullopt;
  }
  double radius = 0.0;
  bool found = false;
  for (const urdf::CollisionSharedPtr& c : link->collision_array) {
    if (!c || !c->geometry) continue;
    const double offset = std::hypot(c->origin.position.x, c->origin.position.y);
    double r = -1.0;
    switch (c->geometry->type) {
      case urdf::Geometry::CYLINDER:
        r = static_cast<const urdf::Cylinder&>(*c->geometry).radius;
        break;
      case urdf::Geometry::SPHERE:
        r = static_cast<const urdf::Sphere&>(*c->geometry).radius;
        break;
      case urdf::Geometry::BOX: {
        const auto& d = static_cast<const urdf::Box&>(*c->geometry).dim;
        r = 0.5 * std::hypot(d.x, d.y);
        break;
      }
      default:
        break;
    }
    if (r > 0.0 && std::isfinite(r)) {
      radius = std::max(radius, r + offset);
      found = true;
    }
  }
  if (!found) {
    *error = "link '" + base_link +
             "' of the robot description has no <collision> cylinder, box or sphere";
    return std::nullopt;
  }
  return radius;
}

std::optional<double> FootprintRadiusFromParameter(const ros::NodeHandle& nh,
                                                   const std::string& param,
                                                   const std::string& base_link,
                                                   std::string* error) {
  std::string key;
  std::string xml;
  if (!nh.searchParam(param, key) || !nh.getParam(key, xml)) {
    *error = "no parameter '" + param + "' (the robot's URDF) to take the robot's radius from";
    return std::nullopt;
  }
  const auto r = FootprintRadiusFromUrdf(xml, base_link, error);
  if (!r) *error = key + ": " + *error;
  return r;
}

}  // namespace spott_ros
