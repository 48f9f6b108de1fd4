#include "spott_harmonic_planner/solver.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace spott_harmonic_planner {
namespace {

// A 5 x 3 grid with three unknowns in a row between a left value 0 and a right value 1, the top
// and bottom rows fixed to the linear profile: the discrete harmonic solution is linear in x,
// u = x / 4, for every stencil (both reproduce linear functions exactly).
struct LineProblem {
  GridMask mask;
  std::vector<double> u;
};

LineProblem MakeLinearProblem() {
  LineProblem p;
  p.mask.width = 5;
  p.mask.height = 3;
  p.mask.free.assign(15, 0);
  p.u.assign(15, 0.0);
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 5; ++x) p.u[y * 5 + x] = (y == 1 && x > 0 && x < 4) ? 0.5 : x / 4.0;
  }
  for (int x = 1; x < 4; ++x) p.mask.free[5 + x] = 1;
  return p;
}

class EverySolver : public ::testing::TestWithParam<std::tuple<SolverKind, Stencil>> {};

TEST_P(EverySolver, ReproducesLinearProfileBetweenFixedValues) {
  SolverOptions options;
  options.kind = std::get<0>(GetParam());
  options.stencil = std::get<1>(GetParam());
  auto solver = MakeSolver(options);
  LineProblem p = MakeLinearProblem();
  solver->Setup(p.mask);
  for (int i = 0; i < 200; ++i) solver->Iterate(p.u.data());
  EXPECT_NEAR(p.u[6], 0.25, 1e-12);
  EXPECT_NEAR(p.u[7], 0.50, 1e-12);
  EXPECT_NEAR(p.u[8], 0.75, 1e-12);
  EXPECT_DOUBLE_EQ(p.u[0], 0.0);  // fixed cells untouched
  EXPECT_DOUBLE_EQ(p.u[4], 1.0);
}

INSTANTIATE_TEST_SUITE_P(
    AllKernels, EverySolver,
    ::testing::Combine(::testing::Values(SolverKind::kSorRedBlack, SolverKind::kAdi,
                                         SolverKind::kMultigrid),
                       ::testing::Values(Stencil::kFivePoint, Stencil::kNinePoint)));

}  // namespace
}  // namespace spott_harmonic_planner
