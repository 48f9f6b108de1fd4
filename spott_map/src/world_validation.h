// Semantic and geometric checks of a parsed world (internal to the loader).
#pragma once

#include <vector>

#include "spott_map/source_location.h"
#include "spott_map/world.h"

namespace spott_map {

/// Checks ids, references and geometry; fills in door openings, normalizes room outlines to
/// counter-clockwise and, when `walls_from_rooms`, adds the walls generated from the room
/// outlines. Appends to `errors` and `warnings`.
void ValidateWorld(World& world, const SourceLocation& robot_start_where, bool walls_from_rooms,
                   double wall_thickness, std::vector<SourceError>& errors,
                   std::vector<SourceError>& warnings);

}  // namespace spott_map
