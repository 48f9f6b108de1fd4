// Multigrid solvers of solver.h on the Galerkin hierarchy of hierarchy.h:
//   multigrid     one V(2,2)-cycle per iteration on the residual equation (a stationary
//                 iteration);
//   multigrid_cg  conjugate gradients preconditioned by one symmetric V(1,1)-cycle, started by
//                 full multigrid. The preconditioner runs in single precision (its result only
//                 has to be a good correction; the outer iteration, its residual and the field stay
//                 in double), so it moves half the bytes and vectorizes twice as wide.
// Both work on the unknowns only (runs of free cells) and allocate nothing per iteration.
#include <algorithm>
#include <cmath>
#include <vector>

#include "hierarchy.h"
#include "solvers_internal.h"

namespace spott_harmonic_planner::internal {

namespace {

class MultigridSolver final : public IterativeSolver {
 public:
  explicit MultigridSolver(const SolverOptions& o)
      : options_(o), cg_(o.kind == SolverKind::kMultigridCg) {}

  void Setup(const GridMask& mask) override {
    CheckMask(mask);
    const std::size_t n = mask.free.size();
    const bool same_size = nx_ == mask.width && ny_ == mask.height && r_.size() == n;
    nx_ = mask.width;
    ny_ = mask.height;
    // Vectors are allocated per grid size; a new mask clears only what the last one used.
    if (!same_size) {
      if (cg_) {
        for (auto* v : {&r32_, &z32_, &z32_old_}) v->assign(n, 0.0f);
        for (auto* v : {&r_, &d_, &q_}) v->assign(n, 0.0);  // z_: the double cycle's only
      } else {
        for (auto* v : {&r_, &z_}) v->assign(n, 0.0);
      }
    } else {
      for (const Run& run : runs()) {
        const std::size_t b = static_cast<std::size_t>(run.y) * nx_;
        for (auto* v : {&r32_, &z32_, &z32_old_}) {
          if (!v->empty()) std::fill(v->begin() + b + run.x0, v->begin() + b + run.x1, 0.0f);
        }
        for (auto* v : {&r_, &z_, &d_, &q_}) {
          if (!v->empty()) std::fill(v->begin() + b + run.x0, v->begin() + b + run.x1, 0.0);
        }
      }
    }
    if (cg_) {
      single_.Build(mask, options_.stencil);
      // The conjugate-gradient passes run over one span from the first unknown to the last
      // (masked) when the fixed cells inside it cost less than a loop start per run (about 16
      // cells' work, measured: short rows, a mostly free window).
      const auto& rs = single_.runs();
      cg_runs_ = rs;
      cg_mask_ = nullptr;
      if (!rs.empty()) {
        const long first = static_cast<long>(rs.front().y) * nx_ + rs.front().x0;
        const long last = static_cast<long>(rs.back().y) * nx_ + rs.back().x1;
        const long fixed = last - first - static_cast<long>(single_.unknowns(0));
        if (fixed < 16 * static_cast<long>(rs.size())) {
          cg_runs_.assign(1, Run{0, static_cast<int>(first), static_cast<int>(last)});
          cg_mask_ = single_.mask();
        }
      }
    } else {
      double_.Build(mask, options_.stencil);
    }
    cg_started_ = false;
  }

  void Iterate(double* u) override {
    if (cg_) {
      IterateCg(u);
      return;
    }
    Residual(u, r_.data());
    double_.VCycle(r_.data(), z_.data(), options_.pre_smoothing, options_.post_smoothing);
    for (const Run& run : double_.runs()) {
      const std::size_t b = static_cast<std::size_t>(run.y) * nx_;
      for (int x = run.x0; x < run.x1; ++x) u[b + x] += z_[b + x];
    }
  }

  bool InitialGuess(double* u) override {
    const auto& runs = cg_ ? single_.runs() : double_.runs();
    for (const Run& run : runs) {
      const std::size_t b = static_cast<std::size_t>(run.y) * nx_;
      std::fill(u + b + run.x0, u + b + run.x1, 0.0);
    }
    if (cg_) {
      ResidualSingle(u, r32_.data());
      single_.FullMultigrid(r32_.data(), z32_.data(), fmg_pre_, fmg_post_);
      for (const Run& run : runs) {
        const std::size_t b = static_cast<std::size_t>(run.y) * nx_;
        for (int x = run.x0; x < run.x1; ++x) u[b + x] = z32_[b + x];
      }
    } else {
      Residual(u, r_.data());
      double_.FullMultigrid(r_.data(), z_.data(), options_.pre_smoothing, options_.post_smoothing);
      for (const Run& run : runs) {
        const std::size_t b = static_cast<std::size_t>(run.y) * nx_;
        for (int x = run.x0; x < run.x1; ++x) u[b + x] = z_[b + x];
      }
    }
    cg_started_ = false;
    return true;
  }

  bool CorrectionGuess(double* u) override {
    if (!cg_) return false;
    ResidualSingle(u, r32_.data());
    single_.FullMultigrid(r32_.data(), z32_.data(), fmg_pre_, fmg_post_);
    for (const Run& run : single_.runs()) {
      const std::size_t b = static_cast<std::size_t>(run.y) * nx_;
      for (int x = run.x0; x < run.x1; ++x) u[b + x] += z32_[b + x];
    }
    cg_started_ = false;
    return true;
  }

  void Restart() override { cg_started_ = false; }
  void SetRelativeFloor(double floor) override { floor_ = floor; }

  SolverKind kind() const override { return options_.kind; }
  Stencil stencil() const override { return options_.stencil; }
  double omega() const override { return 1.0; }

