// Greedy exploration of the local window when the planner has no map beyond it (no global
// planner, no a priori map: SPOTT's "GO" across a building never seen). The window's border is
// where the planner's knowledge ends; unsensed space counts as free. When the sensed obstacles
// cut the robot off from the goal (or from its projection onto the border), the way on is the
// free border cell the robot can reach that lies nearest the goal: a frontier of the window,
// chosen greedily as a best-first search would. As the robot senses the dead ends (an office
// with no other door) they close, and the next choice leads elsewhere.
#pragma once

#include <optional>

#include "spott_harmonic_planner/potential_field.h"

namespace spott_harmonic_planner {

/// The centre of the border cell of `field`'s window nearest `target` among those the robot at
/// `start` reaches through unblocked inner cells (4-connected, as the field's stencil couples
/// them). nullopt when `start` is outside the window or blocked, or reaches no border cell.
std::optional<Vec2> NearestReachableBorderCell(const PotentialField& field, const Vec2& start,
                                               const Vec2& target);

}  // namespace spott_harmonic_planner
