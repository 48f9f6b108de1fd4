// Exact solve of the field's Dirichlet problem when the free region is thin (corridors), private
// to the library.
//
// The unknowns are ordered by their stencil distance from the goal (breadth-first levels: a
// level is a cross-section of a corridor). The stencil couples a level only to itself and to
// its two neighbouring levels, so the matrix is block tridiagonal and block elimination from
// the far end (the Riccati recursion S_K = A_KK, S_k = A_kk - A_k,k+1 S_k+1^-1 A_k+1,k) followed
// by the sweep x_1 = S_1^-1 b_1, x_k+1 = -S_k+1^-1 A_k+1,k x_k solves it exactly in
// O(sum of level size^3) operations, so in O(cells) along a corridor of fixed width.
//
// Relative accuracy (every cell to its own magnitude, down to any value): the Schur complements
// of the M-matrix A are M-matrices, their Cholesky factors have non-positive off-diagonals, so
// -S^-1 A_k+1,k >= 0 is computed from sums of non-negative terms only, and so is every x_k
// from x_k-1: no cancellation, however small p gets. Each level keeps its own binary exponent
// (x_k = m_k 2^e_k with max m_k in [0.5, 1)), so p keeps its precision below double's range:
// a 5-wide corridor of 1000:1 ends near 2^-3700 (double stops at 2^-1074).
#pragma once

#include <cstdint>
#include <vector>

#include "spott_harmonic_planner/potential_field.h"

namespace spott_harmonic_planner::internal {

class ThinRegionSolver {
 public:
  /// Levels of the free cells (kind kFree) from the goal cells. True when the region is thin
  /// enough for the elimination to cost at most about `budget_per_cell` operations per unknown
  /// (and no level exceeds kMaxLevel cells).
  bool Analyze(int nx, int ny, const std::vector<FieldCell>& kind,
               const std::vector<std::size_t>& goal_cells, Stencil stencil,
               double budget_per_cell = 400.0);
  /// Solves (after a successful Analyze): p = mantissa[i] * 2^exponent[i] on the unknowns;
  /// other cells are not written.
  void Solve(std::vector<double>& mantissa, std::vector<std::int32_t>& exponent);
  std::size_t unknowns() const { return unknowns_; }

  static constexpr int kMaxLevel = 24;

 private:
  double Coupling(int dx, int dy) const;  // -a(i, j) for neighbours (dx, dy)

  int nx_ = 0, ny_ = 0;
  Stencil stencil_ = Stencil::kFivePoint;
  std::vector<std::int32_t> level_of_;      // per cell: level (0 = goal), -1 elsewhere
  std::vector<std::int32_t> position_;      // per cell: index within its level
  std::vector<std::uint32_t> order_;        // goal cells, then the unknowns level by level
  std::vector<std::uint32_t> level_start_;  // level k: order_[level_start_[k] .. [k + 1])
  std::size_t unknowns_ = 0;
  // Per level k >= 1: G_k = -S_k^-1 A_k,k-1 (size s_k x s_k-1, row-major) and, for level 1,
  // S_1's Cholesky factor.
  std::vector<double> g_;
  std::vector<std::size_t> g_start_;
  std::vector<double> s1_factor_;
  std::vector<double> work_a_, work_b_, work_x_, correction_;
  struct Link {
    std::int8_t dlevel;  // the neighbour's level minus this cell's: -1, 0 or +1
    std::uint8_t pos;    // its index within its level
    double c;            // the coupling (-a(i, j))
  };
  std::vector<std::uint32_t> link_start_;  // per entry of order_
  std::vector<Link> links_;
};

}  // namespace spott_harmonic_planner::internal
