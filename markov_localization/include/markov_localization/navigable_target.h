// A target point a* of active localization is any state of the belief (state_clearance_m from
// the walls, 10 cm by default), while a navigation planner pads obstacles by the robot's radius
// plus a localization error and refuses goals inside that padding (e.g. a* on the side of a
// doorway). This moves a* to the nearest point that keeps `clearance_m` from every obstacle of
// the map, within `search_radius_m`; the point stays as informative (same room, same doorway).
//
// ROS-free.
#pragma once

#include <optional>

#include "markov_localization/map_model.h"

namespace markov_localization {

/// Distance (m) from `p` to the nearest obstacle of `map`, up to `max_m` (by ray casting in
/// 32 directions on the map's fine raster).
double Clearance(const MapModel& map, const Vec2& p, double max_m);

/// The point nearest to `target` (on a grid of `step_m`) whose clearance is at least
/// `clearance_m`, within `search_radius_m`; nullopt when there is none.
std::optional<Vec2> NavigableTarget(const MapModel& map, const Vec2& target, double clearance_m,
                                    double search_radius_m, double step_m = 0.05);

}  // namespace markov_localization
