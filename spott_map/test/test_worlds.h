// Shared helpers of the spott_map tests.
#pragma once

#include <string>

#include "spott_map/world_loader.h"

namespace spott_map::testing {

/// The test world test/data/two_rooms.yaml (tests run with test/ as working directory).
inline World TwoRoomsWorld() {
  WorldLoadResult r = LoadWorldFile("data/two_rooms.yaml");
  if (!r.ok()) throw std::runtime_error(FormatErrors(r.errors));
  return *r.world;
}

}  // namespace spott_map::testing
