#include "mg_kernels.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <type_traits>

// Two builds of every kernel on x86-64 (AVX2 + FMA, and the baseline), chosen at load time.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__)) && !defined(SPOTT_NO_CLONES)
#define SPOTT_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define SPOTT_CLONES
#endif

// Reductions (sums, maxima) keep kLanes partial results, so the compiler vectorizes them
// without reordering a single sum; the selects need -fno-trapping-math to become blends.

namespace spott_harmonic_planner::internal::kernels {

namespace {

// The colour passes on GCC's 32-byte vector types (8 floats or 4 doubles): each step computes
// a vector of cells and blends the colour's cells into the row in place. That is exact
// Gauss-Seidel: a cell of the colour reads only cells of other colours, which the pass writes
// back unchanged (the next step's loads may see this step's stores). Scalar steps end a run.
// (The auto-vectorized form needed a second pass through a scratch row.)
// Every function taking or returning a vector is inlined: no call passes one (-Wpsabi warns
// about the ABI of such calls in the baseline build).
#pragma GCC diagnostic ignored "-Wpsabi"
template <typename T>
struct Vec;
template <>
struct Vec<float> {
  typedef float type __attribute__((vector_size(32)));
  typedef std::int32_t mask __attribute__((vector_size(32)));
  static constexpr int kLanes = 8;
};
template <>
struct Vec<double> {
  typedef double type __attribute__((vector_size(32)));
  typedef std::int64_t mask __attribute__((vector_size(32)));
  static constexpr int kLanes = 4;
};

template <typename T>
__attribute__((always_inline)) inline typename Vec<T>::type Ld(const T* p) {
  typename Vec<T>::type v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
template <typename T>
__attribute__((always_inline)) inline void St(T* p, typename Vec<T>::type v) {
  std::memcpy(p, &v, sizeof v);
}
// Lanes whose index has parity `parity` (the steps start at even offsets).
template <typename T>
__attribute__((always_inline)) inline typename Vec<T>::mask Parity(int parity) {
  typename Vec<T>::mask m;
  for (int j = 0; j < Vec<T>::kLanes; ++j) m[j] = (j & 1) == parity ? -1 : 0;
  return m;
}

template <typename T>
__attribute__((always_inline)) inline void Colour5T(T* u, const T* f, const T* mask, int nx,
                                                    const Run* runs, std::size_t count,
                                                    int colour) {
  using V = typename Vec<T>::type;
  constexpr int L = Vec<T>::kLanes;
  for (std::size_t q = 0; q < count; ++q) {
    const Run& run = runs[q];
    const std::ptrdiff_t base = static_cast<std::ptrdiff_t>(run.y) * nx;
    const int len = run.x1 - run.x0;
    T* row = u + base + run.x0;
    const T* up = row + nx;
    const T* down = row - nx;
    const T* fr = f + base + run.x0;
    const T* m = mask ? mask + base + run.x0 : nullptr;
    const int parity = ((run.x0 + run.y) & 1) == colour ? 0 : 1;
    const auto sel = Parity<T>(parity);
    int k = 0;
    for (; k + L <= len; k += L) {
      V v = T(0.25) * ((Ld(row + k - 1) + Ld(row + k + 1)) + (Ld(down + k) + Ld(up + k))) +
            Ld(fr + k);
      if (m) v *= Ld(m + k);
      St(row + k, sel ? v : Ld(row + k));
    }
    for (k += (k & 1) != parity ? 1 : 0; k < len; k += 2) {
      const T v = T(0.25) * ((row[k - 1] + row[k + 1]) + (down[k] + up[k])) + fr[k];
      row[k] = m ? m[k] * v : v;
    }
  }
}

// The first red-black sweep from u = 0, in one pass: colour 0 becomes f, colour 1 the mean of
// those plus f (f is 0 on fixed cells, and so is u wherever this pass does not write).
template <typename T>
__attribute__((always_inline)) inline void FirstSweep5T(T* u, const T* f, const T* mask, int nx,
                                                        const Run* runs, std::size_t count) {
  using V = typename Vec<T>::type;
  constexpr int L = Vec<T>::kLanes;
  for (std::size_t q = 0; q < count; ++q) {
    const Run& run = runs[q];
    const std::ptrdiff_t base = static_cast<std::ptrdiff_t>(run.y) * nx + run.x0;
    const int len = run.x1 - run.x0;
    T* __restrict row = u + base;
    const T* __restrict fr = f + base;
    const T* __restrict fu = fr + nx;
    const T* __restrict fd = fr - nx;
    const T* __restrict m = mask ? mask + base : nullptr;
    const int parity = ((run.x0 + run.y) & 1) == 0 ? 0 : 1;  // the lanes of colour 0
    const auto sel = Parity<T>(parity);
    int k = 0;
    for (; k + L <= len; k += L) {
      const V fk = Ld(fr + k);
      V v = T(0.25) * ((Ld(fr + k - 1) + Ld(fr + k + 1)) + (Ld(fd + k) + Ld(fu + k))) + fk;
      if (m) v *= Ld(m + k);
      St(row + k, sel ? fk : v);
    }
    for (; k < len; ++k) {
      if ((k & 1) == parity) {
        row[k] = fr[k];
      } else {
        const T v = T(0.25) * ((fr[k - 1] + fr[k + 1]) + (fd[k] + fu[k])) + fr[k];
        row[k] = m ? m[k] * v : v;
      }
    }
  }
}

template <typename T>
inline void Residual5T(const T* u, const T* f, const T* mask, T* r, int nx, const Run* runs,
                       std::size_t count) {
  for (std::size_t q = 0; q < count; ++q) {
    const Run& run = runs[q];
    const std::ptrdiff_t base = static_cast<std::ptrdiff_t>(run.y) * nx + run.x0;
    const int len = run.x1 - run.x0;
    const T* __restrict row = u + base;
    const T* __restrict up = row + nx;
    const T* __restrict down = row - nx;
    const T* __restrict fr = f + base;
    T* __restrict rr = r + base;
    if (mask) {
      const T* __restrict m = mask + base;
      for (int k = 0; k < len; ++k) {
        rr[k] = m[k] * (fr[k] - row[k] + T(0.25) * ((row[k - 1] + row[k + 1]) + (down[k] + up[k])));
      }
    } else {
      for (int k = 0; k < len; ++k) {
        rr[k] = fr[k] - row[k] + T(0.25) * ((row[k - 1] + row[k + 1]) + (down[k] + up[k]));
      }
    }
  }
}

template <typename T>
inline T Apply9(const T* row, const T* up, const T* down, const Stencil9<T>& a, std::ptrdiff_t i,
                std::ptrdiff_t nx, int k) {
  return a.e[i] * row[k + 1] + a.e[i - 1] * row[k - 1] + a.n[i] * up[k] + a.n[i - nx] * down[k] +
         a.ne[i] * up[k + 1] + a.ne[i - nx - 1] * down[k - 1] + a.nw[i] * up[k - 1] +
         a.nw[i - nx + 1] * down[k + 1];
}

template <typename T>
__attribute__((always_inline)) inline void Colour9T(T* u, const T* f, int nx, const Run* runs,
                                                    std::size_t count, int px, int py,
                                                    const Stencil9<T>& a) {
  using V = typename Vec<T>::type;
  constexpr int L = Vec<T>::kLanes;
  for (std::size_t q = 0; q < count; ++q) {
    const Run& run = runs[q];
    if ((run.y & 1) != py) continue;
    const std::ptrdiff_t base = static_cast<std::ptrdiff_t>(run.y) * nx + run.x0;
    const int len = run.x1 - run.x0;
    T* row = u + base;
    const T* up = row + nx;
    const T* down = row - nx;
    const T* fr = f + base;
    const T* id = a.inv_diag + base;
    const T* e = a.e + base;
    const T* n = a.n + base;
    const T* nd = a.n + base - nx;
    const T* ne = a.ne + base;
    const T* ned = a.ne + base - nx - 1;
    const T* nw = a.nw + base;
    const T* nwd = a.nw + base - nx + 1;
    const int parity = (run.x0 & 1) == px ? 0 : 1;
    const auto sel = Parity<T>(parity);
    int k = 0;
    for (; k + L <= len; k += L) {
      const V s = Ld(e + k) * Ld(row + k + 1) + Ld(e + k - 1) * Ld(row + k - 1) +
                  Ld(n + k) * Ld(up + k) + Ld(nd + k) * Ld(down + k) + Ld(ne + k) * Ld(up + k + 1) +
                  Ld(ned + k) * Ld(down + k - 1) + Ld(nw + k) * Ld(up + k - 1) +
                  Ld(nwd + k) * Ld(down + k + 1);
      St(row + k, sel ? Ld(id + k) * (Ld(fr + k) - s) : Ld(row + k));
    }
    for (k += (k & 1) != parity ? 1 : 0; k < len; k += 2) {
      const T s = e[k] * row[k + 1] + e[k - 1] * row[k - 1] + n[k] * up[k] + nd[k] * down[k] +
                  ne[k] * up[k + 1] + ned[k] * down[k - 1] + nw[k] * up[k - 1] +
                  nwd[k] * down[k + 1];
      row[k] = id[k] * (fr[k] - s);
    }
  }
}

// One row of r = f - A u (restrict parameters: the compiler needs no alias checks between the
// row and its 17 input streams).
template <typename T>
inline void Residual9Row(const T* __restrict row, const T* __restrict up, const T* __restrict down,
                         const T* __restrict fr, const T* __restrict di, const T* __restrict e,
                         const T* __restrict n, const T* __restrict nd, const T* __restrict ne,
                         const T* __restrict ned, const T* __restrict nw, const T* __restrict nwd,
                         T* __restrict rr, int len) {
  for (int k = 0; k < len; ++k) {
    const T s = e[k] * row[k + 1] + e[k - 1] * row[k - 1] + n[k] * up[k] + nd[k] * down[k] +
                ne[k] * up[k + 1] + ned[k] * down[k - 1] + nw[k] * up[k - 1] +
                nwd[k] * down[k + 1] + di[k] * row[k];
    rr[k] = fr[k] - s;
  }
}

template <typename T>
inline void Residual9T(const T* u, const T* f, T* r, int nx, const Run* runs, std::size_t count,
                       const Stencil9<T>& a) {
  for (std::size_t q = 0; q < count; ++q) {
    const Run& run = runs[q];
    const std::ptrdiff_t base = static_cast<std::ptrdiff_t>(run.y) * nx + run.x0;
    const T* row = u + base;
    Residual9Row(row, row + nx, row - nx, f + base, a.diag + base, a.e + base, a.n + base,
                 a.n + base - nx, a.ne + base, a.ne + base - nx - 1, a.nw + base,
                 a.nw + base - nx + 1, r + base, run.x1 - run.x0);
  }
}

template <typename T>
inline void RestrictT(const T* r, int fnx, T* fc, int cnx, const Run* runs, std::size_t count,
                      int sx, int sy, T* __restrict tmp) {
  for (std::size_t q = 0; q < count; ++q) {
    const Run& run = runs[q];
    const int fy = sy * run.y;
    const T* __restrict r0 = r + static_cast<std::ptrdiff_t>(fy) * fnx;
    T* __restrict out = fc + static_cast<std::ptrdiff_t>(run.y) * cnx;
    if (sx == 1) {
      if (sy == 2) {
        for (int X = run.x0; X < run.x1; ++X) {
          out[X] = r0[X] + T(0.5) * (r0[X - fnx] + r0[X + fnx]);
        }
      } else {
        for (int X = run.x0; X < run.x1; ++X) out[X] = r0[X];
      }
      continue;
    }
    // Columns 2 X0 - 1 .. 2 X1 - 1 of the fine rows, summed vertically first.
    const int a = 2 * run.x0 - 1, b = 2 * run.x1 - 1;  // [a, b]
    const int len = b - a + 1;
    const T* __restrict c = r0 + a;
    if (sy == 2) {
      const T* __restrict lo = c - fnx;
      const T* __restrict hi = c + fnx;
      for (int k = 0; k < len; ++k) tmp[k] = c[k] + T(0.5) * (lo[k] + hi[k]);
    } else {
      for (int k = 0; k < len; ++k) tmp[k] = c[k];
    }
    // Coarse X sits on fine 2 X = tmp index 2 (X - X0) + 1.
    const int m = run.x1 - run.x0;
    T* __restrict o = out + run.x0;
    for (int k = 0; k < m; ++k) o[k] = tmp[2 * k + 1] + T(0.5) * (tmp[2 * k] + tmp[2 * k + 2]);
  }
}

template <typename T>
inline void ProlongateT(const T* uc, int cnx, T* u, const T* mask, int fnx, const Run* runs,
                        std::size_t count, int sx, int sy, T* __restrict tmp) {
  for (std::size_t q = 0; q < count; ++q) {
    const Run& run = runs[q];
    const int y = run.y;
    const int y0 = sy == 2 ? y / 2 : y, y1 = sy == 2 ? (y + 1) / 2 : y;
    const T* __restrict c0 = uc + static_cast<std::ptrdiff_t>(y0) * cnx;
    const T* __restrict c1 = uc + static_cast<std::ptrdiff_t>(y1) * cnx;
    T* __restrict row = u + static_cast<std::ptrdiff_t>(y) * fnx;
    const int len = run.x1 - run.x0;
    const T* __restrict mrow = mask ? mask + static_cast<std::ptrdiff_t>(y) * fnx : nullptr;
    if (sx == 1) {
      for (int x = run.x0; x < run.x1; ++x) {
        const T v = y0 == y1 ? c0[x] : T(0.5) * (c0[x] + c1[x]);
        row[x] += mrow ? mrow[x] * v : v;
      }
      continue;
    }
    // Coarse columns X0 = x0 / 2 .. X1 = x1 / 2, interpolated in y into tmp, then in x.
    const int X0 = run.x0 / 2, X1 = run.x1 / 2;
    const int m = X1 - X0 + 1;
    T* __restrict cr = tmp;
    if (y0 == y1) {
      for (int k = 0; k < m; ++k) cr[k] = c0[X0 + k];
    } else {
      for (int k = 0; k < m; ++k) cr[k] = T(0.5) * (c0[X0 + k] + c1[X0 + k]);
    }
    // Fine x = 2 X0 + j: j even -> cr[j / 2], j odd -> mean of cr[j / 2], cr[j / 2 + 1].
    T* __restrict ex = tmp + m + 1;
    int k = 0;
    if constexpr (std::is_same_v<T, float>) {
      // Eight coarse values and their midpoints interleaved by two shuffles (the steps may run
      // past m - 1 in the scratch row: those entries are not read).
      using V = Vec<float>::type;
      for (; k + 1 < m; k += 8) {
        const V a = Ld(cr + k), mid = T(0.5) * (a + Ld(cr + k + 1));
#if defined(__clang__)  // clang spells GCC's vector shuffle with constant indices this way
        St(ex + 2 * k, __builtin_shufflevector(a, mid, 0, 8, 1, 9, 2, 10, 3, 11));
        St(ex + 2 * k + 8, __builtin_shufflevector(a, mid, 4, 12, 5, 13, 6, 14, 7, 15));
#else
        using M = Vec<float>::mask;
        St(ex + 2 * k, __builtin_shuffle(a, mid, M{0, 8, 1, 9, 2, 10, 3, 11}));
        St(ex + 2 * k + 8, __builtin_shuffle(a, mid, M{4, 12, 5, 13, 6, 14, 7, 15}));
#endif
      }
    } else {
      for (; k + 1 < m; ++k) {
        ex[2 * k] = cr[k];
        ex[2 * k + 1] = T(0.5) * (cr[k] + cr[k + 1]);
      }
    }
    ex[2 * (m - 1)] = cr[m - 1];
    const int off = run.x0 - 2 * X0;  // 0 or 1
    T* __restrict out = row + run.x0;
    const T* __restrict src = ex + off;
    if (mrow) {
      const T* __restrict mm = mrow + run.x0;
      for (int k = 0; k < len; ++k) out[k] += mm[k] * src[k];
    } else {
      for (int k = 0; k < len; ++k) out[k] += src[k];
    }
  }
}

}  // namespace

template <typename T>
inline void Fine5T(const std::uint8_t* __restrict m, const std::uint8_t* __restrict mu,
                   T* __restrict d, T* __restrict e, T* __restrict n, int len) {
  for (int j = 0; j < len; ++j) {
    const T a = static_cast<T>(m[j]);
    d[j] = a;
    e[j] = T(-0.25) * a * static_cast<T>(m[j + 1]);
    n[j] = T(-0.25) * a * static_cast<T>(mu[j]);
  }
}

template <typename T>
inline void GalerkinXT(const T* __restrict d, const T* __restrict e, const T* __restrict n,
                       const T* __restrict ne, const T* __restrict nw, T* __restrict bd,
                       T* __restrict be, T* __restrict bn, T* __restrict bne, T* __restrict bnw,
                       int count) {
  if (ne == nullptr) {  // the 5-point level 0: no diagonal couplings
    for (int t = 0; t < count; ++t) {
      const int m = 2 * t, z = m + 1, p = m + 2;
      bd[t] = T(0.25) * d[m] + d[z] + T(0.25) * d[p] + e[m] + e[z];
      be[t] = T(0.5) * e[z] + T(0.25) * d[p] + T(0.5) * e[p];
      bn[t] = T(0.25) * n[m] + n[z] + T(0.25) * n[p];
      bne[t] = T(0.25) * n[p];
      bnw[t] = T(0.25) * n[m];
    }
    return;
  }
  for (int t = 0; t < count; ++t) {
    const int m = 2 * t, z = m + 1, p = m + 2;
    bd[t] = T(0.25) * d[m] + d[z] + T(0.25) * d[p] + e[m] + e[z];
    be[t] = T(0.5) * e[z] + T(0.25) * d[p] + T(0.5) * e[p];
    bn[t] = T(0.25) * n[m] + n[z] + T(0.25) * n[p] + T(0.5) * ((ne[m] + ne[z]) + (nw[z] + nw[p]));
    bne[t] = T(0.5) * ne[z] + T(0.25) * n[p] + T(0.5) * ne[p];
    bnw[t] = T(0.5) * nw[z] + T(0.25) * n[m] + T(0.5) * nw[m];
  }
}

template <typename T, typename Rows>
inline void GalerkinYT(const Rows& b, T* __restrict diag, T* __restrict inv_diag, T* __restrict e,
                       T* __restrict n, T* __restrict ne, T* __restrict nw, int count) {
  const T* __restrict d0 = b.d[0] + 1;
  const T* __restrict d1 = b.d[1] + 1;
  const T* __restrict d2 = b.d[2] + 1;
  const T* __restrict e0 = b.e[0] + 1;
  const T* __restrict e1 = b.e[1] + 1;
  const T* __restrict e2 = b.e[2] + 1;
  const T* __restrict n0 = b.n[0] + 1;
  const T* __restrict n1 = b.n[1] + 1;
  const T* __restrict n2 = b.n[2] + 1;
  const T* __restrict ne0 = b.ne[0] + 1;
  const T* __restrict ne1 = b.ne[1] + 1;
  const T* __restrict ne2 = b.ne[2] + 1;
  const T* __restrict nw0 = b.nw[0] + 1;
  const T* __restrict nw1 = b.nw[1] + 1;
  const T* __restrict nw2 = b.nw[2] + 1;
  for (int k = 0; k < count; ++k) {
    const T a0 = T(0.25) * d0[k] + d1[k] + T(0.25) * d2[k] + n0[k] + n1[k];
    diag[k] = a0;
    inv_diag[k] = T(1) / a0;
    n[k] = T(0.5) * n1[k] + T(0.25) * d2[k] + T(0.5) * n2[k];
    e[k] = T(0.25) * e0[k] + e1[k] + T(0.25) * e2[k] +
           T(0.5) * ((ne0[k] + ne1[k]) + (nw0[k + 1] + nw1[k + 1]));
    ne[k] = T(0.5) * ne1[k] + T(0.25) * e2[k] + T(0.5) * ne2[k];
    nw[k] = T(0.5) * nw1[k] + T(0.25) * e2[k - 1] + T(0.5) * nw2[k];
  }
}

#define SPOTT_KERNELS(T)                                                                          \
  SPOTT_CLONES void Colour5(T* u, const T* f, const T* mask, int nx, const Run* runs,             \
                            std::size_t count, int colour, T* tmp) {                              \
    (void)tmp;                                                                                    \
    Colour5T(u, f, mask, nx, runs, count, colour);                                                \
  }                                                                                               \
  SPOTT_CLONES void Residual5(const T* u, const T* f, const T* mask, T* r, int nx,                \
                              const Run* runs, std::size_t count) {                               \
    Residual5T(u, f, mask, r, nx, runs, count);                                                   \
  }                                                                                               \
  SPOTT_CLONES void Colour9(T* u, const T* f, int nx, const Run* runs, std::size_t count, int px, \
                            int py, const Stencil9<T>& a, T* tmp) {                               \
    (void)tmp;                                                                                    \
    Colour9T(u, f, nx, runs, count, px, py, a);                                                   \
  }                                                                                               \
  SPOTT_CLONES void Residual9(const T* u, const T* f, T* r, int nx, const Run* runs,              \
                              std::size_t count, const Stencil9<T>& a) {                          \
    Residual9T(u, f, r, nx, runs, count, a);                                                      \
  }                                                                                               \
  SPOTT_CLONES void Restrict(const T* r, int fnx, T* fc, int cnx, const Run* runs,                \
                             std::size_t count, int sx, int sy, T* tmp) {                         \
    RestrictT(r, fnx, fc, cnx, runs, count, sx, sy, tmp);                                         \
  }                                                                                               \
  SPOTT_CLONES void Prolongate(const T* uc, int cnx, T* u, const T* mask, int fnx,                \
                               const Run* runs, std::size_t count, int sx, int sy, T* tmp) {      \
    ProlongateT(uc, cnx, u, mask, fnx, runs, count, sx, sy, tmp);                                 \
  }

SPOTT_KERNELS(float)
SPOTT_KERNELS(double)

SPOTT_CLONES bool BlockedDiffers(const std::uint8_t* cells, const std::uint8_t* blocked, int nx,
                                 int ny) {
  const std::size_t n = static_cast<std::size_t>(nx) * ny;
  std::uint8_t ring = 1;
  for (int x = 0; x < nx; ++x) ring &= blocked[x] & blocked[n - nx + x];
  for (int y = 0; y < ny; ++y) {
    ring &= blocked[static_cast<std::size_t>(y) * nx] &
            blocked[static_cast<std::size_t>(y) * nx + nx - 1];
  }
  if (!ring) return true;
  for (int y = 1; y < ny - 1; ++y) {
    const std::uint8_t* __restrict c = cells + static_cast<std::size_t>(y) * nx;
    const std::uint8_t* __restrict b = blocked + static_cast<std::size_t>(y) * nx;
    std::uint8_t diff = 0;
    for (int x = 1; x < nx - 1; ++x) diff |= static_cast<std::uint8_t>((c[x] != 0) ^ b[x]);
    if (diff) return true;
  }
  return false;
}

SPOTT_CLONES void SetBlocked(const std::uint8_t* cells, std::uint8_t* blocked, std::uint8_t* kind,
                             int nx, int ny) {
  const std::size_t n = static_cast<std::size_t>(nx) * ny;
  for (int y = 1; y < ny - 1; ++y) {
    const std::uint8_t* __restrict c = cells + static_cast<std::size_t>(y) * nx;
    std::uint8_t* __restrict b = blocked + static_cast<std::size_t>(y) * nx;
    std::uint8_t* __restrict k = kind + static_cast<std::size_t>(y) * nx;
    for (int x = 1; x < nx - 1; ++x) {
      const std::uint8_t v = c[x] != 0;
      b[x] = v;
      k[x] = static_cast<std::uint8_t>(3 - 2 * v);
    }
    b[0] = b[nx - 1] = 1;
    k[0] = k[nx - 1] = 1;
  }
  for (int x = 0; x < nx; ++x) {
    blocked[x] = blocked[n - nx + x] = 1;
    kind[x] = kind[n - nx + x] = 1;
  }
}

SPOTT_CLONES void Fine5(const std::uint8_t* mask, const std::uint8_t* mask_up, float* d, float* e,
                        float* n, int len) {
  Fine5T(mask, mask_up, d, e, n, len);
}
SPOTT_CLONES void Fine5(const std::uint8_t* mask, const std::uint8_t* mask_up, double* d, double* e,
                        double* n, int len) {
  Fine5T(mask, mask_up, d, e, n, len);
}
SPOTT_CLONES void GalerkinX(const float* d, const float* e, const float* n, const float* ne,
                            const float* nw, float* bd, float* be, float* bn, float* bne,
                            float* bnw, int count) {
  GalerkinXT(d, e, n, ne, nw, bd, be, bn, bne, bnw, count);
}
SPOTT_CLONES void GalerkinX(const double* d, const double* e, const double* n, const double* ne,
                            const double* nw, double* bd, double* be, double* bn, double* bne,
                            double* bnw, int count) {
  GalerkinXT(d, e, n, ne, nw, bd, be, bn, bne, bnw, count);
}
SPOTT_CLONES void GalerkinY(const GalerkinRows& b, float* diag, float* inv_diag, float* e, float* n,
                            float* ne, float* nw, int count) {
  GalerkinYT<float>(b, diag, inv_diag, e, n, ne, nw, count);
}
SPOTT_CLONES void GalerkinY(const GalerkinRowsD& b, double* diag, double* inv_diag, double* e,
                            double* n, double* ne, double* nw, int count) {
  GalerkinYT<double>(b, diag, inv_diag, e, n, ne, nw, count);
}
#undef SPOTT_KERNELS

SPOTT_CLONES void FirstSweep5(float* u, const float* f, const float* mask, int nx, const Run* runs,
                              std::size_t count, float* tmp) {
  (void)tmp;
  FirstSweep5T(u, f, mask, nx, runs, count);
}

namespace {

template <bool kNine, typename T>
inline double Mean(const T* row, const T* up, const T* down, int k) {
  if constexpr (kNine) {
    return 0.2 * ((static_cast<double>(row[k - 1]) + row[k + 1]) +
                  (static_cast<double>(down[k]) + up[k])) +
           0.05 * ((static_cast<double>(down[k - 1]) + down[k + 1]) +
                   (static_cast<double>(up[k - 1]) + up[k + 1]));
  } else {
    return 0.25 * ((static_cast<double>(row[k - 1]) + row[k + 1]) +
                   (static_cast<double>(down[k]) + up[k]));
  }
}

// max |r| and max |r| / u without a division per cell: track the largest ratio seen.
constexpr int kLanes = 8;

// body(k, lane) for k in [0, len): blocks of kLanes with lane = k % kLanes (the partial
// results of a reduction are per lane).
template <typename Body>
inline void ForLanes(int len, Body&& body) {
  int k = 0;
  for (; k + kLanes <= len; k += kLanes) {
    for (int j = 0; j < kLanes; ++j) body(k + j, j);
  }
  for (int j = 0; k < len; ++k, ++j) body(k, j);
}

inline double MaxOf(const double* v) {
  double m = v[0];
  for (int j = 1; j < kLanes; ++j) m = v[j] > m ? v[j] : m;
  return m;
}
inline double SumOf(const double* v) {
  double s = 0.0;
  for (int j = 0; j < kLanes; ++j) s += v[j];
  return s;
}

// The conjugate-gradient passes in double: written on GCC's vector type of four doubles
// (an AVX2 register in the x86-64-v3 clone, two SSE2 registers in the baseline one), one
// vector of cells per step and scalar steps for a run's last cells. (Auto-vectorization of the
// 8-lane blocks above re-checked pointer aliasing in every block.)
typedef double V4 __attribute__((vector_size(32)));
typedef float F4 __attribute__((vector_size(16)));

template <typename V>
__attribute__((always_inline)) inline V Load(const double* p) {
  if constexpr (std::is_same_v<V, double>) {
    return *p;
  } else {
    V v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
}
template <typename V>
__attribute__((always_inline)) inline V LoadF(const float* p) {
  if constexpr (std::is_same_v<V, double>) {
    return static_cast<double>(*p);
  } else {
    // (GCC 12 turns __builtin_convertvector of a loaded F4 into two half conversions; this form
    // is one vcvtps2pd from memory.)
    return V4{static_cast<double>(p[0]), static_cast<double>(p[1]), static_cast<double>(p[2]),
              static_cast<double>(p[3])};
  }
}
template <typename V>
__attribute__((always_inline)) inline void Store(double* p, V v) {
  if constexpr (std::is_same_v<V, double>) {
    *p = v;
  } else {
    std::memcpy(p, &v, sizeof v);
  }
}
template <typename V>
__attribute__((always_inline)) inline void StoreF(float* p, V v) {
  if constexpr (std::is_same_v<V, double>) {
    *p = static_cast<float>(v);
  } else {
    const F4 f = __builtin_convertvector(v, F4);
    std::memcpy(p, &f, sizeof f);
  }
}
template <typename V>
__attribute__((always_inline)) inline V Splat(double x) {
  if constexpr (std::is_same_v<V, double>) {
    return x;
  } else {
    return V4{x, x, x, x};
  }
}
template <typename V>
__attribute__((always_inline)) inline V Max(V a, V b) {
  return a > b ? a : b;
}

// body(V(), k) for k in [0, len): vectors of four cells, then single cells.
template <typename Body>
__attribute__((always_inline)) inline void ForVectors(int len, Body&& body) {
  int k = 0;
  for (; k + 4 <= len; k += 4) body(V4{}, k);
  for (; k < len; ++k) body(0.0, k);
}

// Reductions kept per lane (a vector and a scalar), combined at the end.
struct MaxPair {
  V4 v = {0.0, 0.0, 0.0, 0.0};
  double s = 0.0;
  template <typename V>
  __attribute__((always_inline)) void Add(V x) {
    if constexpr (std::is_same_v<V, double>) {
      s = x > s ? x : s;
    } else {
      v = Max(v, x);
    }
  }
  double Value() const {
    const double a = v[0] > v[1] ? v[0] : v[1], b = v[2] > v[3] ? v[2] : v[3];
    const double c = a > b ? a : b;
    return c > s ? c : s;
  }
};
struct SumPair {
  V4 v = {0.0, 0.0, 0.0, 0.0};
  double s = 0.0;
  template <typename V>
  __attribute__((always_inline)) void Add(V x) {
    if constexpr (std::is_same_v<V, double>) {
      s += x;
    } else {
      v += x;
    }
  }
  double Value() const { return ((v[0] + v[1]) + (v[2] + v[3])) + s; }
};

// |r| / max(u, floor), infinite where that is <= 0 and r != 0 (infinitely wrong relative to
// the cell's value); branch-free selects.
template <typename V>
__attribute__((always_inline)) inline V Relative(V a, V u, double floor) {
  const V zero = Splat<V>(0.0), f = Splat<V>(floor);
  const V w = u > f ? u : f;
  const V safe = w > zero ? w : Splat<V>(1.0);
  const V ratio = a / safe;
  const V big = a > zero ? Splat<V>(__builtin_inf()) : zero;
  return w > zero ? ratio : big;
}

template <bool kNine, typename V, typename T>
__attribute__((always_inline)) inline V MeanV(const T* row, const T* up, const T* down, int k) {
  const auto ld = [](const T* p) {
    if constexpr (std::is_same_v<T, float>) {
      return LoadF<V>(p);
    } else {
      return Load<V>(p);
    }
  };
  if constexpr (kNine) {
    return Splat<V>(0.2) * ((ld(row + k - 1) + ld(row + k + 1)) + (ld(down + k) + ld(up + k))) +
           Splat<V>(0.05) *
               ((ld(down + k - 1) + ld(down + k + 1)) + (ld(up + k - 1) + ld(up + k + 1)));
  } else {
    return Splat<V>(0.25) * ((ld(row + k - 1) + ld(row + k + 1)) + (ld(down + k) + ld(up + k)));
  }
}

template <bool kNine, bool kMasked>
__attribute__((always_inline)) inline Norms TrueResidualT(const double* u, double* r, float* rs,
                                                          const float* mask, int nx,
                                                          const Run* runs, std::size_t count,
                                                          double floor) {
  MaxPair wa, wr;
  for (std::size_t q = 0; q < count; ++q) {
    const Run& run = runs[q];
    const std::ptrdiff_t base = static_cast<std::ptrdiff_t>(run.y) * nx + run.x0;
    const double* __restrict row = u + base;
    const double* __restrict up = row + nx;
    const double* __restrict down = row - nx;
    double* __restrict rr = r + base;
    float* __restrict rf = rs + base;
    const float* __restrict m = kMasked ? mask + base : nullptr;
    ForVectors(run.x1 - run.x0, [&](auto tag, int k) {
      using V = decltype(tag);
      V v = MeanV<kNine, V>(row, up, down, k) - Load<V>(row + k);
      if constexpr (kMasked) v *= LoadF<V>(m + k);
      Store(rr + k, v);
      StoreF(rf + k, v);
      const V a = v < Splat<V>(0.0) ? -v : v;
      wa.Add(a);
      wr.Add(Relative(a, Load<V>(row + k), floor));
    });
  }
  return {wa.Value(), wr.Value()};
}

template <bool kNine, bool kDeficit>
__attribute__((always_inline)) inline Norms ResidualNormsT(const double* u, int nx, const Run* runs,
                                                           std::size_t count, double floor) {
  MaxPair wa, wr;
  SumPair stuck;  // kDeficit: cells judged (>= floor) without a strictly higher 4-neighbour
  for (std::size_t q = 0; q < count; ++q) {
    const Run& run = runs[q];
    const std::ptrdiff_t base = static_cast<std::ptrdiff_t>(run.y) * nx + run.x0;
    const double* __restrict row = u + base;
    const double* __restrict up = row + nx;
    const double* __restrict down = row - nx;
    ForVectors(run.x1 - run.x0, [&](auto tag, int k) {
      using V = decltype(tag);
      const V c = Load<V>(row + k);
      const V v = MeanV<kNine, V>(row, up, down, k) - c;
      const V a = v < Splat<V>(0.0) ? -v : v;
      wa.Add(a);
      wr.Add(Relative(a, c, floor));
      if constexpr (kDeficit) {
        const V best = Max(Max(Load<V>(row + k - 1), Load<V>(row + k + 1)),
                           Max(Load<V>(down + k), Load<V>(up + k)));
        const V zero = Splat<V>(0.0), one = Splat<V>(1.0);
        if constexpr (std::is_same_v<V, double>) {
          const bool bad = (floor <= 0.0 || c >= floor) && (!(best > c) || !(c > 0.0));
          stuck.Add(bad ? 1.0 : 0.0);
        } else {
          const auto judged = floor <= 0.0 ? (c == c) : (c >= Splat<V>(floor));
          const auto bad = judged & ((best <= c) | (c <= zero));
          stuck.Add(bad ? one : zero);
        }
      }
    });
  }
  Norms n{wa.Value(), wr.Value()};
  if constexpr (kDeficit) n.deficit = static_cast<std::size_t>(stuck.Value());
  return n;
}

inline std::size_t AscentDeficitT(const double* u, int nx, const Run* runs, std::size_t count,
                                  double floor) {
  std::size_t deficit = 0;
  for (std::size_t q = 0; q < count; ++q) {
    const Run& run = runs[q];
    const std::ptrdiff_t base = static_cast<std::ptrdiff_t>(run.y) * nx + run.x0;
    const double* __restrict row = u + base;
    const double* __restrict up = row + nx;
    const double* __restrict down = row - nx;
    const int len = run.x1 - run.x0;
    std::uint32_t bad = 0;
    for (int k = 0; k < len; ++k) {
      const double a = row[k - 1] > row[k + 1] ? row[k - 1] : row[k + 1];
      const double b = down[k] > up[k] ? down[k] : up[k];
      const double best = a > b ? a : b;
      const double v = row[k];
      const bool counted = floor <= 0.0 || v >= floor;  // below the focus: not needed
      const bool stuck = !(best > v) || !(v > 0.0);
      bad += (counted && stuck) ? 1u : 0u;
    }
    deficit += bad;
  }
  return deficit;
}

template <bool kNine>
inline void RegularT(const std::uint8_t* active, std::uint8_t* regular, int nx, const Run* runs,
                     std::size_t count) {
  for (std::size_t q = 0; q < count; ++q) {
    const Run& run = runs[q];
    const std::ptrdiff_t base = static_cast<std::ptrdiff_t>(run.y) * nx + run.x0;
    const std::uint8_t* __restrict a = active + base;
    const std::uint8_t* __restrict up = a + nx;
    const std::uint8_t* __restrict down = a - nx;
    std::uint8_t* __restrict out = regular + base;
    const int len = run.x1 - run.x0;
    for (int k = 0; k < len; ++k) {
      std::uint8_t v = a[k - 1] & a[k + 1] & up[k] & down[k];
      if constexpr (kNine) v &= up[k - 1] & up[k + 1] & down[k - 1] & down[k + 1];
      out[k] = v;
    }
  }
}

template <bool kNine, bool kMasked>
__attribute__((always_inline)) inline double DirectionT(const float* z, double* d, double* q,
                                                        const float* mask, double beta, int nx,
                                                        const Run* runs, std::size_t count) {
  SumPair dq;
  for (std::size_t c = 0; c < count; ++c) {
    const Run& run = runs[c];
    const std::ptrdiff_t base = static_cast<std::ptrdiff_t>(run.y) * nx + run.x0;
    const float* __restrict row = z + base;
    const float* __restrict up = row + nx;
    const float* __restrict down = row - nx;
    double* __restrict dd = d + base;
    double* __restrict qq = q + base;
    const float* __restrict m = kMasked ? mask + base : nullptr;
    ForVectors(run.x1 - run.x0, [&](auto tag, int k) {
      using V = decltype(tag);
      const V zk = LoadF<V>(row + k);
      V az = zk - MeanV<kNine, V>(row, up, down, k);
      if constexpr (kMasked) az *= LoadF<V>(m + k);
      const V b = Splat<V>(beta);
      const V dn = zk + b * Load<V>(dd + k);
      const V qn = az + b * Load<V>(qq + k);
      Store(dd + k, dn);
      Store(qq + k, qn);
      dq.Add(dn * qn);
    });
  }
  return dq.Value();
}

__attribute__((always_inline)) inline Norms UpdateT(double* u, const double* d, double* r,
                                                    const double* q, float* rs, double alpha,
                                                    int nx, const Run* runs, std::size_t count,
                                                    double floor) {
  MaxPair wa, wr;
  for (std::size_t c = 0; c < count; ++c) {
    const Run& run = runs[c];
    const std::ptrdiff_t base = static_cast<std::ptrdiff_t>(run.y) * nx + run.x0;
    double* __restrict uu = u + base;
    const double* __restrict dd = d + base;
    double* __restrict rr = r + base;
    const double* __restrict qq = q + base;
    float* __restrict rf = rs + base;
    ForVectors(run.x1 - run.x0, [&](auto tag, int k) {
      using V = decltype(tag);
      const V al = Splat<V>(alpha);
      const V un = Load<V>(uu + k) + al * Load<V>(dd + k);
      const V rn = Load<V>(rr + k) - al * Load<V>(qq + k);
      Store(uu + k, un);
      Store(rr + k, rn);
      StoreF(rf + k, rn);
      const V a = rn < Splat<V>(0.0) ? -rn : rn;
      wa.Add(a);
      wr.Add(Relative(a, un, floor));
    });
  }
  return {wa.Value(), wr.Value()};
}

__attribute__((always_inline)) inline void DotsT(const double* r, const float* z,
                                                 const float* z_old, int nx, const Run* runs,
                                                 std::size_t count, double* rz, double* rz_old) {
  SumPair a, b;
  for (std::size_t c = 0; c < count; ++c) {
    const Run& run = runs[c];
    const std::ptrdiff_t base = static_cast<std::ptrdiff_t>(run.y) * nx + run.x0;
    const double* __restrict rr = r + base;
    const float* __restrict zz = z + base;
    const float* __restrict zo = z_old + base;
    ForVectors(run.x1 - run.x0, [&](auto tag, int k) {
      using V = decltype(tag);
      const V rk = Load<V>(rr + k);
      a.Add(rk * LoadF<V>(zz + k));
      b.Add(rk * LoadF<V>(zo + k));
    });
  }
  *rz = a.Value();
  *rz_old = b.Value();
}

}  // namespace

SPOTT_CLONES Norms TrueResidual(const double* u, double* r, float* rs, const float* mask, int nx,
                                const Run* runs, std::size_t count, bool nine, double floor) {
  if (mask) {
    return nine ? TrueResidualT<true, true>(u, r, rs, mask, nx, runs, count, floor)
                : TrueResidualT<false, true>(u, r, rs, mask, nx, runs, count, floor);
  }
  return nine ? TrueResidualT<true, false>(u, r, rs, mask, nx, runs, count, floor)
              : TrueResidualT<false, false>(u, r, rs, mask, nx, runs, count, floor);
}

SPOTT_CLONES Norms ResidualNorms(const double* u, int nx, const Run* runs, std::size_t count,
                                 bool nine, double floor, bool with_deficit) {
  if (with_deficit) {
    return nine ? ResidualNormsT<true, true>(u, nx, runs, count, floor)
                : ResidualNormsT<false, true>(u, nx, runs, count, floor);
  }
  return nine ? ResidualNormsT<true, false>(u, nx, runs, count, floor)
              : ResidualNormsT<false, false>(u, nx, runs, count, floor);
}

SPOTT_CLONES std::size_t AscentDeficit(const double* u, int nx, const Run* runs, std::size_t count,
                                       double floor) {
  return AscentDeficitT(u, nx, runs, count, floor);
}

SPOTT_CLONES void Regular(const std::uint8_t* active, std::uint8_t* regular, int nx,
                          const Run* runs, std::size_t count, bool nine) {
  nine ? RegularT<true>(active, regular, nx, runs, count)
       : RegularT<false>(active, regular, nx, runs, count);
}

SPOTT_CLONES double Direction(const float* z, double* d, double* q, const float* mask, double beta,
                              int nx, const Run* runs, std::size_t count, bool nine) {
  if (mask) {
    return nine ? DirectionT<true, true>(z, d, q, mask, beta, nx, runs, count)
                : DirectionT<false, true>(z, d, q, mask, beta, nx, runs, count);
  }
  return nine ? DirectionT<true, false>(z, d, q, mask, beta, nx, runs, count)
              : DirectionT<false, false>(z, d, q, mask, beta, nx, runs, count);
}

SPOTT_CLONES Norms Update(double* u, const double* d, double* r, const double* q, float* rs,
                          double alpha, int nx, const Run* runs, std::size_t count, double floor) {
  return UpdateT(u, d, r, q, rs, alpha, nx, runs, count, floor);
}

SPOTT_CLONES void Dots(const double* r, const float* z, const float* z_old, int nx, const Run* runs,
                       std::size_t count, double* rz, double* rz_old) {
  DotsT(r, z, z_old, nx, runs, count, rz, rz_old);
}

}  // namespace spott_harmonic_planner::internal::kernels
