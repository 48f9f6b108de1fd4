// The Galerkin multigrid hierarchy (src/hierarchy.h): coarsening that keeps a corridor on every
// level (the conservative rule emptied the level below a corridor, so the "coarsest" level stayed
// the window's size), work that follows the unknowns, and a V-cycle that converges there.
#include <gtest/gtest.h>

#include <cmath>

#include "../src/hierarchy.h"
#include "spott_harmonic_planner/solver.h"

namespace spott_harmonic_planner {
namespace {

GridMask CorridorMask(int n, int length, int width) {
  GridMask m;
  m.width = m.height = n;
  m.free.assign(static_cast<std::size_t>(n) * n, 0);
  const int x0 = (n - length) / 2, y0 = n / 2 - width / 2;
  for (int y = y0; y < y0 + width; ++y) {
    for (int x = x0; x < x0 + length; ++x) m.free[static_cast<std::size_t>(y) * n + x] = 1;
  }
  return m;
}

TEST(Hierarchy, GalerkinCoarseningKeepsACorridorOnEveryLevel) {
  for (int width : {1, 3, 5, 9}) {
    SCOPED_TRACE(width);
    const GridMask m = CorridorMask(513, 500, width);
    internal::Hierarchy<double> h;
    h.Build(m, Stencil::kFivePoint);
    ASSERT_GE(h.levels(), 2);
    std::size_t total = 0;
    for (int l = 0; l < h.levels(); ++l) {
      EXPECT_GT(h.unknowns(l), 0u) << "level " << l;
      if (l > 0) {
        EXPECT_LT(h.unknowns(l), h.unknowns(l - 1)) << "level " << l;
      }
      total += h.unknowns(l);
    }
    // The coarsest level is small (solved exactly), and all levels together cost about twice
    // the corridor's own cells: the work follows the unknowns, not the 513 x 513 window.
    EXPECT_LE(h.unknowns(h.levels() - 1),
              static_cast<std::size_t>(internal::Hierarchy<double>::kCoarsestUnknowns));
    EXPECT_LT(total, 2.5 * h.unknowns(0));
  }
}

// One V(1,1)-cycle on the residual equation of a 9-wide corridor with zero Dirichlet values:
// the error of a random start falls by at least 4x per cycle (measured 0.1-0.2).
TEST(Hierarchy, VCycleReducesTheCorridorErrorEveryCycle) {
  const int n = 257;
  const GridMask m = CorridorMask(n, 240, 9);
  internal::Hierarchy<double> h;
  h.Build(m, Stencil::kFivePoint);
  std::vector<double> u(m.free.size(), 0.0), r(u.size(), 0.0), e(u.size(), 0.0);
  std::uint32_t s = 12345;
  for (std::size_t i = 0; i < u.size(); ++i) {
    s = s * 1664525u + 1013904223u;
    if (m.free[i]) u[i] = static_cast<double>(s >> 8) / (1u << 24) - 0.5;
  }
  // The exact solution is 0: u is the error; r = -A u.
  const auto norm = [&]() {
    double worst = 0.0;
    for (double v : u) worst = std::max(worst, std::abs(v));
    return worst;
  };
  double before = norm();
  for (int cycle = 0; cycle < 6; ++cycle) {
    h.Apply(u.data(), r.data());
    for (std::size_t i = 0; i < r.size(); ++i) r[i] = m.free[i] ? -r[i] : 0.0;
    h.VCycle(r.data(), e.data(), 1, 1);
    for (std::size_t i = 0; i < u.size(); ++i) u[i] += e[i];
    const double after = norm();
    EXPECT_LT(after, 0.25 * before) << "cycle " << cycle;
    before = after;
  }
}

}  // namespace
}  // namespace spott_harmonic_planner
