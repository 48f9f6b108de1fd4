#include "spott_harmonic_planner/potential_field.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <queue>
#include <random>

#include "test_maps.h"

namespace spott_harmonic_planner {
namespace {

using testing_maps::Block;
using testing_maps::EmptyRaster;
using testing_maps::RandomOffice;

FieldOptions Options(SolverKind kind, Stencil stencil = Stencil::kFivePoint) {
  FieldOptions o;
  o.solver.kind = kind;
  o.solver.stencil = stencil;
  o.tolerance = 1e-10;
  return o;
}

const SolverKind kAllSolvers[] = {SolverKind::kSorRedBlack, SolverKind::kAdi,
                                  SolverKind::kMultigrid, SolverKind::kMultigridCg};

// 5 x 3 window: one free row of three cells between border cells; goal in the first. With the
// 5-point stencil p2 = (1 + p3) / 4 and p3 = p2 / 4, so p2 = 4/15 and p3 = 1/15; with the
// 9-point stencil p2 = 0.2 (1 + p3) and p3 = 0.2 p2, so p2 = 5/24 and p3 = 1/24.
TEST(PotentialField, ThreeCellRowMatchesHandSolutionForEveryKernel) {
  for (SolverKind kind : kAllSolvers) {
    for (Stencil stencil : {Stencil::kFivePoint, Stencil::kNinePoint}) {
      PotentialField field(Options(kind, stencil));
      field.SetOccupancy(EmptyRaster(5, 3));
      ASSERT_TRUE(field.SetGoalPoint(Vec2(1.5, 1.5)));
      field.ColdStart();
      const IterationReport report = field.Solve(500);
      const bool five = stencil == Stencil::kFivePoint;
      SCOPED_TRACE(std::string(ToString(kind)) + " " + ToString(stencil));
      EXPECT_TRUE(report.converged);
      EXPECT_NEAR(field.GoalProbability(2, 1), five ? 4.0 / 15 : 5.0 / 24, 1e-9);
      EXPECT_NEAR(field.GoalProbability(3, 1), five ? 1.0 / 15 : 1.0 / 24, 1e-9);
      EXPECT_NEAR(field.Potential(3, 1), five ? 14.0 / 15 : 23.0 / 24, 1e-9);
      EXPECT_EQ(field.GoalProbability(1, 1), 1.0);
      EXPECT_EQ(field.GoalProbability(0, 1), 0.0);  // the border holds the high value of u
    }
  }
}

TEST(PotentialField, GoalInBlockedCellOrOutsideIsRefused) {
  PotentialField field(Options(SolverKind::kSorRedBlack));
  auto raster = EmptyRaster(10, 10);
  Block(raster, 4, 4, 5, 5);
  field.SetOccupancy(raster);
  EXPECT_FALSE(field.SetGoalPoint(Vec2(4.5, 4.5)));
  EXPECT_FALSE(field.SetGoalPoint(Vec2(11.0, 4.5)));
  EXPECT_FALSE(field.SetGoalPoint(Vec2(0.5, 0.5)));  // the border ring is an obstacle
  EXPECT_FALSE(field.HasGoal());
  EXPECT_TRUE(field.SetGoalPoint(Vec2(2.5, 2.5)));
}

// Discrete steepest descent: from every reachable free cell, the best 8-neighbour (no obstacle)
// must be strictly closer to the goal, until a goal cell. Returns the number of cells from which
// that fails.
int CellsWithoutDescent(const PotentialField& f) {
  int stuck = 0;
  for (int y = 1; y < f.height() - 1; ++y) {
    for (int x = 1; x < f.width() - 1; ++x) {
      if (f.cell(x, y) != FieldCell::kFree || f.GoalProbability(x, y) <= 0.0) continue;
      int cx = x, cy = y;
      for (int steps = 0; f.cell(cx, cy) != FieldCell::kGoal; ++steps) {
        int bx = -1, by = -1;
        double best = f.GoalProbability(cx, cy);
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            if (f.cell(cx + dx, cy + dy) == FieldCell::kObstacle) continue;
            if (f.GoalProbability(cx + dx, cy + dy) > best) {
              best = f.GoalProbability(cx + dx, cy + dy);
              bx = cx + dx;
              by = cy + dy;
            }
          }
        }
        if (bx < 0 || steps > f.width() * f.height()) {
          ++stuck;
          break;
        }
        cx = bx;
        cy = by;
      }
    }
  }
  return stuck;
}

