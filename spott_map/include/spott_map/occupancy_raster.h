// A square-celled occupancy grid cut from the vector map (the raster half of SPOTT's local
// map, III.A). Cell (ix, iy) covers [origin.x + ix*res, origin.x + (ix+1)*res) x the same in y:
// row-major, row 0 at the bottom (smallest y), as nav_msgs/OccupancyGrid.
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "spott_map/geometry.h"
#include "spott_map/map_feature.h"

namespace spott_map {

enum class Cell : std::uint8_t {
  kFree = 0,
  kPadding = 1,   ///< Within the padding (robot radius + localization error) of an obstacle.
  kObstacle = 2,  ///< The obstacle's geometry meets the cell's square.
};

class OccupancyRaster {
 public:
  OccupancyRaster() = default;
  /// `origin`: lower-left corner (m); `resolution`: cell side (m).
  OccupancyRaster(const Vec2& origin, int width, int height, double resolution);

  int width() const { return width_; }
  int height() const { return height_; }
  double resolution() const { return resolution_; }
  const Vec2& origin() const { return origin_; }
  Box Bounds() const;

  bool Contains(int ix, int iy) const { return ix >= 0 && iy >= 0 && ix < width_ && iy < height_; }
  Cell at(int ix, int iy) const { return cells_[Index(ix, iy)]; }
  /// Raises a cell to `value` (obstacle beats padding beats free); never lowers it.
  void Mark(int ix, int iy, Cell value);
  void Clear();
  bool Blocked(int ix, int iy) const { return at(ix, iy) != Cell::kFree; }

  /// Centre of a cell (m).
  Vec2 CellCentre(int ix, int iy) const;
  /// The cell holding `p`, if it is inside the raster.
  std::optional<std::pair<int, int>> CellOf(const Vec2& p) const;

  const std::vector<Cell>& cells() const { return cells_; }
  std::size_t CountCells(Cell value) const;

 private:
  std::size_t Index(int ix, int iy) const {
    return static_cast<std::size_t>(iy) * static_cast<std::size_t>(width_) +
           static_cast<std::size_t>(ix);
  }

  Vec2 origin_{0.0, 0.0};
  int width_ = 0;
  int height_ = 0;
  double resolution_ = 1.0;
  std::vector<Cell> cells_;
};

/// Draws one obstacle: kObstacle where its geometry (segments thickened by their thickness,
/// area features by their outline) meets a cell's square, kPadding where any point of a cell's
/// square lies within `padding_m` of it (a robot centred anywhere in a free cell keeps the
/// padding). Points are obstacles in the cell that holds them.
void RasterizeFeature(const MapFeature& feature, double padding_m, OccupancyRaster& raster);

/// Distance from an axis-aligned box to a segment (0 when they meet).
double DistanceBoxSegment(const Box& box, const Segment& segment);

}  // namespace spott_map
