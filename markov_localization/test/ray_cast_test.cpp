// MapModel::RayCastHit jumps across the cells its clearance says are free; it must meet the
// same first obstacle as the plain cell-by-cell traversal (written out here as the reference).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "markov_localization/map_model.h"
#include "spott_map/world_loader.h"

namespace ml = markov_localization;
using ml::Vec2;

namespace {

// Amanatides-Woo over the fine raster, one cell at a time, the occupancy read per cell.
ml::MapModel::Hit StepByStep(const ml::MapModel& map, const Vec2& from, const Vec2& dir,
                             double max_range) {
  const double fres = map.resolution() / map.subdivision();
  const int w = map.width() * map.subdivision(), h = map.height() * map.subdivision();
  auto occupied = [&](int x, int y) {
    return map.FineOccupiedAt(map.origin() + fres * Vec2(x + 0.5, y + 0.5));
  };
  auto inside = [&](int x, int y) { return x >= 0 && y >= 0 && x < w && y < h; };
  const double fx = (from.x() - map.origin().x()) / fres, fy = (from.y() - map.origin().y()) / fres;
  int ix = static_cast<int>(std::floor(fx)), iy = static_cast<int>(std::floor(fy));
  const ml::MapModel::Hit miss{max_range, 0.0, false, false};
  if (!inside(ix, iy)) return miss;
  const double dx = dir.x(), dy = dir.y();
  if (occupied(ix, iy)) return {0.0, 0.0, true, std::abs(dx) >= std::abs(dy)};
  const double inf = std::numeric_limits<double>::infinity();
  const double tdx = dx != 0.0 ? std::abs(1.0 / dx) : inf,
               tdy = dy != 0.0 ? std::abs(1.0 / dy) : inf;
  double tmx = dx > 0 ? (ix + 1 - fx) * tdx : (dx < 0 ? (fx - ix) * tdx : inf);
  double tmy = dy > 0 ? (iy + 1 - fy) * tdy : (dy < 0 ? (fy - iy) * tdy : inf);
  while (true) {
    double t;
    bool x_face = tmx < tmy;
    if (x_face) {
      t = tmx;
      tmx += tdx;
      ix += dx > 0 ? 1 : -1;
    } else {
      t = tmy;
      tmy += tdy;
      iy += dy > 0 ? 1 : -1;
    }
    if (t >= max_range / fres || !inside(ix, iy)) return miss;
    if (occupied(ix, iy)) {
      const double exit = std::min(tmx, tmy);
      return {t * fres, map.surface_inside_cells() ? 0.5 * (exit - t) * fres : 0.0, true, x_face};
    }
  }
}

// `corner_tie`: a beam through exact cell corners; which of the two cells beside a corner it
// enters is a tie, and with it the face and the path through the cell hit (the depth): only
// the range must agree.
void ExpectSameHit(const ml::MapModel& map, const Vec2& from, const Vec2& dir, double max_range,
                   bool corner_tie = false) {
  const auto want = StepByStep(map, from, dir, max_range);
  const auto got = map.RayCastHit(from, dir, max_range);
  ASSERT_EQ(got.hit, want.hit) << "from " << from.transpose() << " dir " << dir.transpose();
  // Summed and multiplied-out steps differ by rounding only.
  EXPECT_NEAR(got.range_m, want.range_m, 1e-9) << "from " << from.transpose();
  if (want.hit && !corner_tie) {
    EXPECT_NEAR(got.depth_m, want.depth_m, 1e-9);
    EXPECT_EQ(got.x_face, want.x_face) << "from " << from.transpose() << " dir " << dir.transpose();
  }
}

void RandomRays(const ml::MapModel& map, int count, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Vec2 size = map.resolution() * Vec2(map.width(), map.height());
  for (int i = 0; i < count; ++i) {
    const Vec2 from = map.origin() + Vec2(u(rng) * size.x(), u(rng) * size.y());
    const double a = (2.0 * u(rng) - 1.0) * M_PI;
    ExpectSameHit(map, from, Vec2(std::cos(a), std::sin(a)), 0.5 + 12.0 * u(rng));
    if (::testing::Test::HasFailure()) return;
  }
}

}  // namespace