// Cells reachable from the goal by 4-connected free moves (what the 5-point stencil couples).
int ReachableFreeCells(const PotentialField& f) {
  std::vector<char> seen(f.cells().size(), 0);
  std::queue<std::pair<int, int>> q;
  for (int y = 0; y < f.height(); ++y) {
    for (int x = 0; x < f.width(); ++x) {
      if (f.cell(x, y) == FieldCell::kGoal) q.push({x, y});
    }
  }
  int count = 0;
  while (!q.empty()) {
    const auto [x, y] = q.front();
    q.pop();
    const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
    for (int k = 0; k < 4; ++k) {
      const int nx = x + dx[k], ny = y + dy[k];
      if (nx < 0 || ny < 0 || nx >= f.width() || ny >= f.height()) continue;
      const std::size_t i = static_cast<std::size_t>(ny) * f.width() + nx;
      if (seen[i] || f.cell(nx, ny) != FieldCell::kFree) continue;
      seen[i] = 1;
      ++count;
      q.push({nx, ny});
    }
  }
  return count;
}

class RandomMaps : public ::testing::TestWithParam<SolverKind> {};

TEST_P(RandomMaps, DescentFromEveryFreeCellReachesGoalWithoutEnteringObstacle) {
  int maps_checked = 0;
  for (std::uint32_t seed = 1; seed <= 12; ++seed) {
    const bool border_goal = seed % 2 == 0;
    auto raster = RandomOffice(40, 5, 2, 1, seed);
    FieldOptions options = Options(GetParam());
    options.norm = ResidualNorm::kRelative;  // resolve the deep nooks too (README)
    options.tolerance = 1e-6;
    PotentialField field(options);
    field.SetOccupancy(raster);
    bool ok;
    if (border_goal) {
      ok = field.SetGoalSegment({Vec2(40.0, 10.0), Vec2(40.0, 30.0)}, 0.6);
    } else {
      ok = false;
      for (int k = 0; k < 40 && !ok; ++k) ok = field.SetGoalPoint(Vec2(30.5 - k * 0.5, 20.5));
    }
    if (!ok) continue;
    ++maps_checked;
    field.ColdStart();
    const IterationReport report = field.Solve(20000);
    SCOPED_TRACE("seed " + std::to_string(seed));
    ASSERT_TRUE(report.converged) << report.residual;
    std::printf("[          ] %s seed %u: %d sweeps\n", ToString(GetParam()), seed, report.sweeps);
    EXPECT_EQ(CellsWithoutDescent(field), 0);
    // Continuous steepest descent from every reachable free cell's centre.
    int reached = 0, started = 0;
    for (int y = 1; y < field.height() - 1; ++y) {
      for (int x = 1; x < field.width() - 1; ++x) {
        if (field.cell(x, y) != FieldCell::kFree || field.GoalProbability(x, y) <= 0.0) continue;
        ++started;
        const auto path = field.DescendPath(field.CellCentre(x, y));
        EXPECT_FALSE(path.entered_obstacle) << "from " << x << "," << y;
        reached += path.reached_goal ? 1 : 0;
      }
    }
    EXPECT_EQ(reached, started);
    EXPECT_EQ(started, ReachableFreeCells(field));  // p > 0 exactly where the goal is reachable
  }
  EXPECT_GE(maps_checked, 10);
}

INSTANTIATE_TEST_SUITE_P(AllSolvers, RandomMaps, ::testing::ValuesIn(kAllSolvers),
                         [](const auto& info) { return std::string(ToString(info.param)); });

// The paper's optimality argument: the converged 5-point u at a cell is the probability that a
// simple random walk from it hits an obstacle before the goal. Monte-Carlo with a seeded
// generator, 20000 walks per cell: 4 standard deviations are at most 4 * 0.5 / sqrt(20000).
TEST(PotentialField, FivePointFieldMatchesRandomWalkHittingProbability) {
  auto raster = EmptyRaster(8, 7);
  Block(raster, 3, 2, 4, 3);
  PotentialField field(Options(SolverKind::kSorRedBlack));
  field.SetOccupancy(raster);
  ASSERT_TRUE(field.SetGoalPoint(Vec2(6.5, 5.5)));
  field.ColdStart();
  ASSERT_TRUE(field.Solve(5000).converged);
  std::mt19937 rng(42);
  std::uniform_int_distribution<int> dir(0, 3);
  const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
  const int walks = 20000;
  for (int y = 1; y < 6; ++y) {
    for (int x = 1; x < 7; ++x) {
      if (field.cell(x, y) != FieldCell::kFree) continue;
      int hit_obstacle = 0;
      for (int w = 0; w < walks; ++w) {
        int cx = x, cy = y;
        while (field.cell(cx, cy) == FieldCell::kFree) {
          const int d = dir(rng);
          cx += dx[d];
          cy += dy[d];
        }
        hit_obstacle += field.cell(cx, cy) == FieldCell::kObstacle ? 1 : 0;
      }
      EXPECT_NEAR(field.Potential(x, y), static_cast<double>(hit_obstacle) / walks,
                  4 * 0.5 / std::sqrt(walks))
          << "cell " << x << "," << y;
    }
  }
}

