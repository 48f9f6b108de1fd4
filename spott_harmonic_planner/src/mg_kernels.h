// Vectorizable inner loops of the multigrid hierarchy (private to the library). Each works on
// the runs of unknowns of one level (rows of consecutive unknowns), so obstacles cost nothing,
// with unit-stride loops the compiler turns into SIMD; a colour pass computes a whole run and
// blends the colour's cells in (their neighbours are of the other colours, so the computed
// values are exactly the Gauss-Seidel updates). On x86-64 every kernel is compiled twice, for
// AVX2 + FMA and for the baseline, and picked at load time.
#pragma once

#include <cstddef>
#include <cstdint>

namespace spott_harmonic_planner::internal {

struct Run {
  int y;
  int x0;  ///< first unknown
  int x1;  ///< one past the last
};

/// The symmetric 9-point operator of a coarse level: a(i,i) = 1 / inv_diag[i], a(i,i+1) = e[i],
/// a(i,i+nx) = n[i], a(i,i+nx+1) = ne[i], a(i,i+nx-1) = nw[i]; zero towards fixed cells.
template <typename T>
struct Stencil9 {
  const T* diag;
  const T* inv_diag;
  const T* e;
  const T* n;
  const T* ne;
  const T* nw;
};

namespace kernels {

// Level 0, 5-point normalized stencil (A = I - M, M = neighbour mean / 4): u = M u + f on the
// cells of one colour ((x + y) & 1 == colour). The runs may span fixed cells when `mask`
// (1 on unknowns, 0 on fixed cells) is given: one run per row, fewer loop starts on small or
// cluttered grids. `tmp` holds at least nx values.
void Colour5(float* u, const float* f, const float* mask, int nx, const Run* runs,
             std::size_t count, int colour, float* tmp);
void Colour5(double* u, const double* f, const double* mask, int nx, const Run* runs,
             std::size_t count, int colour, double* tmp);
/// The first red-black sweep from u = 0: u = f on colour 0, then u = M u + f on colour 1.
void FirstSweep5(float* u, const float* f, const float* mask, int nx, const Run* runs,
                 std::size_t count, float* tmp);
/// r = f - A u (masked like Colour5).
void Residual5(const float* u, const float* f, const float* mask, float* r, int nx, const Run* runs,
               std::size_t count);
void Residual5(const double* u, const double* f, const double* mask, double* r, int nx,
               const Run* runs, std::size_t count);

// 9-point levels (the Galerkin coarse levels; level 0 of the 9-point stencil uses them too with
// its constant coefficients stored): four colours (x parity px, y parity py).
void Colour9(float* u, const float* f, int nx, const Run* runs, std::size_t count, int px, int py,
             const Stencil9<float>& a, float* tmp);
void Colour9(double* u, const double* f, int nx, const Run* runs, std::size_t count, int px, int py,
             const Stencil9<double>& a, double* tmp);
void Residual9(const float* u, const float* f, float* r, int nx, const Run* runs, std::size_t count,
               const Stencil9<float>& a);
void Residual9(const double* u, const double* f, double* r, int nx, const Run* runs,
               std::size_t count, const Stencil9<double>& a);

/// Coarse right-hand side: fc = P^T r (bilinear weights 1, 1/2, 1/4; factor 1 in a direction
/// that is not coarsened). `tmp` holds at least fine nx values.
void Restrict(const float* r, int fnx, float* fc, int cnx, const Run* coarse_runs,
              std::size_t count, int sx, int sy, float* tmp);
void Restrict(const double* r, int fnx, double* fc, int cnx, const Run* coarse_runs,
              std::size_t count, int sx, int sy, double* tmp);
/// u += P uc on the fine unknowns (times `mask` when given). `tmp` holds at least 3 fine nx.
void Prolongate(const float* uc, int cnx, float* u, const float* mask, int fnx,
                const Run* fine_runs, std::size_t count, int sx, int sy, float* tmp);
void Prolongate(const double* uc, int cnx, double* u, const double* mask, int fnx,
                const Run* fine_runs, std::size_t count, int sx, int sy, double* tmp);

// Galerkin coarse operator of one coarse row (hierarchy.cpp explains the formulas). Fine
// coefficients of level 0's 5-point stencil from its mask row and the row above.
void Fine5(const std::uint8_t* mask, const std::uint8_t* mask_up, float* d, float* e, float* n,
           int len);
void Fine5(const std::uint8_t* mask, const std::uint8_t* mask_up, double* d, double* e, double* n,
           int len);
/// The x stage: fine columns 0 .. 2 count (coarse column t on fine 2 t + 1) to B. `ne`, `nw`
/// may be null (zero).
void GalerkinX(const float* d, const float* e, const float* n, const float* ne, const float* nw,
               float* bd, float* be, float* bn, float* bne, float* bnw, int count);
void GalerkinX(const double* d, const double* e, const double* n, const double* ne,
               const double* nw, double* bd, double* be, double* bn, double* bne, double* bnw,
               int count);
/// The y stage: B on the rows below (0), on (1) and above (2) the coarse row, each indexed
/// by local column k (coarse column X0 - 1 + k), k = 1 .. count; writes the coarse row.
struct GalerkinRows {
  const float* d[3];
  const float* e[3];
  const float* n[3];
  const float* ne[3];
  const float* nw[3];
};
struct GalerkinRowsD {
  const double* d[3];
  const double* e[3];
  const double* n[3];
  const double* ne[3];
  const double* nw[3];
};
void GalerkinY(const GalerkinRows& b, float* diag, float* inv_diag, float* e, float* n, float* ne,
               float* nw, int count);
void GalerkinY(const GalerkinRowsD& b, double* diag, double* inv_diag, double* e, double* n,
               double* ne, double* nw, int count);

// Map ingest (potential_field.cpp): blocked = raster cell != 0 or on the window's border ring.
/// Whether `blocked` differs from what `cells` gives.
bool BlockedDiffers(const std::uint8_t* cells, const std::uint8_t* blocked, int nx, int ny);
/// blocked from `cells`, and kind = 1 (obstacle) or 3 (unreachable) from blocked.
void SetBlocked(const std::uint8_t* cells, std::uint8_t* blocked, std::uint8_t* kind, int nx,
                int ny);

// Conjugate gradients on the fine level (double, the preconditioner's output z in float), for
// the normalized 5-point (nine = false) or 9-point stencil; fixed cells of every vector are 0.
struct Norms {
  double absolute = 0.0;  ///< max |r|
  /// max |r| / max(u, floor) (infinite where that is <= 0 and r != 0): relative to each cell's
  /// value, or to `floor` where the value is smaller (the field's start focus; 0: none).
  double relative = 0.0;
  /// ResidualNorms with `with_deficit`: the unknowns AscentDeficit counts.
  std::size_t deficit = 0;
};
// The conjugate-gradient kernels may run over spans that hold fixed cells too (one span over
// the whole interior of a mostly free window: no loop start per row): `mask` (1 on unknowns, 0
// on fixed cells) then keeps r and q at 0 there, and d, q, r stay 0 on fixed cells.
/// r = M u - u (u holds the Dirichlet values on fixed cells), times `mask` when given;
/// rs = (float) r; returns the norms.
Norms TrueResidual(const double* u, double* r, float* rs, const float* mask, int nx,
                   const Run* runs, std::size_t count, bool nine, double floor);
/// The norms of M u - u without storing it (and the ascent deficit in the same pass).
Norms ResidualNorms(const double* u, int nx, const Run* runs, std::size_t count, bool nine,
                    double floor, bool with_deficit = false);
/// Unknowns with u >= floor (all of them when floor is 0) that have u <= 0 or no strictly larger
/// 4-neighbour: the cells where discrete ascent towards the goal could stop.
std::size_t AscentDeficit(const double* u, int nx, const Run* runs, std::size_t count,
                          double floor);
/// regular[i] = the unknown i has all its stencil neighbours unknowns too (level 0).
void Regular(const std::uint8_t* active, std::uint8_t* regular, int nx, const Run* runs,
             std::size_t count, bool nine);
/// d = z + beta d, q = A z + beta q (A z times `mask` when given); returns d . q.
double Direction(const float* z, double* d, double* q, const float* mask, double beta, int nx,
                 const Run* runs, std::size_t count, bool nine);
/// u += alpha d, r -= alpha q, rs = (float) r; returns the norms of the new r.
Norms Update(double* u, const double* d, double* r, const double* q, float* rs, double alpha,
             int nx, const Run* runs, std::size_t count, double floor);
/// Sum r z and sum r z_old.
void Dots(const double* r, const float* z, const float* z_old, int nx, const Run* runs,
          std::size_t count, double* rz, double* rz_old);

}  // namespace kernels
}  // namespace spott_harmonic_planner::internal
