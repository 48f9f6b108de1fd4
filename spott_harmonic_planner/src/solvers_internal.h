// Factories of the solvers defined in their own files (private to the library).
#pragma once

#include <memory>

#include "spott_harmonic_planner/solver.h"

namespace spott_harmonic_planner::internal {

std::unique_ptr<IterativeSolver> MakeAdiSolver(const SolverOptions& options);
std::unique_ptr<IterativeSolver> MakeMultigridSolver(const SolverOptions& options);

/// Optimal over-relaxation of line Gauss-Seidel on a rectangle (the larger of the x-line and
/// y-line line-Jacobi spectral radii in Young's formula).
double OptimalLineOmega(Stencil stencil, int width, int height);

}  // namespace spott_harmonic_planner::internal
