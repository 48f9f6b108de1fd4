// Galerkin multigrid hierarchy for the Dirichlet problem of solver.h (private to the library).
//
// Level 0 is the window's grid with its constant normalized stencil (A = I - M, M the 5- or
// 9-point neighbour mean) on the free cells. Coarse level l + 1 has a node on every second node
// of level l (vertex coarsening, the outer ring stays fixed); its operator is the Galerkin
// product A_{l+1} = P^T A_l P with P the bilinear interpolation restricted to the unknowns of
// level l. A coarse node is an unknown when its interpolation touches an unknown, so a corridor
// one cell wide stays on every level (its coarse nodes straddle the walls), and P^T A P is the
// energy-optimal coarse correction whatever the walls do: no level empties, no coupling of rooms
// that the fine grid separates can make a cycle diverge (the coarse correction is an A-orthogonal
// projection). Coarse operators are 9-point (stored symmetric: diagonal, E, N, NE, NW),
// formed by the separable product (x, then y) over the coarse unknowns. The coarsest level (at most
// kCoarsestUnknowns) is solved exactly (dense Cholesky). Work is done on the unknowns only (runs of
// active cells per row): a corridor in a large window costs its own cells.
//
// Smoothers: red-black Gauss-Seidel for the 5-point level 0, four-colour Gauss-Seidel (x and y
// parity) for 9-point operators; backwards after the coarse correction, so the V-cycle is
// symmetric (a preconditioner for conjugate gradients). No allocation after Build().
#pragma once

#include <cstdint>
#include <vector>

#include "mg_kernels.h"
#include "spott_harmonic_planner/solver.h"

namespace spott_harmonic_planner::internal {

template <typename T>
class Hierarchy {
 public:
  static constexpr int kCoarsestUnknowns = 40;

  /// Builds every level for `mask` (its outer ring must be fixed).
  void Build(const GridMask& mask, Stencil stencil);
  int levels() const { return static_cast<int>(used_); }
  std::size_t unknowns(int level) const { return levels_[level].unknowns; }
  const std::vector<Run>& runs() const { return levels_[0].runs; }
  /// Level 0: 1 on unknowns, 0 on fixed cells.
  const T* mask() const { return levels_[0].mask.data(); }

  /// e = one V-cycle(pre, post) on A e = r from e = 0 (level 0 arrays, fixed cells of e stay 0).
  void VCycle(const T* r, T* e, int pre, int post);
  /// e = full multigrid on A e = r (one V-cycle per level after the coarsest solve).
  void FullMultigrid(const T* r, T* e, int pre, int post);
  /// y = A x on the unknowns of level 0 (x is zero on fixed cells); returns x . A x.
  double Apply(const T* x, T* y) const;

 private:
  struct Level {
    int nx = 0, ny = 0;
    std::vector<std::uint8_t> active;
    std::vector<Run> runs;
    std::vector<Run> segs;  // per row: from its first to its last unknown (kernels may span gaps)
    std::vector<T> mask;    // level 0: 1 on unknowns, 0 on fixed cells (for the spanning runs)
    std::size_t unknowns = 0;
    // Symmetric 9-point operator (levels >= 1): a(i,i) = diag, a(i,i+1) = e, a(i,i+nx) = n,
    // a(i,i+nx+1) = ne, a(i,i+nx-1) = nw; zero towards fixed cells.
    std::vector<T> diag, inv_diag, e, n, ne, nw;
    std::vector<T> u, f, r;  // correction, right-hand side, residual (levels >= 1)
    int sx = 2, sy = 2;      // coarsening factors from the finer level (1: not coarsened)
    Stencil9<T> op() const {
      return {diag.data(), inv_diag.data(), e.data(), n.data(), ne.data(), nw.data()};
    }
  };

  void BuildCoarse(std::size_t l);
  void Smooth(std::size_t l, T* u, const T* f, int sweeps, bool backwards) const;
  void Residual(std::size_t l, const T* u, const T* f, T* r) const;
  void Restrict(std::size_t l, const T* r, T* fc) const;    // level l -> l + 1
  void Prolongate(std::size_t l, const T* uc, T* u) const;  // add level l + 1 to l
  void Cycle(std::size_t l, T* u, const T* f, int pre, int post, bool zero_start);
  void CoarsestSolve(T* u, const T* f) const;
  void FirstSweep(T* u, const T* f);  // level 0: the first sweep from u = 0
  void FactorCoarsest();
  double A0(int dx, int dy) const;  // level 0's constant stencil

  Stencil stencil_ = Stencil::kFivePoint;
  std::vector<Level> levels_;  // allocated per grid size; the first used_ are in use
  std::size_t used_ = 0;
  std::vector<Run> previous_runs_;  // level 0's runs of the last build
  std::vector<T> galerkin_rows_;    // BuildCoarse's x-stage rows
  // Coarsest level: dense Cholesky factor (row-major lower triangle) of its unknowns.
  std::vector<int> coarse_index_;  // cell of each coarsest unknown
  std::vector<double> chol_;
  std::vector<double> chol_t_;  // its transpose (row k: column k of the factor)
  mutable std::vector<double> chol_rhs_;
  mutable std::vector<T> tmp_;  // a row of scratch for the kernels
  // Fine-level buffers of the full-multigrid start.
  std::vector<std::vector<T>> fmg_rhs_;
  std::vector<std::vector<Run>> fmg_runs_;
};

extern template class Hierarchy<double>;
extern template class Hierarchy<float>;

}  // namespace spott_harmonic_planner::internal
