// Geometric multigrid for the Dirichlet problem of solver.h: V-cycles whose smoother is the
// colour-ordered Gauss-Seidel of kernels.h. Vertex coarsening: coarse cell (I, J) sits on fine
// cell (2I, 2J) and is an unknown when its 3 x 3 fine footprint is; full-weighting restriction of
// the residual, bilinear prolongation of the correction (never into fixed cells). The coarse
// problem is the residual equation with homogeneous Dirichlet values: with the normalized
// stencil (mean - u = h^2/4 Laplacian), doubling h multiplies the right-hand side by 4.
// Passages narrower than three cells close on coarse levels; the smoother alone carries the
// correction through them, so the cycle stays convergent but slows down (measured in bench/).
#include <algorithm>
#include <cmath>
#include <vector>

#include "kernels.h"
#include "solvers_internal.h"

namespace spott_harmonic_planner::internal {

namespace {

struct Level {
  int nx = 0;
  int ny = 0;
  std::vector<std::uint8_t> free;
  std::vector<double> weight;  // smoother weight: 1 on unknowns, 0 on fixed cells
  std::vector<double> u;       // correction (coarse levels only)
  std::vector<double> f;       // right-hand side (coarse levels only)
  std::vector<double> r;       // residual
  std::size_t unknowns = 0;
};

class MultigridSolver final : public IterativeSolver {
 public:
  explicit MultigridSolver(const SolverOptions& o)
      : options_(o), cg_(o.kind == SolverKind::kMultigridCg) {}

  void Setup(const GridMask& mask) override {
    CheckMask(mask);
    cg_started_ = false;
    levels_.clear();
    levels_.push_back(MakeLevel(mask.width, mask.height, mask.free));
    while (true) {
      const Level& fine = levels_.back();
      const int cx = fine.nx / 2 + 1;
      const int cy = fine.ny / 2 + 1;
      if (cx < 3 || cy < 3 || cx >= fine.nx || cy >= fine.ny) break;
      std::vector<std::uint8_t> cfree(static_cast<std::size_t>(cx) * cy, 0);
      for (int y = 1; y < cy - 1; ++y) {
        for (int x = 1; x < cx - 1; ++x) {
          // Conservative coarsening: an unknown only when its whole 3 x 3 fine footprint is,
          // so walls thicken on coarse levels but never vanish (a vanished wall would couple
          // rooms the fine grid separates, and the cycle diverges).
          bool all_free = true;
          for (int dy = -1; dy <= 1 && all_free; ++dy) {
            for (int dx = -1; dx <= 1 && all_free; ++dx) {
              all_free = fine.free[static_cast<std::size_t>(2 * y + dy) * fine.nx + 2 * x + dx];
            }
          }
          cfree[static_cast<std::size_t>(y) * cx + x] = all_free ? 1 : 0;
        }
      }
      Level coarse = MakeLevel(cx, cy, cfree);
      if (coarse.unknowns == 0) break;
      levels_.push_back(std::move(coarse));
      if (cx <= 5 || cy <= 5) break;
    }
    const Level& last = levels_.back();
    const double omega = OptimalOmega(options_.stencil, last.nx, last.ny);
    coarsest_weight_.assign(last.free.size(), 0.0);
    for (std::size_t i = 0; i < last.free.size(); ++i) {
      coarsest_weight_[i] = last.free[i] ? omega : 0.0;
    }
    for (std::size_t l = 1; l < levels_.size(); ++l) {
      levels_[l].u.assign(levels_[l].free.size(), 0.0);
      levels_[l].f.assign(levels_[l].free.size(), 0.0);
    }
  }

  void Iterate(double* u) override {
    if (cg_) {
      IterateCg(u);
    } else {
      Cycle(0, u, nullptr);
    }
  }

  void Restart() override { cg_started_ = false; }

  SolverKind kind() const override { return options_.kind; }
  Stencil stencil() const override { return options_.stencil; }
  double omega() const override { return 1.0; }
  int levels() const { return static_cast<int>(levels_.size()); }

 private:
  static Level MakeLevel(int nx, int ny, std::vector<std::uint8_t> free) {
    Level level;
    level.nx = nx;
    level.ny = ny;
    level.free = std::move(free);
    level.weight.assign(level.free.size(), 0.0);
    for (std::size_t i = 0; i < level.free.size(); ++i) {
      level.weight[i] = level.free[i] ? 1.0 : 0.0;
      level.unknowns += level.free[i] ? 1 : 0;
    }
    level.r.assign(level.free.size(), 0.0);
    return level;
  }

  void Smooth(const Level& level, double* u, const double* f, int sweeps, bool backwards) {
    const int colours = kernels::Colours(options_.stencil);
    for (int s = 0; s < sweeps; ++s) {
      for (int k = 0; k < colours; ++k) {
        const int c = backwards ? colours - 1 - k : k;
        kernels::ColourPass(options_.stencil, level.nx, level.ny, u, f, level.weight.data(), c);
      }
    }
  }

