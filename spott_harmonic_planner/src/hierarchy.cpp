#include "hierarchy.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <type_traits>

namespace spott_harmonic_planner::internal {

namespace {

void MakeRuns(int nx, int ny, const std::vector<std::uint8_t>& active, std::vector<Run>& runs,
              std::size_t& unknowns) {
  // Word-at-a-time scan: a corridor in a large window costs about a byte compare per 8 cells.
  runs.clear();
  unknowns = 0;
  constexpr std::uint64_t kOnes = 0x0101010101010101ull;
  for (int y = 1; y < ny - 1; ++y) {
    const std::uint8_t* row = active.data() + static_cast<std::size_t>(y) * nx;
    const int end = nx - 1;
    int x = 1;
    while (x < end) {
      // Skip fixed cells.
      while (x + 8 <= end) {
        std::uint64_t w;
        std::memcpy(&w, row + x, 8);
        if (w != 0) break;
        x += 8;
      }
      while (x < end && !row[x]) ++x;
      if (x >= end) break;
      const int x0 = x;
      while (x + 8 <= end) {
        std::uint64_t w;
        std::memcpy(&w, row + x, 8);
        if (w != kOnes) break;
        x += 8;
      }
      while (x < end && row[x]) ++x;
      runs.push_back({y, x0, x});
      unknowns += static_cast<std::size_t>(x - x0);
    }
  }
}

// One run per row, from its first to its last unknown.
void MakeSegments(const std::vector<Run>& runs, std::vector<Run>& segs) {
  segs.clear();
  for (const Run& r : runs) {
    if (!segs.empty() && segs.back().y == r.y) {
      segs.back().x1 = r.x1;
    } else {
      segs.push_back(r);
    }
  }
}

template <typename T>
void ClearRuns(std::vector<T>& v, const std::vector<Run>& runs, int nx, int pad) {
  if (v.empty()) return;
  for (const Run& run : runs) {
    const std::size_t b = static_cast<std::size_t>(run.y) * nx;
    std::fill(v.begin() + b + run.x0 - pad, v.begin() + b + run.x1 + pad, T(0));
  }
}

}  // namespace

template <typename T>
double Hierarchy<T>::A0(int dx, int dy) const {
  if (dx == 0 && dy == 0) return 1.0;
  const bool straight = dx == 0 || dy == 0;
  if (stencil_ == Stencil::kFivePoint) return straight ? -0.25 : 0.0;
  return straight ? -0.2 : -0.05;
}

template <typename T>
void Hierarchy<T>::Build(const GridMask& mask, Stencil stencil) {
  CheckMask(mask);
  stencil_ = stencil;
  const std::size_t n = mask.free.size();
  if (levels_.empty() || levels_[0].nx != mask.width || levels_[0].ny != mask.height) {
    // A new grid size: allocate every level once; later builds clear what they used.
    levels_.clear();
    levels_.resize(1);
    Level& f = levels_[0];
    f.nx = mask.width;
    f.ny = mask.height;
    f.r.assign(n, T(0));
  } else {
    Level& f = levels_[0];
    ClearRuns(f.r, f.runs, f.nx, 0);
  }
  Level& f = levels_[0];
  f.active = mask.free;
  previous_runs_.swap(f.runs);
  MakeRuns(f.nx, f.ny, f.active, f.runs, f.unknowns);
  MakeSegments(f.runs, f.segs);
  if (f.mask.size() != n) {
    f.mask.assign(n, T(0));
  } else {
    ClearRuns(f.mask, previous_runs_, f.nx, 0);
  }
  for (const Run& run : f.runs) {
    const std::size_t b = static_cast<std::size_t>(run.y) * f.nx;
    std::fill(f.mask.begin() + b + run.x0, f.mask.begin() + b + run.x1, T(1));
  }
  const bool nine = stencil == Stencil::kNinePoint;
  const std::uint8_t* a = f.active.data();
  if (nine) {
    // Level 0 of the 9-point stencil runs on the coarse levels' kernels: store its constants.
    if (f.inv_diag.size() != n) {
      for (auto* v : {&f.diag, &f.inv_diag, &f.e, &f.n, &f.ne, &f.nw}) v->assign(n, T(0));
    } else {
      for (auto* v : {&f.diag, &f.inv_diag, &f.e, &f.n, &f.ne, &f.nw})
        ClearRuns(*v, previous_runs_, f.nx, 0);
    }
    for (const Run& run : f.runs) {
      for (int x = run.x0; x < run.x1; ++x) {
        const std::size_t i = static_cast<std::size_t>(run.y) * f.nx + x;
        f.inv_diag[i] = T(1);
        f.diag[i] = T(1);
        f.e[i] = a[i + 1] ? T(-0.2) : T(0);
        f.n[i] = a[i + f.nx] ? T(-0.2) : T(0);
        f.ne[i] = a[i + f.nx + 1] ? T(-0.05) : T(0);
        f.nw[i] = a[i + f.nx - 1] ? T(-0.05) : T(0);
      }
    }
  }
  tmp_.assign(static_cast<std::size_t>(3 * f.nx + 16), T(0));
  used_ = 1;
  while (levels_[used_ - 1].unknowns > static_cast<std::size_t>(kCoarsestUnknowns)) {
    const Level& last = levels_[used_ - 1];
    if (last.nx < 4 && last.ny < 4) break;
    BuildCoarse(used_ - 1);
    ++used_;
  }
  FactorCoarsest();
  if (fmg_rhs_.size() < levels_.size()) fmg_rhs_.resize(levels_.size());
  if (fmg_runs_.size() < levels_.size()) fmg_runs_.resize(levels_.size());
  for (std::size_t l = 1; l < used_; ++l) {
    const Level& c = levels_[l];
    if (fmg_rhs_[l].size() != c.active.size()) {
      fmg_rhs_[l].assign(c.active.size(), T(0));
    } else {
      ClearRuns(fmg_rhs_[l], fmg_runs_[l], c.nx, 0);
    }
    fmg_runs_[l] = c.runs;
  }
}

template <typename T>
void Hierarchy<T>::BuildCoarse(std::size_t l) {
  if (levels_.size() < l + 2) levels_.emplace_back();
  const Level& f = levels_[l];
  Level& c = levels_[l + 1];
  const int sx = f.nx >= 4 ? 2 : 1;
  const int sy = f.ny >= 4 ? 2 : 1;
  const int cnx = sx == 2 ? f.nx / 2 + 1 : f.nx;
  const int cny = sy == 2 ? f.ny / 2 + 1 : f.ny;
  const std::size_t n = static_cast<std::size_t>(cnx) * cny;
  if (c.nx != cnx || c.ny != cny || c.active.size() != n) {
    c.nx = cnx;
    c.ny = cny;
    c.active.assign(n, 0);
    for (auto* v : {&c.diag, &c.inv_diag, &c.e, &c.n, &c.ne, &c.nw, &c.u, &c.f, &c.r})
      v->assign(n, T(0));
  } else {
    // Clear what the last build of this level used (and the coefficients' left neighbours,
    // read through the symmetric storage).
    for (const Run& run : c.runs) {
      const std::size_t b = static_cast<std::size_t>(run.y) * c.nx;
      std::fill(c.active.begin() + b + run.x0, c.active.begin() + b + run.x1, 0);
    }
    for (auto* v : {&c.diag, &c.inv_diag, &c.e, &c.n, &c.ne, &c.nw, &c.u, &c.f, &c.r}) {
      ClearRuns(*v, c.runs, c.nx, 0);
    }
  }
  c.sx = sx;
  c.sy = sy;
  // Active coarse nodes: those whose support holds an unknown (from the fine runs).
  for (const Run& run : f.runs) {
    const int y0 = sy == 2 ? (run.y) / 2 : run.y, y1 = sy == 2 ? (run.y + 1) / 2 : run.y;
    const int x0 = sx == 2 ? run.x0 / 2 : run.x0, x1 = sx == 2 ? run.x1 / 2 : run.x1 - 1;
    for (int y = std::max(y0, 1); y <= std::min(y1, c.ny - 2); ++y) {
      const std::size_t b = static_cast<std::size_t>(y) * c.nx;
      std::fill(c.active.begin() + b + std::max(x0, 1),
                c.active.begin() + b + std::min(x1, c.nx - 2) + 1, 1);
    }
  }
  MakeRuns(c.nx, c.ny, c.active, c.runs, c.unknowns);
  MakeSegments(c.runs, c.segs);
  // Galerkin product A_c = P^T A P, P bilinear (the tensor product of 1D linear
  // interpolations): first in x (B = Px^T A Px on the grid of coarse columns and fine rows),
  // then in y. A coarse row needs B on three fine rows and the columns X0 - 1 .. X1 of its run;
  // they are formed per run into a small buffer (rows shared by two coarse rows are formed
  // twice). With the symmetric storage (diagonal d, couplings e to x + 1, n to y + 1, ne to
  // (x + 1, y + 1), nw to (x - 1, y + 1)) and fine columns 2X - 1, 2X, 2X + 1 (weights 1/2,
  // 1, 1/2) the x stage is
  //   Bd  = d-/4 + d0 + d+/4 + e- + e0          Be  = e0/2 + d+/4 + e+/2
  //   Bn  = n-/4 + n0 + n+/4 + (ne- + ne0 + nw0 + nw+)/2
  //   Bne = ne0/2 + n+/4 + ne+/2                 Bnw = nw0/2 + n-/4 + nw-/2
  // and the y stage the same with x and y exchanged (the couplings to (x + 1, y - 1), stored
  // as nw of the cell at (x + 1, y - 1), take the place of nw). Couplings to the coarse ring
  // are dropped: its correction is zero.
  const bool five0 = l == 0 && stencil_ == Stencil::kFivePoint;
  const std::size_t fnx = static_cast<std::size_t>(f.nx);
  // Scratch (T): the fine coefficients of one row segment (5 x fine width) and B on three
  // rows (5 x 3 x coarse width).
  const std::size_t fw = fnx + 8, cw = static_cast<std::size_t>(c.nx) + 8;
  std::vector<T>& buf = galerkin_rows_;
  if (buf.size() < 5 * fw + 15 * cw) buf.assign(5 * fw + 15 * cw, T(0));
  T* F = buf.data();            // F[q * fw + j]: quantity q of the row segment's column j
  T* Bq = buf.data() + 5 * fw;  // Bq[(q * 3 + r) * cw + k]
  const auto B = [&](int q, int r) { return Bq + (q * 3 + r) * cw; };
  const T* src[5] = {f.diag.data(), f.e.data(), f.n.data(), f.ne.data(), f.nw.data()};
  // Fine5 reads each cell's east and north neighbour flags: on the last column and the top row
  // they lie beyond the mask (ASan found the read). A copy padded with zeros (no neighbour, no
  // coupling) keeps the kernel's loop branch-free.
  std::vector<std::uint8_t> active;
  if (five0) {
    active.reserve(f.active.size() + fnx + 1);
    active.assign(f.active.begin(), f.active.end());
    active.resize(f.active.size() + fnx + 1, 0);
  }
  for (const Run& run : c.runs) {
    const int Y = run.y;
    // Coarse columns X0 - 1 .. X1 (local k = 0 .. count + 1), only interior ones hold B.
    const int xa = std::max(run.x0 - 1, 1), xb = std::min(run.x1, c.nx - 2);
    const int kmax = run.x1 - run.x0 + 2, k0 = xa - (run.x0 - 1), count = xb - xa + 1;
    for (int r = 0; r < 3; ++r) {
      if (sy == 1 && r != 1) continue;
      for (int q = 0; q < 5; ++q) std::fill(B(q, r), B(q, r) + kmax, T(0));
      const int fy = sy == 2 ? 2 * Y - 1 + r : Y;
      const int a = sx == 2 ? 2 * xa - 1 : xa;  // first fine column read
      const int len = sx == 2 ? 2 * count + 1 : count;
      const std::size_t base = static_cast<std::size_t>(fy) * fnx + static_cast<std::size_t>(a);
      const T* d;
      const T* e;
      const T* n;
      const T* ne = nullptr;
      const T* nw = nullptr;
      if (five0) {
        kernels::Fine5(active.data() + base, active.data() + base + fnx, F, F + fw, F + 2 * fw,
                       len);
        d = F;
        e = F + fw;
        n = F + 2 * fw;
      } else {
        d = src[0] + base;
        e = src[1] + base;
        n = src[2] + base;
        ne = src[3] + base;
        nw = src[4] + base;
      }
      if (sx == 1) {
        const T* in[5] = {d, e, n, ne, nw};
        for (int q = 0; q < 5; ++q) {
          if (in[q]) std::copy(in[q], in[q] + count, B(q, r) + k0);
        }
        continue;
      }
      kernels::GalerkinX(d, e, n, ne, nw, B(0, r) + k0, B(1, r) + k0, B(2, r) + k0, B(3, r) + k0,
                         B(4, r) + k0, count);
    }
    const std::size_t ci = static_cast<std::size_t>(Y) * c.nx + run.x0;
    const int m = run.x1 - run.x0;
    if (sy == 1) {
      for (int k = 1; k <= m; ++k) {
        const std::size_t i = ci + k - 1;
        c.diag[i] = B(0, 1)[k];
        c.inv_diag[i] = T(1) / B(0, 1)[k];
        c.e[i] = B(1, 1)[k];
        c.n[i] = B(2, 1)[k];
        c.ne[i] = B(3, 1)[k];
        c.nw[i] = B(4, 1)[k];
      }
    } else {
      using Rows = std::conditional_t<std::is_same_v<T, float>, kernels::GalerkinRows,
                                      kernels::GalerkinRowsD>;
      Rows rows;
      for (int r = 0; r < 3; ++r) {
        rows.d[r] = B(0, r);
        rows.e[r] = B(1, r);
        rows.n[r] = B(2, r);
        rows.ne[r] = B(3, r);
        rows.nw[r] = B(4, r);
      }
      kernels::GalerkinY(rows, c.diag.data() + ci, c.inv_diag.data() + ci, c.e.data() + ci,
                         c.n.data() + ci, c.ne.data() + ci, c.nw.data() + ci, m);
    }
    // No couplings to the coarse ring: its correction is zero.
    if (run.x1 - 1 == c.nx - 2) {
      const std::size_t i = ci + m - 1;
      c.e[i] = c.ne[i] = T(0);
    }
    if (run.x0 == 1) c.nw[ci] = T(0);
    if (Y == c.ny - 2) {
      std::fill(c.n.begin() + ci, c.n.begin() + ci + m, T(0));
      std::fill(c.ne.begin() + ci, c.ne.begin() + ci + m, T(0));
      std::fill(c.nw.begin() + ci, c.nw.begin() + ci + m, T(0));
    }
  }
}

template <typename T>
void Hierarchy<T>::FactorCoarsest() {
  const Level& c = levels_[used_ - 1];
  coarse_index_.clear();
  for (const Run& run : c.runs) {
    for (int x = run.x0; x < run.x1; ++x) coarse_index_.push_back(run.y * c.nx + x);
  }
  const int m = static_cast<int>(coarse_index_.size());
  chol_.assign(static_cast<std::size_t>(m) * m, 0.0);
  chol_rhs_.assign(m, 0.0);
  if (used_ == 1) {
    // Level 0 is the coarsest: its constant stencil on the mask.
    for (int a = 0; a < m; ++a) {
      for (int b = 0; b <= a; ++b) {
        const int i = coarse_index_[a], j = coarse_index_[b];
        const int dx = j % c.nx - i % c.nx, dy = j / c.nx - i / c.nx;
        if (std::abs(dx) <= 1 && std::abs(dy) <= 1) chol_[a * m + b] = A0(dx, dy);
      }
    }
  } else {
    for (int a = 0; a < m; ++a) {
      const int i = coarse_index_[a];
      for (int b = 0; b <= a; ++b) {
        const int j = coarse_index_[b];
        const int dx = j % c.nx - i % c.nx, dy = j / c.nx - i / c.nx;
        double v = 0.0;
        if (dx == 0 && dy == 0)
          v = c.diag[i];
        else if (dx == -1 && dy == 0)
          v = c.e[j];
        else if (dx == 0 && dy == -1)
          v = c.n[j];
        else if (dx == -1 && dy == -1)
          v = c.ne[j];
        else if (dx == 1 && dy == -1)
          v = c.nw[j];
        // b < a means j before i in row-major order: only these four lower offsets occur.
        chol_[a * m + b] = v;
      }
    }
  }
  // In-place Cholesky (lower triangle). The masked interpolation can make coarse columns
  // linearly dependent (a corridor one cell wide on an odd column touches two coarse nodes the
  // same way): the operator is then only semi-definite; a pivot that vanishes next to its
  // original diagonal marks a dependent unknown, whose correction is 0 (the system is
  // consistent: the right-hand side is in the range).
  for (int k = 0; k < m; ++k) {
    const double original = chol_[k * m + k];
    double d = original;
    for (int p = 0; p < k; ++p) d -= chol_[k * m + p] * chol_[k * m + p];
    if (!(d > 1e-15 * original)) {
      for (int i = k; i < m; ++i) chol_[i * m + k] = 0.0;
      continue;
    }
    d = std::sqrt(d);
    chol_[k * m + k] = d;
    for (int i = k + 1; i < m; ++i) {
      double s = chol_[i * m + k];
      for (int p = 0; p < k; ++p) s -= chol_[i * m + p] * chol_[k * m + p];
      chol_[i * m + k] = s / d;
    }
  }
  // L^T for the forward substitution's columns.
  chol_t_.assign(static_cast<std::size_t>(m) * m, 0.0);
  for (int i = 0; i < m; ++i) {
    for (int k = 0; k <= i; ++k) chol_t_[static_cast<std::size_t>(k) * m + i] = chol_[i * m + k];
  }
}

template <typename T>
void Hierarchy<T>::CoarsestSolve(T* u, const T* f) const {
  // Column-oriented substitutions: after each pivot the remaining right-hand side is updated by
  // one contiguous axpy (a column of L, stored as a row of L^T; then a row of L), so the work is
  // independent multiply-adds rather than one dot product's chain of dependent additions.
  const int m = static_cast<int>(coarse_index_.size());
  double* y = chol_rhs_.data();
  for (int a = 0; a < m; ++a) y[a] = f[coarse_index_[a]];
  for (int a = 0; a < m; ++a) {
    const double d = chol_[a * m + a];
    const double ya = d == 0.0 ? 0.0 : y[a] / d;  // a dependent unknown: its correction is 0
    y[a] = ya;
    const double* __restrict col = chol_t_.data() + static_cast<std::size_t>(a) * m;
    for (int p = a + 1; p < m; ++p) y[p] -= col[p] * ya;
  }
  for (int a = m - 1; a >= 0; --a) {
    const double d = chol_[a * m + a];
    const double xa = d == 0.0 ? 0.0 : y[a] / d;
    y[a] = xa;
    const double* __restrict row = chol_.data() + static_cast<std::size_t>(a) * m;
    for (int p = 0; p < a; ++p) y[p] -= row[p] * xa;
  }
  for (int a = 0; a < m; ++a) u[coarse_index_[a]] = static_cast<T>(y[a]);
}

template <typename T>
void Hierarchy<T>::Smooth(std::size_t l, T* u, const T* f, int sweeps, bool backwards) const {
  const Level& L = levels_[l];
  T* tmp = tmp_.data();
  if (l == 0 && stencil_ == Stencil::kFivePoint) {
    for (int s = 0; s < sweeps; ++s) {
      for (int k = 0; k < 2; ++k) {
        kernels::Colour5(u, f, L.mask.data(), L.nx, L.segs.data(), L.segs.size(),
                         backwards ? 1 - k : k, tmp);
      }
    }
    return;
  }
  const Stencil9<T> a = L.op();
  for (int s = 0; s < sweeps; ++s) {
    for (int k = 0; k < 4; ++k) {
      const int colour = backwards ? 3 - k : k;
      kernels::Colour9(u, f, L.nx, L.segs.data(), L.segs.size(), colour & 1, colour >> 1, a, tmp);
    }
  }
}

template <typename T>
void Hierarchy<T>::Residual(std::size_t l, const T* u, const T* f, T* r) const {
  const Level& L = levels_[l];
  if (l == 0 && stencil_ == Stencil::kFivePoint) {
    kernels::Residual5(u, f, L.mask.data(), r, L.nx, L.segs.data(), L.segs.size());
  } else {
    kernels::Residual9(u, f, r, L.nx, L.segs.data(), L.segs.size(), L.op());
  }
}

template <typename T>
void Hierarchy<T>::Restrict(std::size_t l, const T* r, T* fc) const {
  const Level& f = levels_[l];
  const Level& c = levels_[l + 1];
  kernels::Restrict(r, f.nx, fc, c.nx, c.segs.data(), c.segs.size(), c.sx, c.sy, tmp_.data());
}

template <typename T>
void Hierarchy<T>::Prolongate(std::size_t l, const T* uc, T* u) const {
  const Level& f = levels_[l];
  const Level& c = levels_[l + 1];
  kernels::Prolongate(uc, c.nx, u, l == 0 ? f.mask.data() : nullptr, f.nx, f.segs.data(),
                      f.segs.size(), c.sx, c.sy, tmp_.data());
}

template <typename T>
void Hierarchy<T>::Cycle(std::size_t l, T* u, const T* f, int pre, int post, bool zero_start) {
  Level& L = levels_[l];
  const bool first_sweep = zero_start && l == 0 && pre > 0 && l + 1 < used_ &&
                           stencil_ == Stencil::kFivePoint && std::is_same_v<T, float>;
  if (zero_start && !first_sweep) {
    for (const Run& run : L.segs) {
      std::fill(u + static_cast<std::ptrdiff_t>(run.y) * L.nx + run.x0,
                u + static_cast<std::ptrdiff_t>(run.y) * L.nx + run.x1, T(0));
    }
  }
  if (l + 1 == used_) {
    CoarsestSolve(u, f);  // exact: the start value does not matter
    return;
  }
  if (first_sweep) {
    FirstSweep(u, f);  // writes every unknown
    Smooth(l, u, f, pre - 1, false);
  } else {
    Smooth(l, u, f, pre, false);
  }
  T* r = L.r.data();
  Residual(l, u, f, r);
  Level& C = levels_[l + 1];
  Restrict(l, r, C.f.data());
  Cycle(l + 1, C.u.data(), C.f.data(), pre, post, true);
  Prolongate(l, C.u.data(), u);
  Smooth(l, u, f, post, true);
}

template <typename T>
void Hierarchy<T>::VCycle(const T* r, T* e, int pre, int post) {
  Cycle(0, e, r, pre, post, true);
}

template <typename T>
void Hierarchy<T>::FullMultigrid(const T* r, T* e, int pre, int post) {
  const std::size_t last = used_ - 1;
  if (last == 0) {
    Cycle(0, e, r, pre, post, true);
    return;
  }
  Restrict(0, r, fmg_rhs_[1].data());
  for (std::size_t l = 1; l < last; ++l) Restrict(l, fmg_rhs_[l].data(), fmg_rhs_[l + 1].data());
  Cycle(last, levels_[last].u.data(), fmg_rhs_[last].data(), pre, post, true);
  for (std::size_t l = last; l-- > 0;) {
    Level& L = levels_[l];
    T* u = l == 0 ? e : L.u.data();
    const T* b = l == 0 ? r : fmg_rhs_[l].data();
    for (const Run& run : L.segs) {
      std::fill(u + static_cast<std::ptrdiff_t>(run.y) * L.nx + run.x0,
                u + static_cast<std::ptrdiff_t>(run.y) * L.nx + run.x1, T(0));
    }
    Prolongate(l, levels_[l + 1].u.data(), u);
    Cycle(l, u, b, pre, post, false);
  }
}

template <typename T>
double Hierarchy<T>::Apply(const T* x, T* y) const {
  const Level& L = levels_[0];
  const int nx = L.nx;
  double dot = 0.0;
  for (const Run& run : L.runs) {
    const std::ptrdiff_t base = static_cast<std::ptrdiff_t>(run.y) * nx;
    const T* __restrict row = x + base;
    const T* __restrict up = row + nx;
    const T* __restrict down = row - nx;
    T* __restrict yr = y + base;
    if (stencil_ == Stencil::kFivePoint) {
      for (int k = run.x0; k < run.x1; ++k) {
        const T v = row[k] - T(0.25) * ((row[k - 1] + row[k + 1]) + (down[k] + up[k]));
        yr[k] = v;
        dot += static_cast<double>(v) * row[k];
      }
    } else {
      for (int k = run.x0; k < run.x1; ++k) {
        const T v = row[k] - T(0.2) * ((row[k - 1] + row[k + 1]) + (down[k] + up[k])) -
                    T(0.05) * ((down[k - 1] + down[k + 1]) + (up[k - 1] + up[k + 1]));
        yr[k] = v;
        dot += static_cast<double>(v) * row[k];
      }
    }
  }
  return dot;
}

template <typename T>
void Hierarchy<T>::FirstSweep(T* u, const T* f) {
  if constexpr (std::is_same_v<T, float>) {
    const Level& L = levels_[0];
    kernels::FirstSweep5(u, f, L.mask.data(), L.nx, L.segs.data(), L.segs.size(), tmp_.data());
  } else {
    Smooth(0, u, f, 1, false);  // not reached: Cycle zeroes u and smooths for other types
  }
}

template class Hierarchy<double>;
template class Hierarchy<float>;

}  // namespace spott_harmonic_planner::internal