 private:
  const std::vector<Run>& runs() const { return cg_ ? single_.runs() : double_.runs(); }

  // r = mean(u) - u on the unknowns (the fixed cells of u hold the Dirichlet values).
  void Residual(const double* u, double* r) const { ResidualInto(u, r); }

  // rs = (float) (mean(u) - u) on the unknowns, in one pass (the full-multigrid start's
  // right-hand side).
  void ResidualSingle(const double* u, float* rs) const { ResidualInto(u, rs); }

  template <typename Out>
  void ResidualInto(const double* u, Out* r) const {
    const bool five = options_.stencil == Stencil::kFivePoint;
    for (const Run& run : runs()) {
      const std::ptrdiff_t base = static_cast<std::ptrdiff_t>(run.y) * nx_;
      const double* __restrict row = u + base;
      const double* __restrict up = row + nx_;
      const double* __restrict down = row - nx_;
      Out* __restrict out = r + base;
      if (five) {
        for (int x = run.x0; x < run.x1; ++x) {
          out[x] =
              static_cast<Out>(0.25 * ((row[x - 1] + row[x + 1]) + (down[x] + up[x])) - row[x]);
        }
      } else {
        for (int x = run.x0; x < run.x1; ++x) {
          out[x] = static_cast<Out>(0.2 * ((row[x - 1] + row[x + 1]) + (down[x] + up[x])) +
                                    0.05 * ((down[x - 1] + down[x + 1]) + (up[x - 1] + up[x + 1])) -
                                    row[x]);
        }
      }
    }
  }

  void ToSingle(const double* a, float* b) const {
    for (const Run& run : runs()) {
      const std::size_t base = static_cast<std::size_t>(run.y) * nx_;
      for (int x = run.x0; x < run.x1; ++x) b[base + x] = static_cast<float>(a[base + x]);
    }
  }

  // Flexible conjugate gradients (Polak-Ribiere beta: the single-precision preconditioner is
  // not exactly symmetric), preconditioned by one V-cycle; three fused passes per iteration
  // besides the cycle, which also track the max-norms of the (recursive) residual.
  void IterateCg(double* u) {
    const auto& rs = cg_runs_;
    const bool nine = options_.stencil == Stencil::kNinePoint;
    if (!cg_started_) {
      norms_ = kernels::TrueResidual(u, r_.data(), r32_.data(), cg_mask_, nx_, rs.data(), rs.size(),
                                     nine, floor_);
      single_.VCycle(r32_.data(), z32_.data(), v_pre_, v_post_);
      double rz_old = 0.0;
      kernels::Dots(r_.data(), z32_.data(), z32_.data(), nx_, rs.data(), rs.size(), &rho_, &rz_old);
      dq_ = kernels::Direction(z32_.data(), d_.data(), q_.data(), cg_mask_, 0.0, nx_, rs.data(),
                               rs.size(), nine);
      cg_started_ = true;
      direction_pending_ = false;
    } else if (direction_pending_) {
      // The next direction from the residual the last update left: computed only now, so the
      // update that meets the tolerance is not followed by a cycle nobody uses.
      std::swap(z32_, z32_old_);
      single_.VCycle(r32_.data(), z32_.data(), v_pre_, v_post_);
      double rz = 0.0, rz_old = 0.0;
      kernels::Dots(r_.data(), z32_.data(), z32_old_.data(), nx_, rs.data(), rs.size(), &rz,
                    &rz_old);
      const double beta = std::max(0.0, (rz - rz_old) / rho_);
      rho_ = rz;
      dq_ = kernels::Direction(z32_.data(), d_.data(), q_.data(), cg_mask_, beta, nx_, rs.data(),
                               rs.size(), nine);
      direction_pending_ = false;
    }
    if (!(rho_ > 0.0) || !(dq_ > 0.0)) return;  // solved to the last bit
    const double alpha = rho_ / dq_;
    norms_ = kernels::Update(u, d_.data(), r_.data(), q_.data(), r32_.data(), alpha, nx_, rs.data(),
                             rs.size(), floor_);
    direction_pending_ = true;
  }

  bool LastResidual(double* absolute, double* relative) const override {
    if (!cg_ || !cg_started_) return false;
    *absolute = norms_.absolute;
    *relative = norms_.relative;
    return true;
  }

  SolverOptions options_;
  bool cg_ = false;
  int nx_ = 0, ny_ = 0;
  Hierarchy<double> double_;
  Hierarchy<float> single_;
  std::vector<double> r_, z_, d_, q_;
  std::vector<float> r32_, z32_, z32_old_;
  std::vector<Run> cg_runs_;        // the runs of unknowns, or one masked span (Setup)
  const float* cg_mask_ = nullptr;  // level 0's mask when cg_runs_ is a span
  kernels::Norms norms_;
  double dq_ = 0.0;
  bool cg_started_ = false;
  bool direction_pending_ = false;  // an update was made; the next direction is not computed
  double rho_ = 0.0;
  double floor_ = 0.0;
  // The preconditioner's cycle: V(1,1), and V(1,1) on each level of the full-multigrid start
  // (V(2,2) halves the iterations but costs as much in the end: measured in bench/).
  static constexpr int fmg_pre_ = 1, fmg_post_ = 1, v_pre_ = 1, v_post_ = 1;
};

}  // namespace

std::unique_ptr<IterativeSolver> MakeMultigridSolver(const SolverOptions& options) {
  return std::make_unique<MultigridSolver>(options);
}

}  // namespace spott_harmonic_planner::internal
