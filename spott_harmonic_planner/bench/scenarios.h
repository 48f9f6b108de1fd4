// The benchmark grids (shared by the benchmark programs and the figure): square windows of
// n x n cells, resolution 1 unless given, a robot cell and a goal cell.
//   open      no obstacle; robot and goal on the middle row, n/8 from the sides (the straight
//             line between them crosses the window)
//   rect      the paper's 35 x 35 case scaled to n: three padded rectangles across that line
//   corridor  a straight corridor `width` cells wide and `length` long carved out of solid
//             obstacle, centred in the window; goal at its left end, robot at its right end
//   office    a random office-like window (walls with doors, furniture), robot and goal free
#pragma once

#include <algorithm>
#include <cstdint>
#include <tuple>
#include <utility>
#include <vector>

#include "../test/test_maps.h"
#include "spott_map/occupancy_raster.h"

namespace spott_harmonic_planner::bench {

struct Scenario {
  spott_map::OccupancyRaster raster;
  int robot_x = 0, robot_y = 0;
  int goal_x = 0, goal_y = 0;
  double Res() const { return raster.resolution(); }
  spott_map::Vec2 Centre(int x, int y) const { return raster.CellCentre(x, y); }
  spott_map::Vec2 Robot() const { return Centre(robot_x, robot_y); }
  spott_map::Vec2 Goal() const { return Centre(goal_x, goal_y); }
};

inline Scenario Open(int n, double res = 1.0) {
  Scenario s{testing_maps::EmptyRaster(n, n, res)};
  s.robot_x = std::max(1, n / 8);
  s.goal_x = std::min(n - 2, n - 1 - n / 8);
  s.robot_y = s.goal_y = n / 2;
  return s;
}

inline Scenario Rect(int n) {
  Scenario s = Open(n);
  const double k = n / 35.0;
  const auto block = [&](double x0, double y0, double x1, double y1) {
    testing_maps::Block(s.raster, static_cast<int>(x0 * k), static_cast<int>(y0 * k),
                        static_cast<int>(x1 * k + k - 1), static_cast<int>(y1 * k + k - 1));
  };
  block(8, 11, 12, 22);  // the paper's three padded obstacles between robot and goal
  block(17, 2, 21, 14);
  block(18, 21, 23, 30);
  s.robot_x = std::max(1, static_cast<int>(3 * k));
  s.goal_x = std::min(n - 2, static_cast<int>(30 * k));
  s.robot_y = s.goal_y = static_cast<int>(17 * k);
  return s;
}

inline Scenario Corridor(int n, int length, int width = 5) {
  Scenario s{testing_maps::EmptyRaster(n, n)};
  const int x0 = (n - length) / 2, y0 = n / 2 - width / 2;
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const bool in = x >= x0 && x < x0 + length && y >= y0 && y < y0 + width;
      if (!in) s.raster.Mark(x, y, spott_map::Cell::kObstacle);
    }
  }
  s.goal_x = x0;
  s.robot_x = x0 + length - 1;
  s.goal_y = s.robot_y = y0 + width / 2;
  return s;
}

// Free cell nearest to (x, y), searching outward.
inline std::pair<int, int> FreeNear(const spott_map::OccupancyRaster& r, int x, int y) {
  for (int rad = 0; rad < r.width(); ++rad) {
    for (int dy = -rad; dy <= rad; ++dy) {
      for (int dx = -rad; dx <= rad; ++dx) {
        const int px = x + dx, py = y + dy;
        if (px > 0 && py > 0 && px < r.width() - 1 && py < r.height() - 1 && !r.Blocked(px, py)) {
          return {px, py};
        }
      }
    }
  }
  return {x, y};
}

inline Scenario Office(int n, int pad, std::uint32_t seed, double res = 1.0) {
  Scenario s{testing_maps::RandomOffice(n, std::max(3, n / 14), 2, pad, seed)};
  if (res != 1.0) {
    spott_map::OccupancyRaster r(s.raster.origin(), n, n, res);
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        if (s.raster.Blocked(x, y)) r.Mark(x, y, spott_map::Cell::kObstacle);
      }
    }
    s.raster = r;
  }
  std::tie(s.robot_x, s.robot_y) = FreeNear(s.raster, n / 8, n / 2);
  std::tie(s.goal_x, s.goal_y) = FreeNear(s.raster, n - 1 - n / 8, n / 2);
  return s;
}

/// The grid as navfn sees it: blocked cells (raster obstacles and the border ring) are lethal.
inline std::vector<std::uint8_t> Lethal(const spott_map::OccupancyRaster& r) {
  std::vector<std::uint8_t> b(static_cast<std::size_t>(r.width()) * r.height());
  for (int y = 0; y < r.height(); ++y) {
    for (int x = 0; x < r.width(); ++x) {
      const bool border = x == 0 || y == 0 || x == r.width() - 1 || y == r.height() - 1;
      b[static_cast<std::size_t>(y) * r.width() + x] = border || r.Blocked(x, y);
    }
  }
  return b;
}

}  // namespace spott_harmonic_planner::bench
