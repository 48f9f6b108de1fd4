// The TR+ controller's sensor messages into its core's types, with issue 21's edge checks: what
// a message may carry (any size, NaN, infinities) either becomes something the mapper and the
// reflexes can use or is refused with the field and why.
#pragma once

#include <geometry_msgs/Transform.h>
#include <spott_msgs/BumperRing.h>
#include <spott_msgs/RangeProfile.h>
#include <spott_msgs/RangeRing.h>
#include <spott_msgs/WorldPlaces.h>

#include <optional>
#include <string>
#include <vector>

#include "spott_map/world.h"
#include "spott_tr_plus/controller/object_recognition.h"
#include "spott_tr_plus/controller/sensor_mapper.h"

namespace spott_tr_plus {
namespace ros_conversions {

using controller::RangeRing;
using controller::Vec2;

/// A ring the mapper can use: nullopt with `*problem` ("field: why", spott_ros::RangeRingProblem)
/// when it cannot be used at all; impossible readings (below 0, beyond max_range) dropped out as
/// NaN, the first one's index in `*discarded` (-1 when none).
std::optional<RangeRing> RingFromMsg(const spott_msgs::RangeRing& msg, std::string* problem,
                                     int* discarded);

/// The angles (base frame, rad) of the pressed segments with a finite angle; a segment without
/// an angle is left out.
std::vector<double> PressedAngles(const spott_msgs::BumperRing& msg);

/// A horizontal profile's points that hit something between `min_height_m` and `max_height_m`
/// above the base, in the base frame (x, y), with `head` the head's pose in the base frame; the
/// head's origin in `*origin`. Points at max range or without a range (no echo), not finite or
/// out of that height band are left out. nullopt when the head's pose is not finite (or a zero
/// quaternion). ProfileSamples' echoes, in 2-D.
std::optional<std::vector<Vec2>> ProfilePoints(const spott_msgs::RangeProfile& msg,
                                               const geometry_msgs::Transform& head,
                                               double min_height_m, double max_height_m,
                                               Vec2* origin);

/// Every sample of a profile (horizontal or vertical), in the base frame (3-D) and in the
/// message's order, for recognition; the head's origin in `*origin`. A sample without a finite
/// point is kept as "no echo" at NaN (the order along the profile matters); a sample is an echo
/// when its range is below max_range. nullopt when the head's pose is not finite.
std::optional<std::vector<controller::ProfileSample>> ProfileSamples(
    const spott_msgs::RangeProfile& msg, const geometry_msgs::Transform& head,
    controller::Vec3* origin);

/// The places of world_server's message (check them first: PlacesProblem).
std::vector<spott_map::Place> PlacesFromMsg(const spott_msgs::WorldPlaces& msg);

}  // namespace ros_conversions
}  // namespace spott_tr_plus
