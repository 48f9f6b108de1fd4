// Steepest-descent paths never cut an obstacle's corner: every step's segment stays clear of
// blocked cells (DescendPath used to check only the cell a step ends in).
#include <gtest/gtest.h>

#include <cmath>

#include "spott_harmonic_planner/potential_field.h"
#include "test_maps.h"

namespace spott_harmonic_planner {
namespace {

// Whether the segment a-b meets a blocked cell's square, by sampling it every 1/200 cell (an
// independent check of the traversal in DescendPath).
bool SegmentHitsObstacle(const PotentialField& f, const Vec2& a, const Vec2& b) {
  const int samples = 1 + static_cast<int>(200.0 * (b - a).norm() / f.resolution());
  for (int k = 0; k <= samples; ++k) {
    const Vec2 p = a + (b - a) * (static_cast<double>(k) / samples);
    const auto c = f.CellOf(p);
    if (!c || f.cell(c->first, c->second) == FieldCell::kObstacle) return true;
  }
  return false;
}

TEST(DescendPath, NoStepCutsAnObstacleCorner) {
  auto raster = testing_maps::EmptyRaster(40, 40);
  testing_maps::Block(raster, 12, 14, 17, 19);  // a 6 x 6 block between start and goal
  testing_maps::Block(raster, 24, 8, 25, 30);   // a wall with two corners to go around
  PotentialField field(FieldOptions{});
  field.SetOccupancy(raster);
  ASSERT_TRUE(field.SetGoalPoint(Vec2(33.5, 20.5)));
  field.ColdStart();
  ASSERT_TRUE(field.Solve(1000).converged);
  int paths = 0, steps = 0, cutting = 0;
  // Starts on a fine lattice in the cells around every corner of the block and of the wall.
  const int corners[8][2] = {{12, 14}, {17, 14}, {12, 19}, {17, 19},
                             {24, 8},  {25, 8},  {24, 30}, {25, 30}};
  for (const auto& corner : corners) {
    for (int dy = -2; dy <= 2; ++dy) {
      for (int dx = -2; dx <= 2; ++dx) {
        for (double fy = 0.05; fy < 1.0; fy += 0.15) {
          for (double fx = 0.05; fx < 1.0; fx += 0.15) {
            const Vec2 start(corner[0] + dx + fx, corner[1] + dy + fy);
            const auto c = field.CellOf(start);
            if (!c || field.cell(c->first, c->second) != FieldCell::kFree) continue;
            const auto path = field.DescendPath(start);
            ++paths;
            EXPECT_TRUE(path.reached_goal) << start.transpose();
            EXPECT_FALSE(path.entered_obstacle);
            for (std::size_t k = 1; k < path.points.size(); ++k, ++steps) {
              if (SegmentHitsObstacle(field, path.points[k - 1], path.points[k])) ++cutting;
            }
          }
        }
      }
    }
  }
  EXPECT_GT(paths, 500);
  EXPECT_GT(steps, 10000);
  EXPECT_EQ(cutting, 0) << "of " << steps << " steps";
}

}  // namespace
}  // namespace spott_harmonic_planner
