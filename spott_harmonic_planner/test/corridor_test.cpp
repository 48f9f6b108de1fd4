// Long corridors (paper footnote 16): the plain potential u goes flat, the complement storage
// of PotentialField does not.
#include <gtest/gtest.h>

#include <cmath>

#include "spott_harmonic_planner/potential_field.h"
#include "test_maps.h"

namespace spott_harmonic_planner {
namespace {

// A corridor `length` cells long and `width` free cells wide inside its walls (the window's
// border ring), the goal on the whole left end (a border segment).
PotentialField SolveCorridor(int length, int width, SolverKind kind) {
  FieldOptions o;
  o.solver.kind = kind;
  o.norm = ResidualNorm::kRelative;
  o.tolerance = 1e-6;
  PotentialField field(o);
  field.SetOccupancy(testing_maps::EmptyRaster(length + 2, width + 2));
  EXPECT_TRUE(field.SetGoalSegment({Vec2(0.0, 0.0), Vec2(0.0, width + 2.0)}, 0.6));
  field.ColdStart();
  const auto report = field.Solve(200000);
  EXPECT_TRUE(report.converged) << report.residual;
  return field;
}

template <typename T>
std::vector<T> PlainPotential(const PotentialField& f) {
  std::vector<T> u(f.values().size());
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = static_cast<T>(1.0 - f.values()[i]);
  return u;
}

template <typename T>
std::vector<T> NegatedComplement(const PotentialField& f) {
  std::vector<T> u(f.values().size());
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = -static_cast<T>(f.values()[i]);
  return u;
}

// p decays like exp(-pi d / (w + 1)) along a corridor of w free cells, so u = 1 - p rounds to 1
// in double once pi d / (w + 1) > 53 ln 2 = 36.7, about 11.7 (w + 1) cells from the goal: the
// plain field of a 5-wide corridor is exact at 7:1 and flat well before 20:1.
TEST(Corridor, PlainDoubleGoesFlatBetweenSevenAndTwentyToOne) {
  const int w = 5;
  const PotentialField short_corridor = SolveCorridor(7 * w, w, SolverKind::kAdi);
  EXPECT_EQ(CountFlatCells(short_corridor, PlainPotential<double>(short_corridor)), 0);
  const PotentialField f = SolveCorridor(20 * w, w, SolverKind::kAdi);
  EXPECT_GT(CountFlatCells(f, PlainPotential<double>(f)), 0);
  EXPECT_GT(CountFlatCells(f, PlainPotential<float>(f)), 0);
  EXPECT_EQ(CountFlatCells(f, NegatedComplement<double>(f)), 0);
}

TEST(Corridor, HundredToOneCorridorHasNoFlatCellAndAUsablePath) {
  for (SolverKind kind : {SolverKind::kAdi, SolverKind::kSorRedBlack, SolverKind::kMultigrid}) {
    SCOPED_TRACE(ToString(kind));
    const int w = 5;
    const PotentialField f = SolveCorridor(100 * w, w, kind);
    EXPECT_EQ(CountFlatCells(f, NegatedComplement<double>(f)), 0);
    EXPECT_GT(CountFlatCells(f, PlainPotential<double>(f)), 300);  // what the plain field loses
    // Far end: p is tiny but positive and still decreasing away from the goal.
    EXPECT_GT(f.GoalProbability(500, 3), 0.0);
    EXPECT_LT(f.GoalProbability(500, 3), 1e-100);  // exp(-0.512 * 500): 5e-112
    EXPECT_LT(f.GoalProbability(500, 3), f.GoalProbability(499, 3));
    const auto path = f.DescendPath(f.CellCentre(500, 3));
    EXPECT_TRUE(path.reached_goal);
    EXPECT_FALSE(path.entered_obstacle);
    EXPECT_NEAR(path.length_m, 499.5, 2.0);  // straight down the corridor
  }
}

}  // namespace
}  // namespace spott_harmonic_planner