  // Conjugate gradients on A u = b (A = I - M, M the stencil's neighbour mean on the unknowns;
  // A is symmetric positive definite), preconditioned by one V-cycle from zero. The residual
  // b - A u is the normalized residual mean - u of kernels::Residual.
  void IterateCg(double* u) {
    const Level& fine = levels_[0];
    const std::size_t n = fine.free.size();
    const auto dot = [n](const std::vector<double>& a, const std::vector<double>& b) {
      double s = 0.0;
      for (std::size_t i = 0; i < n; ++i) s += a[i] * b[i];
      return s;
    };
    if (!cg_started_) {
      cg_r_.assign(n, 0.0);
      cg_z_.assign(n, 0.0);
      cg_q_.assign(n, 0.0);
      kernels::Residual(options_.stencil, fine.nx, fine.ny, u, nullptr, fine.free.data(),
                        cg_r_.data());
      Precondition();
      cg_d_ = cg_z_;
      cg_rho_ = dot(cg_r_, cg_z_);
      cg_started_ = true;
    }
    if (!(cg_rho_ > 0.0)) return;  // solved to the last bit
    // q = A d = d - M d; kernels::Residual gives M d - d (d is zero on fixed cells).
    kernels::Residual(options_.stencil, fine.nx, fine.ny, cg_d_.data(), nullptr, fine.free.data(),
                      cg_q_.data());
    for (std::size_t i = 0; i < n; ++i) cg_q_[i] = -cg_q_[i];
    const double dq = dot(cg_d_, cg_q_);
    if (!(dq > 0.0)) return;
    const double alpha = cg_rho_ / dq;
    for (std::size_t i = 0; i < n; ++i) {
      u[i] += alpha * cg_d_[i];
      cg_r_[i] -= alpha * cg_q_[i];
    }
    Precondition();
    const double rho = dot(cg_r_, cg_z_);
    const double beta = rho / cg_rho_;
    cg_rho_ = rho;
    for (std::size_t i = 0; i < n; ++i) cg_d_[i] = cg_z_[i] + beta * cg_d_[i];
  }

  // z = one V-cycle on A z = r from z = 0.
  void Precondition() {
    std::fill(cg_z_.begin(), cg_z_.end(), 0.0);
    Cycle(0, cg_z_.data(), cg_r_.data());
  }

  void Cycle(std::size_t l, double* u, const double* f) {
    Level& level = levels_[l];
    if (l + 1 == levels_.size()) {
      // Coarsest level (small, or the last with unknowns: conservative coarsening can empty a
      // level early): over-relaxed Gauss-Seidel with Young's optimal omega for its rectangle,
      // about half its side in sweeps (error reduction ~ e^-pi per side length).
      const int colours = kernels::Colours(options_.stencil);
      const int sweeps = std::max(4, (level.nx + level.ny) / 2);
      for (int s = 0; s < sweeps; ++s) {
        for (int c = 0; c < colours; ++c) {
          kernels::ColourPass(options_.stencil, level.nx, level.ny, u, f, coarsest_weight_.data(),
                              c);
        }
      }
      return;
    }
    Smooth(level, u, f, options_.pre_smoothing, false);
    kernels::Residual(options_.stencil, level.nx, level.ny, u, f, level.free.data(),
                      level.r.data());
    Level& coarse = levels_[l + 1];
    Restrict(level, coarse);
    std::fill(coarse.u.begin(), coarse.u.end(), 0.0);
    Cycle(l + 1, coarse.u.data(), coarse.f.data());
    Prolongate(coarse, level, u);
    Smooth(level, u, f, options_.post_smoothing, /*backwards=*/cg_);  // symmetric for CG
  }

  // Full weighting (1/4 centre, 1/8 edges, 1/16 corners) of the fine residual, times 4.
  static void Restrict(const Level& fine, Level& coarse) {
    const int fx = fine.nx;
    const double* r = fine.r.data();
    for (int y = 0; y < coarse.ny; ++y) {
      for (int x = 0; x < coarse.nx; ++x) {
        const std::size_t ci = static_cast<std::size_t>(y) * coarse.nx + x;
        if (!coarse.free[ci]) {
          coarse.f[ci] = 0.0;
          continue;
        }
        const std::size_t i = static_cast<std::size_t>(2 * y) * fx + 2 * x;
        const double centre = r[i];
        const double edges = r[i - 1] + r[i + 1] + r[i - fx] + r[i + fx];
        const double corners = r[i - fx - 1] + r[i - fx + 1] + r[i + fx - 1] + r[i + fx + 1];
        coarse.f[ci] = 4.0 * (0.25 * centre + 0.125 * edges + 0.0625 * corners);
      }
    }
  }

  // Bilinear interpolation of the coarse correction, added to the fine unknowns.
  static void Prolongate(const Level& coarse, const Level& fine, double* u) {
    const int cx = coarse.nx;
    const double* e = coarse.u.data();
    for (int y = 1; y < fine.ny - 1; ++y) {
      const int y0 = y / 2;
      const int y1 = (y + 1) / 2;
      for (int x = 1; x < fine.nx - 1; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * fine.nx + x;
        if (!fine.free[i]) continue;
        const int x0 = x / 2;
        const int x1 = (x + 1) / 2;
        const double v =
            e[static_cast<std::size_t>(y0) * cx + x0] + e[static_cast<std::size_t>(y0) * cx + x1] +
            e[static_cast<std::size_t>(y1) * cx + x0] + e[static_cast<std::size_t>(y1) * cx + x1];
        u[i] += 0.25 * v;
      }
    }
  }

  SolverOptions options_;
  bool cg_ = false;
  std::vector<Level> levels_;
  std::vector<double> coarsest_weight_;
  bool cg_started_ = false;
  double cg_rho_ = 0.0;
  std::vector<double> cg_r_, cg_z_, cg_d_, cg_q_;
};

}  // namespace

std::unique_ptr<IterativeSolver> MakeMultigridSolver(const SolverOptions& options) {
  return std::make_unique<MultigridSolver>(options);
}

}  // namespace spott_harmonic_planner::internal