TEST(RayCast, JumpsMeetTheFirstObstacleOfTheStepByStepTraversalOnRandomGrids) {
  std::mt19937 rng(7);
  std::bernoulli_distribution wall(0.04);
  const int n = 120;
  std::vector<std::int8_t> data(n * n, 0);
  for (auto& v : data) v = wall(rng) ? 100 : 0;
  for (int i = 0; i < n; ++i) data[i] = data[(n - 1) * n + i] = 0;  // beams leave at the edge
  const auto map = ml::MapModel::FromOccupancy(Vec2(-1.0, 2.0), n, n, 0.05, data, 50, 0.0);
  RandomRays(map, 20000, 1);
}

TEST(RayCast, JumpsMeetTheFirstObstacleOfTheStepByStepTraversalInABuilding) {
  auto world = spott_map::LoadWorldFile(std::string(WORLDS_DIR) + "/bonn_department.yaml");
  ASSERT_TRUE(world.world);
  ml::MapModelParameters p;
  p.ray_cast_subdivision = 5;  // the node's raster, surfaces inside the fine cells
  const auto map = ml::MapModel::FromWorld(*world.world, p);
  ASSERT_TRUE(map.surface_inside_cells());
  RandomRays(map, 20000, 2);
}

TEST(RayCast, RaysAlongTheAxesAndDiagonalsThroughCellCornersAgree) {
  // Exact ties of the traversal: beams along grid lines and through cell corners.
  auto world = spott_map::LoadWorldFile(std::string(WORLDS_DIR) + "/bonn_department.yaml");
  ASSERT_TRUE(world.world);
  ml::MapModelParameters p;
  p.resolution_m = 0.2;
  p.ray_cast_subdivision = 5;
  const auto map = ml::MapModel::FromWorld(*world.world, p);
  const double s = std::sqrt(0.5);
  const Vec2 dirs[] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {s, s}, {-s, s}, {s, -s}, {-s, -s}};
  for (int iy = 1; iy < map.height() - 1; iy += 3)
    for (int ix = 1; ix < map.width() - 1; ix += 3) {
      if (!map.IsState(ix, iy)) continue;
      for (const Vec2& d : dirs) {
        const bool diagonal = d.x() != 0.0 && d.y() != 0.0;
        ExpectSameHit(map, map.CellCentre(ix, iy), d, 8.0, diagonal);
        ExpectSameHit(map, map.CellCentre(ix, iy) - 0.5 * map.resolution() * Vec2(1, 1), d, 8.0,
                      diagonal);
        if (HasFailure()) return;
      }
    }
}

TEST(RayCast, AnAngleGivesTheSameHitAsItsDirection) {
  std::vector<std::int8_t> data(40 * 40, 0);
  for (int i = 0; i < 40; ++i) data[i * 40 + 30] = 100;  // a wall at x = 30 cells
  const auto map = ml::MapModel::FromOccupancy(Vec2(0, 0), 40, 40, 0.1, data, 50, 0.0);
  for (double a = -0.6; a < 0.6; a += 0.05) {  // within the 4 m grid
    const auto by_angle = map.RayCastHit(Vec2(0.55, 2.05), a, 10.0);
    const auto by_dir = map.RayCastHit(Vec2(0.55, 2.05), Vec2(std::cos(a), std::sin(a)), 10.0);
    EXPECT_TRUE(by_angle.hit);
    EXPECT_EQ(by_angle.range_m, by_dir.range_m);
    EXPECT_NEAR(by_angle.range_m, 2.45 / std::cos(a), 1e-9) << a;
  }
}
