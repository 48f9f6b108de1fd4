// Walls generated from room outlines: what an architect's drawing shows once the rooms are
// drawn, without listing every wall by hand.
#pragma once

#include <vector>

#include "spott_map/world.h"

namespace spott_map {

/// One wall per maximal straight run of room boundary: collinear edges of neighbouring rooms
/// merge into one wall, and every door's opening is cut out (a door leaf is not a wall). Ids are
/// "wall_<n>" in a deterministic order. `tolerance` (m) decides when edges are collinear.
std::vector<Wall> GenerateWallsFromRooms(const std::vector<Room>& rooms,
                                         const std::vector<Door>& doors, double thickness,
                                         double tolerance);

}  // namespace spott_map