TEST(PotentialField, WarmStartAfterNewObstacleMatchesColdSolve) {
  for (SolverKind kind : kAllSolvers) {
    SCOPED_TRACE(ToString(kind));
    auto raster = RandomOffice(64, 6, 1, 1, 7);
    PotentialField warm(Options(kind));
    warm.SetOccupancy(raster);
    ASSERT_TRUE(warm.SetGoalPoint(Vec2(5.5, 5.5)) || warm.SetGoalPoint(Vec2(8.5, 8.5)));
    warm.ColdStart();
    ASSERT_TRUE(warm.Solve(20000).converged);
    Block(raster, 30, 30, 34, 34);  // a sensed obstacle appears
    warm.SetOccupancy(raster);
    EXPECT_GT(warm.report().sweeps, 0);  // same window: the values are kept
    const int warm_sweeps_before = warm.report().sweeps;
    ASSERT_TRUE(warm.Solve(20000).converged);
    const int warm_sweeps = warm.report().sweeps - warm_sweeps_before;

    PotentialField cold(Options(kind));
    cold.SetOccupancy(raster);
    ASSERT_TRUE(cold.SetGoalPoint(Vec2(5.5, 5.5)) || cold.SetGoalPoint(Vec2(8.5, 8.5)));
    cold.ColdStart();
    ASSERT_TRUE(cold.Solve(20000).converged);
    double worst = 0.0;
    for (std::size_t i = 0; i < cold.values().size(); ++i) {
      worst = std::max(worst, std::abs(cold.values()[i] - warm.values()[i]));
    }
    // Both stop at residual 1e-10; the error is within a few hundred residuals on 64 x 64.
    EXPECT_LT(worst, 1e-7);
    EXPECT_LE(warm_sweeps, cold.report().sweeps);
  }
}

// Anytime: the heuristic initial guess plus two sweeps already points at the goal in open space.
TEST(PotentialField, AnytimeAnswerPointsAtGoalInOpenSpace) {
  PotentialField field(Options(SolverKind::kSorRedBlack));
  field.SetOccupancy(EmptyRaster(61, 61));
  ASSERT_TRUE(field.SetGoalPoint(Vec2(30.5, 30.5)));
  field.ColdStart();
  field.Iterate(2);
  EXPECT_FALSE(field.report().converged);
  const Vec2 goal(30.5, 30.5);
  for (double angle = 0.1; angle < 2 * M_PI; angle += 0.5) {
    const Vec2 from = goal + 12.0 * Vec2(std::cos(angle), std::sin(angle));
    const auto d = field.DescentDirection(from);
    ASSERT_TRUE(d.has_value());
    const Vec2 want = (goal - from).normalized();
    EXPECT_GT(d->dot(want), std::cos(25.0 * M_PI / 180.0)) << "angle " << angle;
  }
}

TEST(PotentialField, NoDirectionWhereGoalIsUnreachable) {
  auto raster = EmptyRaster(20, 20);
  Block(raster, 10, 1, 10, 18);  // a wall cuts the window in two
  PotentialField field(Options(SolverKind::kMultigrid));
  field.SetOccupancy(raster);
  ASSERT_TRUE(field.SetGoalPoint(Vec2(3.5, 10.5)));
  field.ColdStart();
  ASSERT_TRUE(field.Solve(200).converged);
  EXPECT_FALSE(field.DescentDirection(Vec2(15.5, 10.5)).has_value());
  EXPECT_TRUE(field.DescentDirection(Vec2(7.5, 10.5)).has_value());
  EXPECT_FALSE(field.DescendPath(Vec2(15.5, 10.5)).reached_goal);
}

