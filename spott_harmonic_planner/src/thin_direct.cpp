#include "thin_direct.h"

#include <algorithm>
#include <cmath>

namespace spott_harmonic_planner::internal {

namespace {
constexpr int kDx[8] = {1, -1, 0, 0, 1, 1, -1, -1};
constexpr int kDy[8] = {0, 0, 1, -1, 1, -1, 1, -1};

// In-place Cholesky of the s x s row-major matrix a (lower triangle used). False when not
// positive definite.
bool Cholesky(double* a, int s) {
  for (int k = 0; k < s; ++k) {
    double d = a[k * s + k];
    for (int p = 0; p < k; ++p) d -= a[k * s + p] * a[k * s + p];
    if (!(d > 0.0)) return false;
    d = std::sqrt(d);
    a[k * s + k] = d;
    for (int i = k + 1; i < s; ++i) {
      double v = a[i * s + k];
      for (int p = 0; p < k; ++p) v -= a[i * s + p] * a[k * s + p];
      a[i * s + k] = v / d;
    }
  }
  return true;
}

// x = (L L^T)^-1 b for one right-hand side held in x (stride `stride` between its entries).
void CholeskySolve(const double* l, int s, double* x, int stride) {
  for (int i = 0; i < s; ++i) {
    double v = x[i * stride];
    for (int p = 0; p < i; ++p) v -= l[i * s + p] * x[p * stride];
    x[i * stride] = v / l[i * s + i];
  }
  for (int i = s - 1; i >= 0; --i) {
    double v = x[i * stride];
    for (int p = i + 1; p < s; ++p) v -= l[p * s + i] * x[p * stride];
    x[i * stride] = v / l[i * s + i];
  }
}
// X = (L L^T)^-1 X for the s x m row-major block X (all columns at once: the inner loops run
// along the rows of X and vectorize).
void CholeskySolveBlock(const double* l, int s, double* x, int m) {
  for (int i = 0; i < s; ++i) {
    double* xi = x + i * m;
    for (int p = 0; p < i; ++p) {
      const double lip = l[i * s + p];
      const double* xp = x + p * m;
      for (int t = 0; t < m; ++t) xi[t] -= lip * xp[t];
    }
    const double inv = 1.0 / l[i * s + i];
    for (int t = 0; t < m; ++t) xi[t] *= inv;
  }
  for (int i = s - 1; i >= 0; --i) {
    double* xi = x + i * m;
    for (int p = i + 1; p < s; ++p) {
      const double lpi = l[p * s + i];
      const double* xp = x + p * m;
      for (int t = 0; t < m; ++t) xi[t] -= lpi * xp[t];
    }
    const double inv = 1.0 / l[i * s + i];
    for (int t = 0; t < m; ++t) xi[t] *= inv;
  }
}
}  // namespace

double ThinRegionSolver::Coupling(int dx, int dy) const {
  const bool straight = dx == 0 || dy == 0;
  if (stencil_ == Stencil::kFivePoint) return straight ? 0.25 : 0.0;
  return straight ? 0.2 : 0.05;
}

bool ThinRegionSolver::Analyze(int nx, int ny, const std::vector<FieldCell>& kind,
                               const std::vector<std::size_t>& goal_cells, Stencil stencil,
                               double budget_per_cell) {
  nx_ = nx;
  ny_ = ny;
  stencil_ = stencil;
  const std::size_t n = static_cast<std::size_t>(nx) * ny;
  // Reset only what the last analysis set (the arrays keep the window's size).
  if (level_of_.size() != n) {
    level_of_.assign(n, -1);
    position_.assign(n, 0);
  } else {
    for (std::uint32_t i : order_) level_of_[i] = -1;
  }
  order_.clear();
  level_start_.clear();
  for (std::size_t i : goal_cells) {
    if (level_of_[i] == 0) continue;
    level_of_[i] = 0;
    order_.push_back(static_cast<std::uint32_t>(i));
  }
  level_start_.push_back(0);
  const int links = stencil == Stencil::kFivePoint ? 4 : 8;
  // Breadth-first levels; level 0 (the goal cells) holds no unknowns.
  std::size_t fb = 0, fe = order_.size();
  double cost = 0.0;
  std::size_t previous = 0;
  for (std::int32_t k = 1; fb < fe; ++k) {
    const std::size_t begin = order_.size();
    level_start_.push_back(static_cast<std::uint32_t>(begin));
    for (std::size_t q = fb; q < fe; ++q) {
      const std::uint32_t i = order_[q];
      const int x = static_cast<int>(i % nx), y = static_cast<int>(i / nx);
      for (int t = 0; t < links; ++t) {
        const int px = x + kDx[t], py = y + kDy[t];
        if (px < 0 || py < 0 || px >= nx || py >= ny) continue;
        const std::size_t j = static_cast<std::size_t>(py) * nx + px;
        if (kind[j] != FieldCell::kFree || level_of_[j] >= 0) continue;
        level_of_[j] = k;
        position_[j] = static_cast<std::int32_t>(order_.size() - begin);
        order_.push_back(static_cast<std::uint32_t>(j));
      }
    }
    const std::size_t size = order_.size() - begin;
    if (size > static_cast<std::size_t>(kMaxLevel)) return false;
    const double s = static_cast<double>(size), sp = static_cast<double>(previous);
    if (k > 1) cost += s * s * s / 3.0 + 2.0 * s * s * sp + s * sp * links;
    previous = size;
    fb = begin;
    fe = order_.size();
  }
  // The last pushed level is empty: level_start_ then ends with the end of order_.
  unknowns_ = order_.size() - level_start_[1];
  if (unknowns_ == 0) return false;
  if (cost > budget_per_cell * static_cast<double>(unknowns_)) return false;
  // Each unknown's couplings: (level offset -1, 0 or +1, position in that level, weight).
  link_start_.assign(order_.size() + 1, 0);
  links_.clear();
  for (std::size_t q = level_start_[1]; q < order_.size(); ++q) {
    link_start_[q] = static_cast<std::uint32_t>(links_.size());
    const std::uint32_t i = order_[q];
    const int x = static_cast<int>(i % nx), y = static_cast<int>(i / nx);
    const int k = level_of_[i];
    for (int t = 0; t < links; ++t) {
      const std::size_t j = static_cast<std::size_t>(y + kDy[t]) * nx + x + kDx[t];
      const int kj = level_of_[j];
      if (kj < 0) continue;  // fixed (obstacle, unreachable): p = 0 there
      links_.push_back({static_cast<std::int8_t>(kj - k), static_cast<std::uint8_t>(position_[j]),
                        Coupling(kDx[t], kDy[t])});
    }
  }
  link_start_[order_.size()] = static_cast<std::uint32_t>(links_.size());
  return true;
}

void ThinRegionSolver::Solve(std::vector<double>& mantissa, std::vector<std::int32_t>& exponent) {
  // Levels 1 .. levels hold unknowns: order_[level_start_[k] .. level_start_[k + 1]).
  const int levels = static_cast<int>(level_start_.size()) - 2;
  const auto size = [this](int k) {
    return static_cast<int>(level_start_[k + 1] - level_start_[k]);
  };
  const auto first = [this](int k) { return static_cast<std::size_t>(level_start_[k]); };
  g_start_.assign(levels + 2, 0);
  for (int k = 2; k <= levels; ++k) {
    g_start_[k + 1] = g_start_[k] + static_cast<std::size_t>(size(k)) * size(k - 1);
  }
  g_.assign(g_start_[levels + 1], 0.0);
  const std::size_t square = static_cast<std::size_t>(kMaxLevel) * kMaxLevel;
  work_a_.resize(square);
  correction_.resize(square);
  double* s_mat = work_a_.data();
  double* corr = correction_.data();
  bool have_correction = false;
  for (int k = levels; k >= 1; --k) {
    const int sk = size(k);
    // S_k = A_kk - C_k,k+1 G_k+1 (the correction was computed with level k + 1).
    for (int q = 0; q < sk * sk; ++q) s_mat[q] = have_correction ? -corr[q] : 0.0;
    for (int a = 0; a < sk; ++a) {
      s_mat[a * sk + a] += 1.0;
      const std::size_t q = first(k) + a;
      for (std::uint32_t l = link_start_[q]; l < link_start_[q + 1]; ++l) {
        if (links_[l].dlevel == 0) s_mat[a * sk + links_[l].pos] -= links_[l].c;
      }
    }
    if (!Cholesky(s_mat, sk)) return;  // cannot happen for an M-matrix (the caller checks)
    if (k == 1) {
      s1_factor_.assign(s_mat, s_mat + sk * sk);
      break;
    }
    // G_k = S_k^-1 C_k,k-1: one column per cell of level k - 1.
    const int sp = size(k - 1);
    double* g = g_.data() + g_start_[k];
    for (int b = 0; b < sp; ++b) {
      const std::size_t q = first(k - 1) + b;
      for (std::uint32_t l = link_start_[q]; l < link_start_[q + 1]; ++l) {
        if (links_[l].dlevel == 1) g[links_[l].pos * sp + b] += links_[l].c;
      }
    }
    CholeskySolveBlock(s_mat, sk, g, sp);
    // correction = C_k-1,k G_k (sp x sp): row b sums G_k's rows of b's neighbours in k.
    std::fill(corr, corr + sp * sp, 0.0);
    for (int b = 0; b < sp; ++b) {
      const std::size_t q = first(k - 1) + b;
      double* row = corr + b * sp;
      for (std::uint32_t l = link_start_[q]; l < link_start_[q + 1]; ++l) {
        if (links_[l].dlevel != 1) continue;
        const double c = links_[l].c;
        const double* grow = g + links_[l].pos * sp;
        for (int t = 0; t < sp; ++t) row[t] += c * grow[t];
      }
    }
    have_correction = true;
  }
  // x_1 = S_1^-1 b_1 (b_1: the goal's value 1 times the coupling to each goal neighbour).
  const int s1 = size(1);
  work_x_.assign(static_cast<std::size_t>(kMaxLevel), 0.0);
  work_b_.assign(static_cast<std::size_t>(kMaxLevel), 0.0);
  for (int a = 0; a < s1; ++a) {
    const std::size_t q = first(1) + a;
    double v = 0.0;
    for (std::uint32_t l = link_start_[q]; l < link_start_[q + 1]; ++l) {
      if (links_[l].dlevel == -1) v += links_[l].c;
    }
    work_x_[a] = v;
  }
  CholeskySolve(s1_factor_.data(), s1, work_x_.data(), 1);
  std::int32_t e = 0;
  double* previous = work_x_.data();
  double* next = work_b_.data();
  const auto emit = [&](int k, const double* x, int s) {
    double top = 0.0;
    for (int a = 0; a < s; ++a) top = std::max(top, x[a]);
    const int shift = top > 0.0 ? std::ilogb(top) : 0;
    e += shift;
    const double scale = std::ldexp(1.0, -shift);
    for (int a = 0; a < s; ++a) {
      const std::uint32_t i = order_[first(k) + a];
      mantissa[i] = x[a] * scale;
      exponent[i] = e;
    }
  };
  emit(1, previous, s1);
  for (int a = 0; a < s1; ++a) previous[a] = mantissa[order_[first(1) + a]];
  for (int k = 2; k <= levels; ++k) {
    const int sk = size(k), sp = size(k - 1);
    const double* g = g_.data() + g_start_[k];
    for (int a = 0; a < sk; ++a) {
      double v = 0.0;
      for (int b = 0; b < sp; ++b) v += g[a * sp + b] * previous[b];
      next[a] = v;
    }
    emit(k, next, sk);
    for (int a = 0; a < sk; ++a) next[a] = mantissa[order_[first(k) + a]];
    std::swap(previous, next);
  }
}

}  // namespace spott_harmonic_planner::internal
