// The local map of SPOTT section III.A: a fixed-size window into the global map, kept both as
// vectors (the features that meet it) and as a raster occupancy grid in whose free space the
// local planner computes its potential. Obstacles are padded by the robot's radius plus the
// largest allowed localization error (paper footnote 15). The window re-centres on the robot
// when it nears the border (III.D.1 step f).
#pragma once

#include <string>
#include <vector>

#include "spott_map/map_database.h"
#include "spott_map/occupancy_raster.h"

namespace spott_map {

struct LocalMapParameters {
  double window_size_m = 7.0;     ///< Side of the square window (m), > 0.
  double resolution_m = 0.2;      ///< Cell side (m), > 0; 7 m / 0.2 m = the paper's 35 x 35.
  double robot_radius_m = 0.225;  ///< (m) >= 0; Nomad 200.
  double max_localization_error_m = 0.1;  ///< (m) >= 0; footnote 15.
  double recentre_margin_m = 1.0;  ///< Re-centre when the robot is this close to the border (m), >=
                                   ///< 0 and < window_size_m / 2.
  double door_thickness_m = 0.05;  ///< A closed door leaf drawn across its opening (m), >= 0.

  double padding_m() const { return robot_radius_m + max_localization_error_m; }
  /// Cells per side: round(window_size_m / resolution_m), of valid parameters (at most 8192).
  int cells() const;
};

/// Every violated constraint, each naming its parameter, e.g.
/// "resolution_m must be > 0 (got -0.1)". Empty when valid.
std::vector<std::string> ValidateParameters(const LocalMapParameters& params);

/// Draws the database's obstacles into `raster`: every feature (whatever its label: walls,
/// sensed objects) and every closed door. Open and unknown doors are free.
void RasterizeDatabase(const MapDatabase& db, double padding_m, double door_thickness_m,
                       OccupancyRaster& raster);

class LocalMap {
 public:
  /// Throws std::invalid_argument listing every violation when `params` are invalid.
  explicit LocalMap(const LocalMapParameters& params);

  /// Cuts the window centred (to the nearest cell) on `centre` from `db`.
  void Recentre(const MapDatabase& db, const Vec2& centre);
  /// Cuts again at the same place, after the database changed.
  void Refresh(const MapDatabase& db);
  /// True when `robot` is within recentre_margin_m of the window's border (or outside it).
  bool NeedsRecentre(const Vec2& robot) const;

  const LocalMapParameters& parameters() const { return params_; }
  const OccupancyRaster& raster() const { return raster_; }
  /// The features that meet the window (the vector half of the local map).
  const std::vector<MapFeature>& features() const { return features_; }
  Box bounds() const { return raster_.Bounds(); }
  Vec2 centre() const { return centre_; }
  /// The database revision the window was cut from.
  std::uint64_t revision() const { return revision_; }

 private:
  LocalMapParameters params_;
  OccupancyRaster raster_;
  std::vector<MapFeature> features_;
  Vec2 centre_{0.0, 0.0};
  std::uint64_t revision_ = 0;
};

}  // namespace spott_map