TEST(PotentialField, ClearanceIsDistanceToNearestBlockedSquare) {
  auto raster = EmptyRaster(21, 21);
  Block(raster, 10, 10, 10, 10);
  PotentialField field(Options(SolverKind::kSorRedBlack));
  field.SetOccupancy(raster);
  EXPECT_NEAR(field.Clearance(Vec2(13.5, 10.5)), 2.5, 1e-6);  // 3 cells east, minus half a cell
  EXPECT_NEAR(field.Clearance(Vec2(1.5, 15.5)), 0.5, 1e-6);   // next to the border ring
  EXPECT_NEAR(field.Clearance(Vec2(10.5, 10.5)), 0.0, 1e-6);
}

// The steering scales the bias and the speed with the clearance: it must not step by a whole
// cell between two cells (the robot weaved along a wall when it did).
TEST(PotentialField, ClearanceIsContinuousBetweenCellCentres) {
  auto raster = EmptyRaster(21, 21);
  Block(raster, 10, 10, 10, 10);
  PotentialField field(Options(SolverKind::kSorRedBlack));
  field.SetOccupancy(raster);
  EXPECT_NEAR(field.Clearance(Vec2(13.0, 10.5)), 2.0, 1e-6);  // halfway between 2.5 and 1.5
  double last = field.Clearance(Vec2(11.0, 10.5));
  for (double x = 11.05; x <= 14.0; x += 0.05) {
    const double c = field.Clearance(Vec2(x, 10.5));
    EXPECT_GE(c, last) << x;                // away from the block
    EXPECT_LE(c - last, 0.05 + 1e-9) << x;  // no jump
    last = c;
  }
}

TEST(PotentialField, BadOptionsAreRefusedByName) {
  FieldOptions o;
  o.tolerance = 0.0;
  o.solver.omega = 2.5;
  const auto v = ValidateFieldOptions(o);
  ASSERT_EQ(v.size(), 2u);
  EXPECT_NE(v[0].find("omega"), std::string::npos);
  EXPECT_NE(v[1].find("tolerance"), std::string::npos);
  EXPECT_THROW(PotentialField{o}, std::invalid_argument);
}

// The re-centred window (moved by whole cells): the values move with it, so the field answers at
// once with the last window's directions, and the solve from them ends at the cold solve's field.
TEST(PotentialField, WindowShiftMovesTheValuesAndConvergesToTheColdField) {
  const auto world = RandomOffice(80, 6, 1, 1, 9);
  // Two 64 x 64 windows of the same world, the second 3 cells east and 2 north of the first.
  const auto window = [&world](int ox, int oy) {
    spott_map::OccupancyRaster r(Vec2(ox, oy), 64, 64, 1.0);
    for (int y = 0; y < 64; ++y) {
      for (int x = 0; x < 64; ++x) {
        if (world.Blocked(x + ox, y + oy)) r.Mark(x, y, spott_map::Cell::kObstacle);
      }
    }
    return r;
  };
  FieldOptions o;
  o.tolerance = 1e-9;
  PotentialField warm(o);
  warm.SetOccupancy(window(5, 5));
  Vec2 goal(40.5, 40.5);
  for (int k = 0; k < 20 && !warm.SetGoalPoint(goal); ++k) goal += Vec2(1.0, 0.0);
  ASSERT_TRUE(warm.HasGoal());
  warm.ColdStart();
  ASSERT_TRUE(warm.Solve(1000).converged);
  const double before = warm.GoalProbability(30, 30);  // map cell (35, 35)
  warm.SetOccupancy(window(8, 7));
  EXPECT_TRUE(warm.HasGoal());                      // the goal point moved with the window
  EXPECT_EQ(warm.GoalProbability(27, 28), before);  // the same map cell
  const int sweeps_before = warm.report().sweeps;
  ASSERT_TRUE(warm.Solve(1000).converged);
  PotentialField cold(o);
  cold.SetOccupancy(window(8, 7));
  ASSERT_TRUE(cold.SetGoalPoint(goal));
  cold.ColdStart();
  ASSERT_TRUE(cold.Solve(1000).converged);
  double worst = 0.0;
  for (std::size_t i = 0; i < cold.values().size(); ++i) {
    worst = std::max(worst, std::abs(cold.values()[i] - warm.values()[i]));
  }
  EXPECT_LT(worst, 1e-7);
  EXPECT_GT(warm.report().sweeps, sweeps_before);  // iterated on from the moved values
}

}  // namespace
}  // namespace spott_harmonic_planner
