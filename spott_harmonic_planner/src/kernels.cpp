#include "kernels.h"

namespace spott_harmonic_planner::kernels {

namespace {

// Rows are distinct memory, so the row pointers may be declared non-aliasing; within a row the
// written cells (one colour) and the read neighbours (other colours) never coincide.
template <bool kHasRhs>
void ColourPass5(int nx, int ny, double* u, const double* f, const double* w, int colour) {
  for (int y = 1; y < ny - 1; ++y) {
    double* __restrict row = u + static_cast<std::ptrdiff_t>(y) * nx;
    const double* __restrict up = row + nx;
    const double* __restrict down = row - nx;
    const double* __restrict wr = w + static_cast<std::ptrdiff_t>(y) * nx;
    const double* __restrict fr = kHasRhs ? f + static_cast<std::ptrdiff_t>(y) * nx : nullptr;
    const int x0 = ((1 + y) & 1) == colour ? 1 : 2;
    for (int x = x0; x < nx - 1; x += 2) {
      double m = 0.25 * ((row[x - 1] + row[x + 1]) + (down[x] + up[x]));
      if constexpr (kHasRhs) m += fr[x];
      row[x] += wr[x] * (m - row[x]);
    }
  }
}

template <bool kHasRhs>
void ColourPass9(int nx, int ny, double* u, const double* f, const double* w, int colour) {
  const int px = colour & 1;
  const int py = colour >> 1;
  for (int y = 1 + ((1 + py) & 1); y < ny - 1; y += 2) {
    double* __restrict row = u + static_cast<std::ptrdiff_t>(y) * nx;
    const double* __restrict up = row + nx;
    const double* __restrict down = row - nx;
    const double* __restrict wr = w + static_cast<std::ptrdiff_t>(y) * nx;
    const double* __restrict fr = kHasRhs ? f + static_cast<std::ptrdiff_t>(y) * nx : nullptr;
    const int x0 = 1 + ((1 + px) & 1);
    for (int x = x0; x < nx - 1; x += 2) {
      double m = 0.2 * ((row[x - 1] + row[x + 1]) + (down[x] + up[x])) +
                 0.05 * ((down[x - 1] + down[x + 1]) + (up[x - 1] + up[x + 1]));
      if constexpr (kHasRhs) m += fr[x];
      row[x] += wr[x] * (m - row[x]);
    }
  }
}

}  // namespace

void ColourPass(Stencil s, int nx, int ny, double* u, const double* f, const double* w,
                int colour) {
  if (s == Stencil::kFivePoint) {
    f ? ColourPass5<true>(nx, ny, u, f, w, colour) : ColourPass5<false>(nx, ny, u, f, w, colour);
  } else {
    f ? ColourPass9<true>(nx, ny, u, f, w, colour) : ColourPass9<false>(nx, ny, u, f, w, colour);
  }
}

double Residual(Stencil s, int nx, int ny, const double* u, const double* f,
                const std::uint8_t* free, double* r) {
  double worst = 0.0;
  for (int y = 1; y < ny - 1; ++y) {
    const std::ptrdiff_t base = static_cast<std::ptrdiff_t>(y) * nx;
    const double* __restrict row = u + base;
    const double* __restrict up = row + nx;
    const double* __restrict down = row - nx;
    const std::uint8_t* __restrict fr = free + base;
    double* __restrict rr = r ? r + base : nullptr;
    for (int x = 1; x < nx - 1; ++x) {
      double m;
      if (s == Stencil::kFivePoint) {
        m = 0.25 * ((row[x - 1] + row[x + 1]) + (down[x] + up[x]));
      } else {
        m = 0.2 * ((row[x - 1] + row[x + 1]) + (down[x] + up[x])) +
            0.05 * ((down[x - 1] + down[x + 1]) + (up[x - 1] + up[x + 1]));
      }
      if (f) m += f[base + x];
      const double v = fr[x] ? m - row[x] : 0.0;
      if (rr) rr[x] = v;
      worst = std::max(worst, std::abs(v));
    }
  }
  return worst;
}

}  // namespace spott_harmonic_planner::kernels
