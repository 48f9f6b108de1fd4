// Alternating-direction line relaxation (SPOTT III.D.1, "Alternating Direction" with
// successive over-relaxation): every maximal run of free cells along a row is solved exactly
// (a tridiagonal system, Thomas algorithm) with the neighbouring rows held at their latest
// values, rows in Gauss-Seidel order; then the same along columns. Each line solution is
// over-relaxed by omega. With obstacles the x and y operators do not commute, so this is the
// line-relaxation form of ADI rather than Peaceman-Rachford with its parameter sequence.
#include <cmath>
#include <vector>

#include "kernels.h"
#include "solvers_internal.h"

namespace spott_harmonic_planner::internal {

double OptimalLineOmega(Stencil stencil, int width, int height) {
  const double cx = std::cos(M_PI / std::max(2, width - 1));
  const double cy = std::cos(M_PI / std::max(2, height - 1));
  // Line-Jacobi spectral radius: off-line coupling over the line operator's smallest eigenvalue.
  const auto mu = [stencil](double c_along, double c_across) {
    if (stencil == Stencil::kFivePoint) return (0.5 * c_across) / (1.0 - 0.5 * c_along);
    return (0.4 * c_across + 0.2 * c_along * c_across) / (1.0 - 0.4 * c_along);
  };
  const double rho = std::max(mu(cx, cy), mu(cy, cx));
  return 2.0 / (1.0 + std::sqrt(std::max(0.0, 1.0 - rho * rho)));
}

namespace {

class AdiSolver final : public IterativeSolver {
 public:
  explicit AdiSolver(const SolverOptions& o) : options_(o) {
    coupling_ = o.stencil == Stencil::kFivePoint ? 0.25 : 0.2;
  }

  void Setup(const GridMask& mask) override {
    CheckMask(mask);
    mask_ = mask;
    omega_ = options_.omega > 0.0 ? options_.omega
                                  : OptimalLineOmega(options_.stencil, mask.width, mask.height);
    // Thomas coefficients for a run of constant tridiagonal (-c, 1, -c): they depend only on
    // the position in the run, so they are computed once for the longest possible run.
    const int longest = std::max(mask.width, mask.height);
    cprime_.assign(longest, 0.0);
    inv_denominator_.assign(longest, 0.0);
    double previous = 0.0;
    for (int k = 0; k < longest; ++k) {
      const double denominator = 1.0 + coupling_ * previous;  // b - a c'_{k-1}, a = -c
      inv_denominator_[k] = 1.0 / denominator;
      cprime_[k] = -coupling_ * inv_denominator_[k];
      previous = cprime_[k];
    }
    line_rhs_.assign(longest, 0.0);
    line_u_.assign(longest, 0.0);
    line_index_.assign(longest, 0);
  }

  void Iterate(double* u) override {
    const int nx = mask_.width;
    const int ny = mask_.height;
    // x lines, bottom to top.
    for (int y = 1; y < ny - 1; ++y) {
      int x = 1;
      while (x < nx - 1) {
        if (!mask_.free[Index(x, y)]) {
          ++x;
          continue;
        }
        int n = 0;
        for (; x < nx - 1 && mask_.free[Index(x, y)]; ++x) line_index_[n++] = Index(x, y);
        SolveLine(u, n, 1, nx);
      }
    }
    // y lines, left to right.
    for (int x = 1; x < nx - 1; ++x) {
      int y = 1;
      while (y < ny - 1) {
        if (!mask_.free[Index(x, y)]) {
          ++y;
          continue;
        }
        int n = 0;
        for (; y < ny - 1 && mask_.free[Index(x, y)]; ++y) line_index_[n++] = Index(x, y);
        SolveLine(u, n, nx, 1);
      }
    }
  }

  SolverKind kind() const override { return SolverKind::kAdi; }
  Stencil stencil() const override { return options_.stencil; }
  double omega() const override { return omega_; }

 private:
  std::ptrdiff_t Index(int x, int y) const {
    return static_cast<std::ptrdiff_t>(y) * mask_.width + x;
  }

  // Solves the run line_index_[0..n) whose cells are `along` apart; `across` steps to the
  // neighbouring lines.
  void SolveLine(double* u, int n, std::ptrdiff_t along, std::ptrdiff_t across) {
    const double c = coupling_;
    for (int k = 0; k < n; ++k) {
      const std::ptrdiff_t i = line_index_[k];
      double d;
      if (options_.stencil == Stencil::kFivePoint) {
        d = 0.25 * (u[i - across] + u[i + across]);
      } else {
        d = 0.2 * (u[i - across] + u[i + across]) +
            0.05 * ((u[i - across - along] + u[i - across + along]) +
                    (u[i + across - along] + u[i + across + along]));
      }
      if (k == 0) d += c * u[i - along];      // fixed cell before the run
      if (k == n - 1) d += c * u[i + along];  // fixed cell after it
      line_rhs_[k] = d;
    }
    // Forward elimination, then back substitution.
    double dprev = 0.0;
    for (int k = 0; k < n; ++k) {
      dprev = (line_rhs_[k] + c * dprev) * inv_denominator_[k];
      line_u_[k] = dprev;
    }
    for (int k = n - 2; k >= 0; --k) line_u_[k] -= cprime_[k] * line_u_[k + 1];
    for (int k = 0; k < n; ++k) {
      double& v = u[line_index_[k]];
      v += omega_ * (line_u_[k] - v);
    }
  }

  SolverOptions options_;
  GridMask mask_;
  double coupling_ = 0.25;
  double omega_ = 1.0;
  std::vector<double> cprime_, inv_denominator_, line_rhs_, line_u_;
  std::vector<std::ptrdiff_t> line_index_;
};

}  // namespace

std::unique_ptr<IterativeSolver> MakeAdiSolver(const SolverOptions& options) {
  return std::make_unique<AdiSolver>(options);
}

}  // namespace spott_harmonic_planner::internal
