// The inner loops of MarkovGrid's updates over one orientation layer (private to the core).
//
// Each loop comes in a portable version and, on x86-64, in AVX2 and AVX-512 versions chosen at
// run time from what the CPU supports (the binary is built for the baseline x86-64 and runs
// anywhere). Every version computes each cell with the same float operations in the same order
// as the plain loop it replaces, so the belief is the same bit for bit; only the double sums
// over a layer are added in another order (lanes, then a fixed reduction), so normalizers
// differ by rounding (~1e-16 relative). Results never depend on the thread count: per-layer
// sums are combined in layer order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace markov_localization {
namespace kernels {

enum class Isa { kScalar = 0, kAvx2 = 1, kAvx512 = 2 };

/// The best version this CPU runs.
Isa SupportedIsa();
/// The version in use (SupportedIsa() unless forced).
Isa ActiveIsa();
/// Tests and benchmarks: use `isa` (clamped to SupportedIsa()); returns the one in use.
Isa ForceIsa(Isa isa);
const char* IsaName(Isa isa);

/// Runs [begin, end) of state cells in `state_mask` as pairs (begin0, end0, begin1, ...), gaps
/// shorter than `min_gap` cells bridged; together they cover every state cell.
std::vector<std::uint32_t> StateSpans(const std::vector<std::uint8_t>& state_mask,
                                      std::size_t min_gap);

/// Columns of the sensor update are stored with this stride (floats per beam) when the table
/// has at most kPermuteBins range bins (the AVX-512 version then looks them up in registers).
constexpr int kPermuteBins = 64;

struct SensorLayerIn {
  float* data;                      // the layer's P(l), updated in place
  std::uint8_t* flags;              // out: 1 where P(s|l) was applied (state cells)
  const std::uint8_t* const* rows;  // expected range bin of each cell, per beam
  const float* columns;             // [beam][column_stride]: factor per expected bin
  int beams;
  int column_stride;
  float theta;                 // cells <= theta keep their value (eq. (4))
  const std::uint32_t* spans;  // runs [spans[2i], spans[2i + 1]) of cells
  std::size_t num_spans;
};

struct SensorLayerOut {
  double likely = 0.0;    // sum of the updated values
  double unlikely = 0.0;  // sum of the values left out
  std::size_t evaluated = 0;
};

/// Eq. (2)/(4) over one layer: where data > theta, data *= prod_b columns[b][rows[b][c]]
/// (multiplied in beam order starting from 1, then times data), flags = 1; elsewhere flags = 0.
SensorLayerOut SensorLayer(const SensorLayerIn& in);

/// Normalization after the sensor update: state cells become max(floor, data * (flags ?
/// a_likely : a_unlikely)); other cells are untouched (they hold 0). Returns the layer's
/// largest value afterwards.
float ScaleLayer(float* data, const std::uint8_t* flags, const std::uint8_t* state_mask,
                 const std::uint32_t* spans, std::size_t num_spans, float a_likely,
                 float a_unlikely, float floor);

// ---- motion update: plain loops the compiler vectorizes, one version per ISA (target_clones).
// Lanes never mix a cell's arithmetic, so every version gives the same floats; sums use eight
// double accumulators (cell i to accumulator i mod 8) added in a fixed order.

/// Bilinear shift of a w x h layer by (ox + fx, oy + fy) cells, in gather form: out(tx, ty) =
/// ((in(tx-ox-1, ty-oy-1) w11 + in(tx-ox, ty-oy-1) w01) + in(tx-ox-1, ty-oy) w10) + in(tx-ox,
/// ty-oy) w00, sources outside the layer 0 (the order in which the former scatter added them).
void ShiftBilinear(const float* in, float* out, int w, int h, int ox, int oy, float w00, float w10,
                   float w01, float w11);

/// `passes` 3-tap passes [k, 1 - 2k, k] along x (each row) or y (each column), zero outside;
/// new = k (left + right) + (1 - 2k) centre. `line` is scratch.
void BlurX(float* data, int w, int h, int passes, float k, std::vector<float>& line);
void BlurY(float* data, int w, int h, int passes, float k, std::vector<float>& line);

/// dst = mask ? src : 0.
void MaskedCopy(float* dst, const float* src, const std::uint8_t* mask, std::size_t n);

/// One heading-noise pass of a layer: dst = ((c0 cur) + k prev) + k next, a missing neighbour
/// (nullptr) left out. Returns the sum of dst.
double HeadingBlend(float* dst, const float* cur, const float* prev, const float* next, float c0,
                    float k, std::size_t n);

double Sum(const float* data, std::size_t n);
float Max(const float* data, std::size_t n);
void Scale(float* data, std::size_t n, float factor);

}  // namespace kernels
}  // namespace markov_localization
