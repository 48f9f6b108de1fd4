// A small world for the core tests, with hand-computable geometry: room `west` is 10 x 6 m,
// room `east` 4 x 6 m east of it; walls 0.1 m thick centred on the room outlines (so the inside
// faces are at x = 0.05, x = 9.95 and x = 10.05, y = 0.05, y = 5.95, ...); a door between the
// rooms centred at (10, 3), 1 m wide, closed; a 0.5 m crate centred at (7, 1), 0.5 m tall.
#pragma once

#include <string>

#include "robot_sim/sim_world.h"
#include "spott_map/world_loader.h"

namespace robot_sim::testing {

inline const char* kTestWorldYaml = R"(
world: {name: test_rooms}
walls: {from_rooms: true, thickness: 0.1}
rooms:
  - {id: west, polygon: [[0, 0], [10, 0], [10, 6], [0, 6]]}
  - {id: east, polygon: [[10, 0], [14, 0], [14, 6], [10, 6]]}
doors:
  - {id: d1, between: [west, east], center: [10, 3], width: 1.0, state: closed}
objects:
  - {id: crate, kind: cuboid, pose: [7, 1, 0], size: [0.5, 0.5], height: 0.5}
robot_start: {pose: [2, 3, 0]}
)";

inline spott_map::World TestWorld() {
  auto result = spott_map::LoadWorldFromString(kTestWorldYaml, "test_rooms.yaml");
  if (!result.ok()) throw std::runtime_error(spott_map::FormatErrors(result.errors));
  return *result.world;
}

inline std::string PackageFile(const std::string& relative) {
  return std::string(PACKAGE_DIR) + "/" + relative;
}

/// A box solid centred at (x, y) turned by yaw, size_x by size_y, `height` tall.
inline Solid Box(const std::string& id, double x, double y, double yaw, double size_x,
                 double size_y, double height) {
  Solid box;
  box.id = id;
  box.pose = {x, y, yaw};
  box.size_x = size_x;
  box.size_y = size_y;
  box.height = height;
  return box;
}

}  // namespace robot_sim::testing
