// Maps shared by the tests: hand-made rasters and random office-like windows.
#pragma once

#include <random>
#include <string>

#include "spott_map/map_feature.h"
#include "spott_map/occupancy_raster.h"

namespace spott_harmonic_planner::testing_maps {

inline spott_map::OccupancyRaster EmptyRaster(int w, int h, double res = 1.0) {
  return spott_map::OccupancyRaster(spott_map::Vec2(0.0, 0.0), w, h, res);
}

/// An axis-parallel wall or box feature over [x0, x1] x [y0, y1] (m).
inline spott_map::MapFeature BoxFeature(const std::string& id, double x0, double y0, double x1,
                                        double y1, spott_map::FeatureSource source) {
  spott_map::MapFeature box;
  box.id = id;
  box.label = "wall";
  box.type = spott_map::FeatureType::kRectangle;
  box.source = source;
  box.pose = spott_map::Pose2{0.5 * (x0 + x1), 0.5 * (y0 + y1), 0.0};
  box.size_x = x1 - x0;
  box.size_y = y1 - y0;
  return box;
}

inline void Block(spott_map::OccupancyRaster& r, int x0, int y0, int x1, int y1) {
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      if (r.Contains(x, y)) r.Mark(x, y, spott_map::Cell::kObstacle);
    }
  }
}

/// A random office-like window: `walls` axis-parallel wall pieces 1 cell thick with a door gap,
/// and `boxes` rectangular furniture blocks, each padded by `pad` cells. The seed owns the map.
inline spott_map::OccupancyRaster RandomOffice(int n, int boxes, int walls, int pad,
                                               std::uint32_t seed) {
  std::mt19937 rng(seed);
  auto r = EmptyRaster(n, n);
  std::uniform_int_distribution<int> pos(2, n - 3);
  std::uniform_int_distribution<int> size(1, std::max(2, n / 8));
  for (int b = 0; b < boxes; ++b) {
    const int x = pos(rng), y = pos(rng), sx = size(rng), sy = size(rng);
    Block(r, x - pad, y - pad, x + sx + pad, y + sy + pad);
  }
  for (int k = 0; k < walls; ++k) {
    const int at = pos(rng);
    const int door = pos(rng);
    const int half = std::max(2, n / 12) + pad;
    for (int t = 1; t < n - 1; ++t) {
      if (std::abs(t - door) <= half) continue;
      if (k % 2 == 0) {
        Block(r, at - pad, t, at + pad, t);
      } else {
        Block(r, t, at - pad, t, at + pad);
      }
    }
  }
  return r;
}

}  // namespace spott_harmonic_planner::testing_maps
