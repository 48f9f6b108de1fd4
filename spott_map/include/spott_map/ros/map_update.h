// Applying a spott_msgs/MapUpdate to a map database copy.
#pragma once

#include <string>
#include <vector>

#include <spott_msgs/MapUpdate.h>

#include "spott_map/map_database.h"

namespace spott_map::ros_conversions {

/// Applies every part of `update` that is valid, removals first (a refinement removes a feature
/// and adds its successor in one update): removed ones removed, added features go through
/// AddSensedFeature, those with an id (the owner's) matched against the CAD features only (the
/// owner de-duplicated them; a copy that dropped one as another sensed feature's duplicate
/// would lose it when the owner removes that other), those without an id against every
/// feature; relabelled ones are relabelled, door states set. Returns a
/// sentence per part that was refused (malformed feature, unknown id or door, invalid state);
/// the rest is still applied.
std::vector<std::string> ApplyMapUpdate(const spott_msgs::MapUpdate& update,
                                        double feature_tolerance_m, MapDatabase& db);

}  // namespace spott_map::ros_conversions
