// The map the localization works on (Beetz et al. section 2): a grid at the belief's x/y
// resolution that says which cells hold an obstacle (what range sensors see) and which cells the
// robot's centre may occupy (the states of the belief). Built from a spott_map world (CAD walls
// and closed doors) or from an occupancy grid in nav_msgs/OccupancyGrid's convention.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "spott_map/geometry.h"
#include "spott_map/world.h"

namespace markov_localization {

using spott_map::Vec2;

struct MapModelParameters {
  double resolution_m = 0.15;      ///< Cell side (m), in (0, 2]; the paper's 10-15 cm.
  double state_clearance_m = 0.1;  ///< The robot's centre keeps this distance to obstacles
                                   ///< (m), in [0, 2]: cells closer are not states.
  double door_thickness_m = 0.05;  ///< Thickness of a closed door leaf (m), in (0, 1].
  /// Beams are cast on a raster this many times finer than the belief's cells, so that a
  /// 0.9 m door does not shrink to 0.6 m at 15 cm (integer in [1, 8]).
  /// With the sonar physics (cone, specular echoes) an odd value keeps twins' tables half-turn
  /// symmetric at 20 and 25 cm (cell centres on fine-cell centres; the node uses 5); a single
  /// diffuse ray is symmetric with 4 at 15 cm and not with 5 at 20 / 25 cm (see the README).
  int ray_cast_subdivision = 4;
};

/// Every violation by parameter name; empty when valid.
std::vector<std::string> ValidateParameters(const MapModelParameters& params);

class MapModel {
 public:
  MapModel() = default;

  /// The CAD map of a world: walls and closed doors (objects are not in the CAD map).
  /// Throws std::invalid_argument naming the parameter or the problem.
  static MapModel FromWorld(const spott_map::World& world, const MapModelParameters& params);

  /// An occupancy grid, row-major with row 0 at the bottom (nav_msgs/OccupancyGrid): values
  /// 0..100 are occupancy percentages, -1 unknown. Cells >= `occupied_threshold` are obstacles;
  /// unknown cells are not states and do not reflect beams. Throws std::invalid_argument.
  static MapModel FromOccupancy(const Vec2& origin, int width, int height, double resolution_m,
                                const std::vector<std::int8_t>& data, int occupied_threshold,
                                double state_clearance_m);

  int width() const { return width_; }
  int height() const { return height_; }
  double resolution() const { return resolution_; }
  const Vec2& origin() const { return origin_; }
  std::size_t NumCells() const { return occupied_.size(); }
  std::size_t Index(int ix, int iy) const {
    return static_cast<std::size_t>(iy) * static_cast<std::size_t>(width_) +
           static_cast<std::size_t>(ix);
  }
  bool Contains(int ix, int iy) const { return ix >= 0 && iy >= 0 && ix < width_ && iy < height_; }
  /// An obstacle cell (some obstacle meets the cell's square).
  bool Occupied(int ix, int iy) const { return occupied_[Index(ix, iy)] != 0; }
  /// A cell the robot's centre may be in: a state of the belief.
  bool IsState(int ix, int iy) const { return state_[Index(ix, iy)] != 0; }
  bool IsStateAt(const Vec2& p) const;
  const std::vector<std::uint8_t>& state_mask() const { return state_; }
  std::size_t NumStateCells() const { return num_state_cells_; }

  Vec2 CellCentre(int ix, int iy) const;
  std::optional<std::pair<int, int>> CellOf(const Vec2& p) const;

  /// Distance (m) from `from` along heading `angle_rad` to the first obstacle cell, or
  /// `max_range_m` when none is nearer (cells outside the grid end the beam at max range).
  double RayCast(const Vec2& from, double angle_rad, double max_range_m) const;

  /// A beam's first obstacle: distance (m) and the face of the raster cell it entered (the
  /// surface normal is along x for an x face, along y otherwise); hit false at max range.
  struct Hit {
    double range_m = 0.0;
    bool hit = false;
    bool x_face = false;
  };
  Hit RayCastHit(const Vec2& from, double angle_rad, double max_range_m) const;

 private:
  void ComputeStates(double clearance_m, const std::vector<std::uint8_t>& unknown);
  bool FineOccupied(int fx, int fy) const {
    return fine_occupied_[static_cast<std::size_t>(fy) * fine_width_ + fx] != 0;
  }

  Vec2 origin_{0.0, 0.0};
  int width_ = 0;
  int height_ = 0;
  double resolution_ = 1.0;
  std::vector<std::uint8_t> occupied_;
  std::vector<std::uint8_t> state_;
  std::size_t num_state_cells_ = 0;
  // The raster beams are cast on: `subdivision_` x finer than the cells above.
  int subdivision_ = 1;
  int fine_width_ = 0;
  int fine_height_ = 0;
  std::vector<std::uint8_t> fine_occupied_;
};

}  // namespace markov_localization
