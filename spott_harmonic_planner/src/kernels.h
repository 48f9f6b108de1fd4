// Inner loops shared by the solvers (private to the library). All grids are row-major with
// `nx` columns; the outer ring is fixed and never written.
#pragma once

#include <algorithm>
#include <cmath>

#include "spott_harmonic_planner/solver.h"

namespace spott_harmonic_planner::kernels {

/// Weighted neighbour mean of cell i: the right-hand side of the normalized stencil.
inline double Mean5(const double* u, int i, int nx) {
  return 0.25 * ((u[i - 1] + u[i + 1]) + (u[i - nx] + u[i + nx]));
}
inline double Mean9(const double* u, int i, int nx) {
  return 0.2 * ((u[i - 1] + u[i + 1]) + (u[i - nx] + u[i + nx])) +
         0.05 * ((u[i - nx - 1] + u[i - nx + 1]) + (u[i + nx - 1] + u[i + nx + 1]));
}
inline double Mean(Stencil s, const double* u, int i, int nx) {
  return s == Stencil::kFivePoint ? Mean5(u, i, nx) : Mean9(u, i, nx);
}

/// Number of colours of the Gauss-Seidel ordering: red-black for the 5-point stencil, four
/// colours (x parity, y parity) for the 9-point one, so that no cell's neighbour shares its
/// colour and every colour pass is a true Gauss-Seidel step.
inline int Colours(Stencil s) { return s == Stencil::kFivePoint ? 2 : 4; }

/// One over-relaxed Gauss-Seidel pass over the cells of `colour`:
/// u += w * (mean + f - u), with w[i] = omega on free cells and 0 on fixed ones. `f` may be null
/// (Laplace's equation).
void ColourPass(Stencil s, int nx, int ny, double* u, const double* f, const double* w, int colour);

/// Residual r = f + mean - u on free cells (w[i] != 0 marks them), 0 elsewhere. Returns the
/// max-norm. `r` may be null (norm only).
double Residual(Stencil s, int nx, int ny, const double* u, const double* f,
                const std::uint8_t* free, double* r);

}  // namespace spott_harmonic_planner::kernels
