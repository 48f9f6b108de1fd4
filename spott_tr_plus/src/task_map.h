// Task interpretation against the map database (internal to spott_tr_plus): which rooms a goal
// belongs to, and choosing its point in their free, reachable space.
#pragma once

#include <string>
#include <vector>

#include "free_space.h"
#include "spott_map/map_database.h"
#include "spott_tr_plus/task_command.h"

namespace spott_tr_plus {
namespace internal {

/// The room(s) a goal about target `t` (footprint `g`) under `preposition` belongs to, as
/// indices into db.graph().rooms(): the rooms of a door; a room or hallway itself when the goal
/// is inside it; the rooms on either side of a wall or line; the room holding any other target
/// (or those within `near_m` of it); every room for `far`, for the region outside a room, and
/// when the target is in none.
std::vector<int> RightRooms(const Target& t, const TargetGeometry& g,
                            const std::string& preposition, const spott_map::MapDatabase& db,
                            double near_m);

/// Chooses r's point in the part of r that is free, reachable and in `rooms`: the point the
/// geometry preferred when it is there (and clear of obstacles by the padding), else the
/// nearest such cell centre. Sets r.rooms and r.free_area_m2. False with the reason in `why`
/// (`what` names the region: "the goal region behind desk") when there is no such point.
bool FitGoalToFreeSpace(GoalRegion& r, const std::vector<int>& rooms, const FreeSpace& space,
                        const spott_map::MapDatabase& db, const std::string& what,
                        std::string* why);

}  // namespace internal
}  // namespace spott_tr_plus
