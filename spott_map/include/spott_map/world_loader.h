// Loading and validating world files (YAML). The format is documented in spott_map/README.md.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "spott_map/source_location.h"
#include "spott_map/world.h"

namespace spott_map {

struct WorldLoadResult {
  std::optional<World> world;       ///< Set only when there are no errors.
  std::vector<SourceError> errors;  ///< Each names the file, line and column.
  std::vector<SourceError> warnings;
  bool ok() const { return world.has_value(); }
};

/// Reads and validates a world file.
WorldLoadResult LoadWorldFile(const std::string& path);

/// Parses and validates world text; `source_name` names it in errors.
WorldLoadResult LoadWorldFromString(const std::string& text, const std::string& source_name);

/// Geometric tolerance of the loader (m): how far a door centre may lie from a room's boundary,
/// how close collinear room edges must be to merge into one wall.
constexpr double kWorldTolerance = 0.02;

/// Every coordinate and size in a world file must lie within this distance of the origin (m):
/// a 1 km square holds any indoor floor, and keeps world_server's raster map bounded.
constexpr double kWorldMaxCoordinate = 500.0;

}  // namespace spott_map
