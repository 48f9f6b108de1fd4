// Iteration kernels for the discrete Laplace equation of SPOTT's local planner (III.D.1): a
// Dirichlet problem on a rectangular grid, solved in place. Every cell of the grid is either an
// unknown ("free") or holds a fixed (Dirichlet) value; the outer ring of the grid must be fixed.
//
// Stencils (both normalized so that a free cell equals the weighted mean of its neighbours):
//   5-point:  u = (N + S + E + W) / 4
//   9-point (van de Vooren): u = [4 (N + S + E + W) + (NE + NW + SE + SW)] / 20
//
// Solvers: Gauss-Seidel with successive over-relaxation in red-black order (four colours for the
// 9-point stencil, whose diagonal neighbours would share a colour otherwise); alternating-
// direction line relaxation (x lines then y lines, each line solved exactly); Galerkin
// multigrid over the unknowns (V-cycles with colour Gauss-Seidel smoothers; src/hierarchy.h);
// and conjugate gradients preconditioned by one such V-cycle in single precision, started by
// full multigrid (multigrid_cg, the default). All are iterations on the same equations and
// converge to the same discrete solution.
//
// Not thread-safe: one solver per thread. Grids are row-major, index = y * width + x.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace spott_harmonic_planner {

enum class Stencil { kFivePoint, kNinePoint };
enum class SolverKind { kSorRedBlack, kAdi, kMultigrid, kMultigridCg };

const char* ToString(Stencil stencil);
const char* ToString(SolverKind kind);
std::optional<Stencil> ParseStencil(const std::string& text);  ///< five_point | nine_point
/// sor_red_black | adi | multigrid | multigrid_cg
std::optional<SolverKind> ParseSolverKind(const std::string& text);

struct SolverOptions {
  SolverKind kind = SolverKind::kMultigridCg;  ///< The node's default too.
  Stencil stencil = Stencil::kFivePoint;
  /// Over-relaxation factor of SOR and of the ADI line relaxation, in (0, 2); 0 = the optimal
  /// value for the grid's rectangle (Young's formula with the Jacobi spectral radius).
  double omega = 0.0;
  int pre_smoothing = 2;   ///< Multigrid: colour Gauss-Seidel sweeps before the coarse correction.
  int post_smoothing = 2;  ///< Multigrid: sweeps after it.
};

/// Every violated constraint, each naming its parameter. Empty when valid.
std::vector<std::string> ValidateSolverOptions(const SolverOptions& options);

/// A grid's unknowns: free[i] != 0 marks an unknown; the outer ring must be 0.
struct GridMask {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> free;
};

/// Jacobi spectral radius of the stencil on a width x height rectangle with a fixed ring.
double JacobiSpectralRadius(Stencil stencil, int width, int height);
/// Young's optimal SOR factor 2 / (1 + sqrt(1 - rho^2)) for that rectangle.
double OptimalOmega(Stencil stencil, int width, int height);

/// Max-norm of the normalized residual (weighted neighbour mean - u) over the free cells.
double MaxResidual(Stencil stencil, const GridMask& mask, const double* u);

class IterativeSolver {
 public:
  virtual ~IterativeSolver() = default;
  /// Prepares for a grid. Throws std::invalid_argument when the outer ring is not fixed.
  virtual void Setup(const GridMask& mask) = 0;
  /// One iteration in place on `u` (width x height): a colour sweep of every cell (SOR), an x-line
  /// pass and a y-line pass (ADI), or one V-cycle (multigrid). Fixed cells are never written.
  virtual void Iterate(double* u) = 0;
  virtual SolverKind kind() const = 0;
  virtual Stencil stencil() const = 0;
  /// Relaxation factor in use (1 for multigrid, whose smoother is plain Gauss-Seidel).
  virtual double omega() const = 0;
  /// `u` was changed from outside (a cold start, values clamped): solvers that keep state
  /// between iterations (conjugate gradients) start over from it.
  virtual void Restart() {}
  /// Sets the unknowns of `u` to a solver's own initial guess from the fixed values alone (the
  /// multigrid solvers: full multigrid). False (u unchanged) when the solver has none. After
  /// Setup().
  virtual bool InitialGuess(double* u) {
    (void)u;
    return false;
  }
  /// Adds the solver's own estimate of the correction for the residual of `u` (the multigrid
  /// solvers: full multigrid on the residual equation): a warm start after the equations
  /// changed. False (u unchanged) when the solver has none. After Setup().
  virtual bool CorrectionGuess(double* u) {
    (void)u;
    return false;
  }
  /// The relative norm of LastResidual() takes |r_i| against max(u_i, floor) (0: u_i alone).
  virtual void SetRelativeFloor(double floor) { (void)floor; }
  /// Max-norms (absolute, and relative to each cell's value) of the residual after the last
  /// Iterate(), when the solver tracks them on the way (conjugate gradients); false otherwise.
  virtual bool LastResidual(double* absolute, double* relative) const {
    (void)absolute;
    (void)relative;
    return false;
  }
};

/// Throws std::invalid_argument when `options` are invalid.
std::unique_ptr<IterativeSolver> MakeSolver(const SolverOptions& options);

void CheckMask(const GridMask& mask);  ///< Throws std::invalid_argument on a bad mask.

}  // namespace spott_harmonic_planner
