// The free space of a map database as the planners see it (internal to spott_tr_plus): a
// raster over the building whose cells are free when no obstacle (a feature of the database,
// a closed door) lies within the padding of their centre (robot radius + localization error,
// SPOTT III-D footnote 15) and their centre is in a room; and which of them the robot can
// reach. Task interpretation chooses goal points in it (task_interpretation.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include "spott_map/map_database.h"
#include "spott_map/occupancy_raster.h"

namespace spott_tr_plus {
namespace internal {

class FreeSpace {
 public:
  /// Rasterizes `db` at `resolution_m` (coarsened when the building would need more than
  /// `max_cells` cells). `db` must outlive the object.
  FreeSpace(const spott_map::MapDatabase& db, double padding_m, double resolution_m,
            std::size_t max_cells = 8'000'000);

  /// Marks the cells reachable from `robot` (4-connected through free cells), starting from
  /// the free cell nearest to it within `seed_radius_m` (the robot itself may stand inside the
  /// padding of a wall). False when there is none.
  bool FloodFrom(const spott_map::Vec2& robot, double seed_radius_m);

  int num_cells() const { return static_cast<int>(room_.size()); }
  spott_map::Vec2 Centre(int cell) const;
  /// The cell holding p, or -1 outside the raster.
  int CellOf(const spott_map::Vec2& p) const;
  /// Index into db.graph().rooms() of the room holding the cell's centre, or -1.
  int RoomOf(int cell) const { return room_[cell]; }
  bool Free(int cell) const { return free_[cell] != 0; }
  bool Reachable(int cell) const { return reached_[cell] != 0; }
  double cell_area_m2() const { return raster_.resolution() * raster_.resolution(); }
  double padding_m() const { return padding_m_; }
  /// No obstacle lies within the padding of the exact point p.
  bool Clear(const spott_map::Vec2& p) const;
  /// The room the robot's flood started in (index into db.graph().rooms()), or -1.
  int robot_room() const { return robot_room_; }

 private:
  const spott_map::MapDatabase& db_;
  double padding_m_;
  spott_map::OccupancyRaster raster_;
  std::vector<int> room_;
  std::vector<std::uint8_t> free_, reached_;
  int robot_room_ = -1;
};

}  // namespace internal
}  // namespace spott_tr_plus
