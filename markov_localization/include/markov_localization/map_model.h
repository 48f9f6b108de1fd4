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

#include "markov_localization/occupancy_map.h"
#include "spott_map/geometry.h"
#include "spott_map/map_database.h"
#include "spott_map/world.h"

namespace markov_localization {

using spott_map::Vec2;

struct MapModelParameters {
  double resolution_m = 0.15;      ///< Cell side (m), in [0.01, 2]; the paper's 10-15 cm.
  double state_clearance_m = 0.1;  ///< The robot's centre keeps this distance to obstacles
                                   ///< (m), in [0, 2]: cells closer are not states.
  double door_thickness_m = 0.05;  ///< Thickness of a closed door leaf (m), in (0, 1].
  /// Beams are cast on a raster this many times finer than the belief's cells, so that a
  /// 0.9 m door does not shrink to 0.6 m at 15 cm (integer in [1, 8]).
  /// With the sonar physics (cone, specular echoes) an odd value keeps twins' tables half-turn
  /// symmetric at 20 and 25 cm (cell centres on fine-cell centres; the node uses 5); a single
  /// diffuse ray is symmetric with 4 at 15 cm and not with 5 at 20 / 25 cm (see the README).
  int ray_cast_subdivision = 4;
  /// Occupancy grids (OccupancyMap, nav_msgs/OccupancyGrid): cells of at least this occupancy
  /// (%) are obstacles, cells below free_threshold are free, the rest and -1 are unknown
  /// (map_server writes 100, 0 and -1). In [1, 100] and [0, occupied_threshold].
  int occupied_threshold = 65;
  int free_threshold = 20;
};

/// Every violation by parameter name; empty when valid.
std::vector<std::string> ValidateParameters(const MapModelParameters& params);

class MapModel {
 public:
  MapModel() = default;

  /// The CAD map of a world: walls and closed doors (objects are not in the CAD map).
  /// Throws std::invalid_argument naming the parameter or the problem.
  static MapModel FromWorld(const spott_map::World& world, const MapModelParameters& params);

  /// An occupancy grid (a /map message, a map_server file) rasterized at the belief's
  /// resolution params.resolution_m, whatever the grid's own: the belief's cells start at the
  /// grid's origin corner (and follow its rotation origin_yaw), beams are cast on a raster
  /// ray_cast_subdivision times finer, where a fine cell is an obstacle when any obstacle cell
  /// of the grid overlaps its square (walls thinner than a fine cell are never lost). A cell is
  /// a state when its centre lies in a free cell of the grid and keeps state_clearance_m from
  /// every fine obstacle; unknown cells are no states and do not reflect beams. Throws
  /// std::invalid_argument naming the problem.
  static MapModel FromOccupancy(const OccupancyMap& grid, const MapModelParameters& params);

  /// The same at the grid's own resolution without subdivision; cells below
  /// `occupied_threshold` are free (no intermediate unknown values).
  static MapModel FromOccupancy(const Vec2& origin, int width, int height, double resolution_m,
                                const std::vector<std::int8_t>& data, int occupied_threshold,
                                double state_clearance_m);

  /// The map of a map database (a world whose doors changed or that sensed new features): walls,
  /// closed doors and the database's sensed features; the grid's geometry is that of
  /// FromWorld(world, params) (rooms and extent from `world`), so a belief carries over cell
  /// by cell. Throws std::invalid_argument.
  static MapModel FromDatabase(const spott_map::World& world, const spott_map::MapDatabase& db,
                               const MapModelParameters& params);

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

  /// Whether the fine raster (the beams') has an obstacle in the fine cell holding `p`.
  bool FineOccupiedAt(const Vec2& p) const;
  int subdivision() const { return subdivision_; }
  /// Whether obstacle surfaces lie inside the first fine cell a beam meets (rasterized
  /// geometry; see Hit::depth_m) rather than on its face (a grid whose cells are the fine
  /// cells).
  bool surface_inside_cells() const { return surface_inside_cells_; }

  /// Distance (m) from `from` along heading `angle_rad` to the first obstacle cell's face, or
  /// `max_range_m` when none is nearer (cells outside the grid end the beam at max range).
  double RayCast(const Vec2& from, double angle_rad, double max_range_m) const;

  /// A beam's first obstacle: distance (m) to the face of the raster cell it entered (the
  /// surface normal is along x for an x face, along y otherwise); hit false at max range.
  /// `depth_m` is half the beam's path through that cell: an obstacle marks every fine cell
  /// its geometry meets, so the surface lies somewhere inside the first cell, on average half
  /// way (without it every expected range is short by up to a fine cell, 1.5 cm on average at
  /// 3 cm, which biased the pose refinement's laser ranges; the tables' 10 cm bins ignore it).
  struct Hit {
    double range_m = 0.0;
    double depth_m = 0.0;
    bool hit = false;
    bool x_face = false;
  };
  Hit RayCastHit(const Vec2& from, double angle_rad, double max_range_m) const;
  /// The same along the unit vector `dir` (a caller that has the direction's cosine and sine
  /// already, or a reflected beam, needs no trigonometry).
  Hit RayCastHit(const Vec2& from, const Vec2& dir, double max_range_m) const;

  /// Both maps have the same cells and the same beam raster (a map database's maps of one world).
  bool SameRaster(const MapModel& other) const;
  /// The box (map frame) of the fine cells whose occupancy differs from `other`'s: a door
  /// opened or closed, a feature added. Nullopt when none does. Requires SameRaster(other).
  std::optional<spott_map::Box> OccupancyChangedFrom(const MapModel& other) const;

 private:
  void ComputeStates(double clearance_m, const std::vector<std::uint8_t>& unknown);
  void ComputeFineClearance();
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
  bool surface_inside_cells_ = false;
  int fine_width_ = 0;
  int fine_height_ = 0;
  std::vector<std::uint8_t> fine_occupied_;
  // Per fine cell, the Chebyshev distance (fine cells, up to 255) to the nearest obstacle cell
  // or the raster's edge; 0 on obstacles. A beam in a cell of clearance c crosses only free
  // cells while it stays within c - 1 cells of it: the cast skips their lookups (issue 14:
  // the pose refinement's casts were most of a sonar update's CPU).
  std::vector<std::uint8_t> fine_clearance_;
};

}  // namespace markov_localization
