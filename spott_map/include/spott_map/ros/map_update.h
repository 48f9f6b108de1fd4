// Applying a spott_msgs/MapUpdate to a map database copy.
#pragma once

#include <string>
#include <vector>

#include <spott_msgs/MapUpdate.h>

#include "spott_map/map_database.h"

namespace spott_map::ros_conversions {

/// Applies every part of `update` that is valid: added features go through
/// AddSensedFeature (so nothing already there is added twice), relabelled ones are relabelled,
/// removed ones removed, door states set. Returns a sentence per part that was refused
/// (malformed feature, unknown id or door, invalid state); the rest is still applied.
std::vector<std::string> ApplyMapUpdate(const spott_msgs::MapUpdate& update,
                                        double feature_tolerance_m, MapDatabase& db);

}  // namespace spott_map::ros_conversions
