// The exact solve of thin regions (src/thin_direct.h): relative accuracy down to any magnitude,
// corridors far beyond double's range, and the same field as the iterative solvers.
#include <gtest/gtest.h>

#include <cmath>

#include "spott_harmonic_planner/potential_field.h"
#include "test_maps.h"

namespace spott_harmonic_planner {
namespace {

// lambda + 1 / lambda = 4 - 2 cos(pi / (w + 1)): the decay per cell of the slowest mode along a
// corridor w free cells wide (5-point stencil); w = 5: lambda = 0.599280, ln lambda = -0.512026.
double CorridorDecay(int w) {
  const double s = 4.0 - 2.0 * std::cos(M_PI / (w + 1));
  return (s - std::sqrt(s * s - 4.0)) / 2.0;
}

PotentialField Corridor(int length, int width, double tolerance = 1e-6) {
  FieldOptions o;
  o.tolerance = tolerance;
  PotentialField field(o);  // the defaults: multigrid_cg, relative
  field.SetOccupancy(testing_maps::EmptyRaster(length + 2, width + 2));
  EXPECT_TRUE(field.SetGoalSegment({Vec2(0.0, 0.0), Vec2(0.0, width + 2.0)}, 0.6));
  field.ColdStart();
  return field;
}

TEST(ThinDirect, CorridorDecaysAtTheHandComputedRatePerCell) {
  const int w = 5;
  PotentialField f = Corridor(400, w);
  const auto r = f.Solve(10);
  EXPECT_TRUE(r.converged) << r.residual;
  EXPECT_EQ(r.sweeps, 1);  // one exact solve
  EXPECT_LT(r.residual, 1e-12);
  const double lnl = std::log(CorridorDecay(w));
  EXPECT_NEAR(lnl, -0.512026, 1e-6);
  // Far from both ends p(x + 1) / p(x) is the slowest mode's lambda to every digit that matters
  // (the next mode decays e^-1.9 per cell faster), on every row.
  for (int y = 1; y <= w; ++y) {
    for (int x = 50; x < 300; x += 50) {
      EXPECT_NEAR(f.LogGoalProbability(x + 1, y) - f.LogGoalProbability(x, y), lnl, 1e-9)
          << x << "," << y;
    }
  }
}

// p at 300:1 falls below double's smallest value (the relative norm used to stop converging
// from about 285:1: subnormal values, then an infinite relative residual, and no path).
TEST(ThinDirect, ThousandToOneCorridorConvergesWithAFullPath) {
  const int w = 5;
  for (int ratio : {300, 1000, 1200}) {
    SCOPED_TRACE(ratio);
    const int length = ratio * w;
    PotentialField f = Corridor(length, w);
    const auto r = f.Solve(10);
    EXPECT_TRUE(r.converged) << r.residual;
    EXPECT_TRUE(f.extended_range());
    // ln p at the far end: about length * ln lambda (every cell keeps its own exponent).
    const double far = f.LogGoalProbability(length, 3);
    EXPECT_NEAR(far / length, std::log(CorridorDecay(w)), 0.01);
    EXPECT_EQ(f.GoalProbability(length, 3), 0.0);  // below double: values() holds 0 there
    // Strictly increasing towards the goal along every row: descent has a direction everywhere.
    for (int y = 1; y <= w; ++y) {
      for (int x = 2; x <= length; ++x) {
        ASSERT_LT(f.LogGoalProbability(x, y), f.LogGoalProbability(x - 1, y)) << x << "," << y;
      }
    }
    ASSERT_TRUE(f.DescentDirection(f.CellCentre(length, 3)).has_value());
    EXPECT_LT(f.DescentDirection(f.CellCentre(length, 3))->x(), -0.999);  // to the goal (left)
    const auto path = f.DescendPath(f.CellCentre(length, 3));
    EXPECT_TRUE(path.reached_goal);
    EXPECT_FALSE(path.entered_obstacle);
    EXPECT_NEAR(path.length_m, length - 0.5, 2.0);  // straight down the corridor
  }
}

// A thin but winding region: the exact solve and an iterative solver agree cell by cell.
TEST(ThinDirect, ZigZagCorridorMatchesTheIterativeSolution) {
  // 3-wide zig-zag in solid obstacle: along y = 3..5, up x = 34..36, back along y = 17..19, up
  // x = 3..5; the goal at its far end.
  const auto in = [](int x, int y, int x0, int y0, int x1, int y1) {
    return x >= x0 && x <= x1 && y >= y0 && y <= y1;
  };
  spott_map::OccupancyRaster raster(Vec2(0.0, 0.0), 40, 40, 1.0);
  for (int y = 0; y < 40; ++y) {
    for (int x = 0; x < 40; ++x) {
      const bool free = in(x, y, 2, 3, 36, 5) || in(x, y, 34, 3, 36, 19) ||
                        in(x, y, 3, 17, 36, 19) || in(x, y, 3, 17, 5, 35);
      if (!free) raster.Mark(x, y, spott_map::Cell::kObstacle);
    }
  }
  FieldOptions direct;  // default: multigrid_cg (thin regions solved exactly)
  FieldOptions iterative;
  iterative.solver.kind = SolverKind::kAdi;
  iterative.tolerance = 1e-11;
  PotentialField a(direct), b(iterative);
  for (PotentialField* f : {&a, &b}) {
    f->SetOccupancy(raster);
    ASSERT_TRUE(f->SetGoalPoint(Vec2(4.5, 34.5)));
    f->ColdStart();
    ASSERT_TRUE(f->Solve(200000).converged);
  }
  EXPECT_EQ(a.report().sweeps, 1);  // solved exactly
  int compared = 0;
  for (int y = 0; y < 40; ++y) {
    for (int x = 0; x < 40; ++x) {
      if (a.cell(x, y) != FieldCell::kFree) continue;
      ++compared;
      EXPECT_NEAR(a.GoalProbability(x, y) / b.GoalProbability(x, y), 1.0, 1e-8) << x << "," << y;
    }
  }
  EXPECT_GT(compared, 250);
  EXPECT_LT(a.GoalProbability(3, 3), 1e-25);  // the far end, about 100 cells of e^-0.75 away
}

}  // namespace
}  // namespace spott_harmonic_planner
