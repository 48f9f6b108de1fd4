// A small building whose path costs and projections are computed by hand in the tests:
//
//   y=6 +-----------------------------------------------+
//       |                 H (hallway)                   |
//   y=4 +---dAH----------+---dBH----------+---dCH-------+
//       |        A       |        B       |        C    |
//       |       dAB (4,2)|       dBC (8,2)|             |
//   y=0 +----------------+----------------+-------------+
//       x=0              x=4              x=8           x=12
//
// Centres (area centroids): A (2,2), B (6,2), C (10,2), H (6,5).
// Door centres: dAB (4,2), dBC (8,2), dAH (2,4), dBH (6,4), dCH (10,4); openings 1 m wide.
// Edge costs (centre -> door centre -> centre, m):
//   A-dAB-B = 2 + 2 = 4        B-dBC-C = 4
//   A-dAH-H = 2 + |(2,4)-(6,5)| = 2 + sqrt(17)
//   B-dBH-H = 2 + 1 = 3
//   C-dCH-H = 2 + sqrt(17)
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "spott_map/room_door_graph.h"

namespace spott_global_planner::test {

inline spott_map::Room MakeRoom(const std::string& id, double x0, double y0, double x1, double y1,
                                spott_map::RoomKind kind = spott_map::RoomKind::kRoom) {
  spott_map::Room r;
  r.id = id;
  r.name = id;
  r.kind = kind;
  r.polygon = {spott_map::Vec2(x0, y0), spott_map::Vec2(x1, y0), spott_map::Vec2(x1, y1),
               spott_map::Vec2(x0, y1)};
  return r;
}

/// A door of width 1 m centred on `centre`, its opening along x (`horizontal`) or along y.
inline spott_map::Door MakeDoor(const std::string& id, const std::string& a, const std::string& b,
                                const spott_map::Vec2& centre, bool horizontal) {
  spott_map::Door d;
  d.id = id;
  d.room_a = a;
  d.room_b = b;
  d.width = 1.0;
  d.center = centre;
  const spott_map::Vec2 half = horizontal ? spott_map::Vec2(0.5, 0.0) : spott_map::Vec2(0.0, 0.5);
  d.opening = spott_map::Segment{centre - half, centre + half};
  return d;
}

inline spott_map::RoomDoorGraph MakeTestBuilding() {
  using spott_map::Vec2;
  std::vector<spott_map::Room> rooms = {MakeRoom("A", 0, 0, 4, 4), MakeRoom("B", 4, 0, 8, 4),
                                        MakeRoom("C", 8, 0, 12, 4),
                                        MakeRoom("H", 0, 4, 12, 6, spott_map::RoomKind::kHallway)};
  std::vector<spott_map::Door> doors = {
      MakeDoor("dAB", "A", "B", Vec2(4, 2), false), MakeDoor("dBC", "B", "C", Vec2(8, 2), false),
      MakeDoor("dAH", "A", "H", Vec2(2, 4), true), MakeDoor("dBH", "B", "H", Vec2(6, 4), true),
      MakeDoor("dCH", "C", "H", Vec2(10, 4), true)};
  return spott_map::RoomDoorGraph(std::move(rooms), std::move(doors));
}

inline const double kSqrt17 = std::sqrt(17.0);

}  // namespace spott_global_planner::test
