#include "spott_harmonic_planner/solver.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "kernels.h"
#include "solvers_internal.h"

namespace spott_harmonic_planner {

const char* ToString(Stencil stencil) {
  return stencil == Stencil::kFivePoint ? "five_point" : "nine_point";
}

const char* ToString(SolverKind kind) {
  switch (kind) {
    case SolverKind::kSorRedBlack:
      return "sor_red_black";
    case SolverKind::kAdi:
      return "adi";
    case SolverKind::kMultigrid:
      return "multigrid";
  }
  return "?";
}

std::optional<Stencil> ParseStencil(const std::string& text) {
  if (text == "five_point") return Stencil::kFivePoint;
  if (text == "nine_point") return Stencil::kNinePoint;
  return std::nullopt;
}

std::optional<SolverKind> ParseSolverKind(const std::string& text) {
  if (text == "sor_red_black") return SolverKind::kSorRedBlack;
  if (text == "adi") return SolverKind::kAdi;
  if (text == "multigrid") return SolverKind::kMultigrid;
  return std::nullopt;
}

std::vector<std::string> ValidateSolverOptions(const SolverOptions& o) {
  std::vector<std::string> v;
  if (!(o.omega == 0.0 || (o.omega > 0.0 && o.omega < 2.0))) {
    std::ostringstream s;
    s << "omega must be 0 (optimal) or in (0, 2) (got " << o.omega << ")";
    v.push_back(s.str());
  }
  if (o.pre_smoothing < 0 || o.pre_smoothing > 16) {
    v.push_back("pre_smoothing must be in [0, 16] (got " + std::to_string(o.pre_smoothing) + ")");
  }
  if (o.post_smoothing < 0 || o.post_smoothing > 16) {
    v.push_back("post_smoothing must be in [0, 16] (got " + std::to_string(o.post_smoothing) + ")");
  }
  if (o.pre_smoothing + o.post_smoothing == 0) {
    v.push_back("pre_smoothing + post_smoothing must be >= 1 (multigrid needs a smoother)");
  }
  return v;
}

double JacobiSpectralRadius(Stencil stencil, int width, int height) {
  // Interior of n unknowns between two fixed cells: the slowest mode is sin(pi i / (n + 1)).
  const double cx = std::cos(M_PI / std::max(2, width - 1));
  const double cy = std::cos(M_PI / std::max(2, height - 1));
  if (stencil == Stencil::kFivePoint) return 0.5 * (cx + cy);
  return (2.0 * cx + 2.0 * cy + cx * cy) / 5.0;
}

double OptimalOmega(Stencil stencil, int width, int height) {
  const double rho = JacobiSpectralRadius(stencil, width, height);
  return 2.0 / (1.0 + std::sqrt(std::max(0.0, 1.0 - rho * rho)));
}

void CheckMask(const GridMask& mask) {
  if (mask.width < 3 || mask.height < 3) {
    throw std::invalid_argument("harmonic solver: the grid needs at least 3 x 3 cells (got " +
                                std::to_string(mask.width) + " x " + std::to_string(mask.height) +
                                ")");
  }
  if (mask.free.size() != static_cast<std::size_t>(mask.width) * mask.height) {
    throw std::invalid_argument("harmonic solver: mask size does not match width x height");
  }
  for (int x = 0; x < mask.width; ++x) {
    if (mask.free[x] || mask.free[static_cast<std::size_t>(mask.height - 1) * mask.width + x]) {
      throw std::invalid_argument("harmonic solver: the outer ring of the grid must be fixed");
    }
  }
  for (int y = 0; y < mask.height; ++y) {
    if (mask.free[static_cast<std::size_t>(y) * mask.width] ||
        mask.free[static_cast<std::size_t>(y) * mask.width + mask.width - 1]) {
      throw std::invalid_argument("harmonic solver: the outer ring of the grid must be fixed");
    }
  }
}

double MaxResidual(Stencil stencil, const GridMask& mask, const double* u) {
  return kernels::Residual(stencil, mask.width, mask.height, u, nullptr, mask.free.data(), nullptr);
}

// ---------------------------------------------------------------------------------------------
// Red-black (four-colour for 9 points) Gauss-Seidel with successive over-relaxation.
namespace {

class SorSolver final : public IterativeSolver {
 public:
  explicit SorSolver(const SolverOptions& o) : options_(o) {}

  void Setup(const GridMask& mask) override {
    CheckMask(mask);
    mask_ = mask;
    omega_ = options_.omega > 0.0 ? options_.omega
                                  : OptimalOmega(options_.stencil, mask.width, mask.height);
    weight_.assign(mask.free.size(), 0.0);
    for (std::size_t i = 0; i < weight_.size(); ++i) weight_[i] = mask.free[i] ? omega_ : 0.0;
  }

  void Iterate(double* u) override {
    const int colours = kernels::Colours(options_.stencil);
    for (int c = 0; c < colours; ++c) {
      kernels::ColourPass(options_.stencil, mask_.width, mask_.height, u, nullptr, weight_.data(),
                          c);
    }
  }

  SolverKind kind() const override { return SolverKind::kSorRedBlack; }
  Stencil stencil() const override { return options_.stencil; }
  double omega() const override { return omega_; }

 private:
  SolverOptions options_;
  GridMask mask_;
  double omega_ = 1.0;
  std::vector<double> weight_;
};

}  // namespace

std::unique_ptr<IterativeSolver> MakeSolver(const SolverOptions& options) {
  const auto violations = ValidateSolverOptions(options);
  if (!violations.empty()) {
    std::string text = "invalid solver options:";
    for (const auto& s : violations) text += " " + s + ";";
    throw std::invalid_argument(text);
  }
  switch (options.kind) {
    case SolverKind::kSorRedBlack:
      return std::make_unique<SorSolver>(options);
    case SolverKind::kAdi:
      return internal::MakeAdiSolver(options);
    case SolverKind::kMultigrid:
      return internal::MakeMultigridSolver(options);
  }
  throw std::invalid_argument("unknown solver kind");
}

}  // namespace spott_harmonic_planner
