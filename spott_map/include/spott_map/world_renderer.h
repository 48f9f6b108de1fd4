// Drawing a world to a PNG with Cairo: rooms and hallways, walls, doors (open, closed,
// unknown, openings), objects, named places, the robot's start, labels, a legend and a scale.
#pragma once

#include <optional>
#include <string>

#include "spott_map/world.h"

namespace spott_map {

struct RenderOptions {
  double pixels_per_metre = 40.0;  ///< > 0
  double margin_m = 1.5;           ///< Blank border around the world (m), >= 0.
  bool labels = true;              ///< Room names, object ids and place names.
  bool legend = true;
};

/// Writes the picture; returns an error message on failure.
std::optional<std::string> RenderWorldToPng(const World& world, const std::string& png_path,
                                            const RenderOptions& options = RenderOptions());

}  // namespace spott_map
