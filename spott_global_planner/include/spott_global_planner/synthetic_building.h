// Generated buildings for the benchmarks and the randomized tests: a rows x cols grid of
// square rooms; doors between neighbours form a random spanning tree (so every room is
// reachable) plus a share of extra doors that make loops, as corridors and connecting doors
// do. Deterministic for a seed.
#pragma once

#include <cstdint>

#include "spott_map/room_door_graph.h"

namespace spott_global_planner {

struct SyntheticBuildingParameters {
  int rows = 10;
  int cols = 10;
  double room_size_m = 5.0;   ///< Side of each room (m).
  double door_width_m = 0.9;  ///< (m)
  double extra_door_share =
      0.3;  ///< Of the neighbour pairs not in the tree, the share with a door.
  std::uint64_t seed = 1;
};

/// Rooms "r<row>_<col>" with room (row, col) covering [col, col+1) x [row, row+1) times the room
/// size; doors "d<n>" at the middle of the shared wall, state unknown.
spott_map::RoomDoorGraph MakeSyntheticBuilding(const SyntheticBuildingParameters& params);

}  // namespace spott_global_planner
