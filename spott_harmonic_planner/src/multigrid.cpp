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
  explicit MultigridSolver(const SolverOptions& o) : options_(o) {}

  void Setup(const GridMask& mask) override {
    CheckMask(mask);
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
    for (std::size_t l = 1; l < levels_.size(); ++l) {
      levels_[l].u.assign(levels_[l].free.size(), 0.0);
      levels_[l].f.assign(levels_[l].free.size(), 0.0);
    }
  }

  void Iterate(double* u) override { Cycle(0, u, nullptr); }

  SolverKind kind() const override { return SolverKind::kMultigrid; }
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

  void Smooth(const Level& level, double* u, const double* f, int sweeps) {
    const int colours = kernels::Colours(options_.stencil);
    for (int s = 0; s < sweeps; ++s) {
      for (int c = 0; c < colours; ++c) {
        kernels::ColourPass(options_.stencil, level.nx, level.ny, u, f, level.weight.data(), c);
      }
    }
  }

  void Cycle(std::size_t l, double* u, const double* f) {
    Level& level = levels_[l];
    if (l + 1 == levels_.size()) {
      // Coarsest level: a few cells; Gauss-Seidel sweeps proportional to its size solve it.
      Smooth(level, u, f, 2 * (level.nx + level.ny));
      return;
    }
    Smooth(level, u, f, options_.pre_smoothing);
    kernels::Residual(options_.stencil, level.nx, level.ny, u, f, level.free.data(),
                      level.r.data());
    Level& coarse = levels_[l + 1];
    Restrict(level, coarse);
    std::fill(coarse.u.begin(), coarse.u.end(), 0.0);
    Cycle(l + 1, coarse.u.data(), coarse.f.data());
    Prolongate(coarse, level, u);
    Smooth(level, u, f, options_.post_smoothing);
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
  std::vector<Level> levels_;
};

}  // namespace

std::unique_ptr<IterativeSolver> MakeMultigridSolver(const SolverOptions& options) {
  return std::make_unique<MultigridSolver>(options);
}

}  // namespace spott_harmonic_planner::internal
