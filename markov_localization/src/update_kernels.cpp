#include "update_kernels.h"

#include <algorithm>
#include <atomic>

#if defined(__x86_64__) && defined(__GNUC__)
#define MARKOV_X86_KERNELS 1
#include <immintrin.h>
// GCC 12's AVX-512 intrinsics start from _mm512_undefined_*: false "uninitialized" warnings.
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

namespace markov_localization {
namespace kernels {

namespace {

Isa DetectIsa() {
#ifdef MARKOV_X86_KERNELS
  __builtin_cpu_init();  // also checks that the OS saves the AVX/AVX-512 registers
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
      __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512dq"))
    return Isa::kAvx512;
  if (__builtin_cpu_supports("avx2")) return Isa::kAvx2;
#endif
  return Isa::kScalar;
}

std::atomic<int>& ActiveSlot() {
  static std::atomic<int> slot{static_cast<int>(DetectIsa())};
  return slot;
}

// ---- portable versions (also the tails of the vector versions) --------------------------------

void SensorCells(const SensorLayerIn& in, std::size_t begin, std::size_t end, SensorLayerOut& out) {
  float* data = in.data;
  for (std::size_t c = begin; c < end; ++c) {
    const float p = data[c];
    // Eq. (4): cells at or below theta keep P(l) (their factor P~(s)/P~(s) = 1).
    if (p <= in.theta) {
      out.unlikely += p;
      in.flags[c] = 0;
      continue;
    }
    in.flags[c] = 1;
    float l = 1.0f;
    for (int b = 0; b < in.beams; ++b) l *= in.columns[b * in.column_stride + in.rows[b][c]];
    const float v = p * l;
    data[c] = v;
    out.likely += v;
    ++out.evaluated;
  }
}

float ScaleCells(float* data, const std::uint8_t* flags, const std::uint8_t* mask,
                 std::size_t begin, std::size_t end, float a_likely, float a_unlikely, float floor,
                 float mx) {
  for (std::size_t c = begin; c < end; ++c) {
    if (!mask[c]) continue;
    // Which factor a cell gets depends on whether it was updated; its value before was
    // <= theta exactly when it was left out. A floor keeps every state recoverable.
    data[c] = std::max(floor, data[c] * (flags[c] ? a_likely : a_unlikely));
    mx = std::max(mx, data[c]);
  }
  return mx;
}

SensorLayerOut SensorLayerScalar(const SensorLayerIn& in) {
  SensorLayerOut out;
  for (std::size_t s = 0; s < in.num_spans; ++s)
    SensorCells(in, in.spans[2 * s], in.spans[2 * s + 1], out);
  return out;
}

float ScaleLayerScalar(float* data, const std::uint8_t* flags, const std::uint8_t* mask,
                       const std::uint32_t* spans, std::size_t num_spans, float a_likely,
                       float a_unlikely, float floor) {
  float mx = 0.0f;
  for (std::size_t s = 0; s < num_spans; ++s)
    mx = ScaleCells(data, flags, mask, spans[2 * s], spans[2 * s + 1], a_likely, a_unlikely, floor,
                    mx);
  return mx;
}

#ifdef MARKOV_X86_KERNELS

// ---- AVX2: 8 cells at a time, the columns looked up by gathers ---------------------------------

__attribute__((target("avx2"))) SensorLayerOut SensorLayerAvx2(const SensorLayerIn& in) {
  SensorLayerOut out;
  const __m256 theta = _mm256_set1_ps(in.theta);
  const __m256 one = _mm256_set1_ps(1.0f);
  __m256d likely = _mm256_setzero_pd(), unlikely = _mm256_setzero_pd();
  float* data = in.data;
  for (std::size_t s = 0; s < in.num_spans; ++s) {
    std::size_t c = in.spans[2 * s];
    const std::size_t end = in.spans[2 * s + 1];
    for (; c + 8 <= end; c += 8) {
      const __m256 p = _mm256_loadu_ps(data + c);
      const __m256 upd = _mm256_cmp_ps(p, theta, _CMP_NLE_UQ);  // !(p <= theta)
      const int m = _mm256_movemask_ps(upd);
      if (m == 0) {
        unlikely = _mm256_add_pd(unlikely, _mm256_cvtps_pd(_mm256_castps256_ps128(p)));
        unlikely = _mm256_add_pd(unlikely, _mm256_cvtps_pd(_mm256_extractf128_ps(p, 1)));
        _mm_storel_epi64(reinterpret_cast<__m128i*>(in.flags + c), _mm_setzero_si128());
        continue;
      }
      __m256 l = one;
      for (int b = 0; b < in.beams; ++b) {
        const __m128i e8 = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(in.rows[b] + c));
        const __m256i e = _mm256_cvtepu8_epi32(e8);
        l = _mm256_mul_ps(l, _mm256_i32gather_ps(in.columns + b * in.column_stride, e, 4));
      }
      const __m256 v = _mm256_mul_ps(p, l);
      const __m256 stored = _mm256_blendv_ps(p, v, upd);
      _mm256_storeu_ps(data + c, stored);
      const __m256 lv = _mm256_and_ps(upd, v), up = _mm256_andnot_ps(upd, p);
      likely = _mm256_add_pd(likely, _mm256_cvtps_pd(_mm256_castps256_ps128(lv)));
      likely = _mm256_add_pd(likely, _mm256_cvtps_pd(_mm256_extractf128_ps(lv, 1)));
      unlikely = _mm256_add_pd(unlikely, _mm256_cvtps_pd(_mm256_castps256_ps128(up)));
      unlikely = _mm256_add_pd(unlikely, _mm256_cvtps_pd(_mm256_extractf128_ps(up, 1)));
      // flags: one byte per cell, 1 where updated.
      const __m256i f32 = _mm256_srli_epi32(_mm256_castps_si256(upd), 31);
      const __m128i f16 =
          _mm_packus_epi32(_mm256_castsi256_si128(f32), _mm256_extracti128_si256(f32, 1));
      _mm_storel_epi64(reinterpret_cast<__m128i*>(in.flags + c), _mm_packus_epi16(f16, f16));
      out.evaluated += static_cast<std::size_t>(__builtin_popcount(m));
    }
    SensorCells(in, c, end, out);
  }
  alignas(32) double l4[4], u4[4];
  _mm256_store_pd(l4, likely);
  _mm256_store_pd(u4, unlikely);
  out.likely += (l4[0] + l4[1]) + (l4[2] + l4[3]);
  out.unlikely += (u4[0] + u4[1]) + (u4[2] + u4[3]);
  return out;
}

__attribute__((target("avx2"))) float ScaleLayerAvx2(float* data, const std::uint8_t* flags,
                                                     const std::uint8_t* mask,
                                                     const std::uint32_t* spans,
                                                     std::size_t num_spans, float a_likely,
                                                     float a_unlikely, float floor) {
  const __m256 al = _mm256_set1_ps(a_likely), au = _mm256_set1_ps(a_unlikely);
  const __m256 fl = _mm256_set1_ps(floor);
  __m256 vmx = _mm256_setzero_ps();
  float mx = 0.0f;
  for (std::size_t s = 0; s < num_spans; ++s) {
    std::size_t c = spans[2 * s];
    const std::size_t end = spans[2 * s + 1];
    for (; c + 8 <= end; c += 8) {
      const __m256i f =
          _mm256_cvtepu8_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(flags + c)));
      const __m256i st =
          _mm256_cvtepu8_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(mask + c)));
      const __m256 updated = _mm256_castsi256_ps(_mm256_cmpgt_epi32(f, _mm256_setzero_si256()));
      const __m256 state = _mm256_castsi256_ps(_mm256_cmpgt_epi32(st, _mm256_setzero_si256()));
      const __m256 d = _mm256_loadu_ps(data + c);
      // std::max(floor, x) is x when floor < x, else floor: _mm256_max_ps(x, floor) likewise.
      const __m256 nv = _mm256_max_ps(_mm256_mul_ps(d, _mm256_blendv_ps(au, al, updated)), fl);
      const __m256 r = _mm256_blendv_ps(d, nv, state);
      _mm256_storeu_ps(data + c, r);
      vmx = _mm256_max_ps(vmx, r);
    }
    mx = ScaleCells(data, flags, mask, c, end, a_likely, a_unlikely, floor, mx);
  }
  alignas(32) float m8[8];
  _mm256_store_ps(m8, vmx);
  for (float v : m8) mx = std::max(mx, v);
  return mx;
}

// ---- AVX-512: 16 cells at a time; columns of <= 64 bins looked up in registers -----------------

#define MARKOV_AVX512 __attribute__((target("avx512f,avx512bw,avx512vl,avx512dq")))

// The likelihood products of NC chunks of 16 cells, kept in registers while the beams are
// applied in order (a column's four registers serve all NC chunks). NC > 1: full chunks only.
template <int NC>
MARKOV_AVX512 inline void ProductsAvx512(const SensorLayerIn& in, std::size_t c0,
                                         const __mmask16* lanes, __m512* l) {
  const __m512i bit5 = _mm512_set1_epi32(32);
  __m512 acc[NC];  // local (not through `l`, which may alias the columns): kept in registers
#pragma GCC unroll 8
  for (int k = 0; k < NC; ++k) acc[k] = _mm512_set1_ps(1.0f);
  for (int b = 0; b < in.beams; ++b) {
    const float* t = in.columns + b * in.column_stride;
    const std::uint8_t* row = in.rows[b] + c0;
    if (in.column_stride == kPermuteBins) {
      const __m512 t0 = _mm512_loadu_ps(t), t1 = _mm512_loadu_ps(t + 16);
      const __m512 t2 = _mm512_loadu_ps(t + 32), t3 = _mm512_loadu_ps(t + 48);
#pragma GCC unroll 8
      for (int k = 0; k < NC; ++k) {
        const __m512i e = _mm512_cvtepu8_epi32(
            NC > 1 ? _mm_loadu_si128(reinterpret_cast<const __m128i*>(row + 16 * k))
                   : _mm_maskz_loadu_epi8(lanes[k], row + 16 * k));
        const __m512 lo = _mm512_permutex2var_ps(t0, e, t1);
        const __m512 hi = _mm512_permutex2var_ps(t2, e, t3);
        const __m512 f = _mm512_mask_blend_ps(_mm512_test_epi32_mask(e, bit5), lo, hi);
        acc[k] = _mm512_mul_ps(acc[k], f);
      }
    } else {
#pragma GCC unroll 8
      for (int k = 0; k < NC; ++k) {
        const __m512i e = _mm512_cvtepu8_epi32(
            NC > 1 ? _mm_loadu_si128(reinterpret_cast<const __m128i*>(row + 16 * k))
                   : _mm_maskz_loadu_epi8(lanes[k], row + 16 * k));
        const __m512 f = _mm512_i32gather_ps(e, t, 4);
        acc[k] = _mm512_mul_ps(acc[k], f);
      }
    }
  }
#pragma GCC unroll 8
  for (int k = 0; k < NC; ++k) l[k] = acc[k];
}

MARKOV_AVX512 SensorLayerOut SensorLayerAvx512(const SensorLayerIn& in) {
  constexpr int kChunks = 8;  // cells in blocks of 8 x 16
  SensorLayerOut out;
  const __m512 theta = _mm512_set1_ps(in.theta);
  __m512d likely = _mm512_setzero_pd(), unlikely = _mm512_setzero_pd();
  float* data = in.data;
  for (std::size_t s = 0; s < in.num_spans; ++s) {
    const std::size_t end = in.spans[2 * s + 1];
    for (std::size_t c0 = in.spans[2 * s]; c0 < end; c0 += 16 * kChunks) {
      const std::size_t n = std::min<std::size_t>(16 * kChunks, end - c0);
      const int chunks = static_cast<int>((n + 15) / 16);
      __mmask16 upd[kChunks], lanes[kChunks];
      bool any = false;
      for (int ch = 0; ch < chunks; ++ch) {
        const std::size_t c = c0 + 16 * ch, m = std::min<std::size_t>(16, end - c);
        lanes[ch] = static_cast<__mmask16>(m == 16 ? 0xFFFFu : (1u << m) - 1u);
        const __m512 p = _mm512_maskz_loadu_ps(lanes[ch], data + c);
        upd[ch] = _mm512_mask_cmp_ps_mask(lanes[ch], p, theta, _CMP_NLE_UQ);  // !(p <= theta)
        const __m512 up = _mm512_maskz_mov_ps(static_cast<__mmask16>(lanes[ch] & ~upd[ch]), p);
        unlikely = _mm512_add_pd(unlikely, _mm512_cvtps_pd(_mm512_castps512_ps256(up)));
        unlikely = _mm512_add_pd(
            unlikely,
            _mm512_cvtps_pd(_mm256_castpd_ps(_mm512_extractf64x4_pd(_mm512_castps_pd(up), 1))));
        _mm_mask_storeu_epi8(in.flags + c, lanes[ch], _mm_maskz_set1_epi8(upd[ch], 1));
        any = any || upd[ch] != 0;
      }
      if (!any) continue;
      __m512 l[kChunks];
      if (chunks == kChunks) {
        ProductsAvx512<kChunks>(in, c0, lanes, l);
      } else {
        for (int ch = 0; ch < chunks; ++ch) ProductsAvx512<1>(in, c0 + 16 * ch, lanes + ch, l + ch);
      }
      for (int ch = 0; ch < chunks; ++ch) {
        if (upd[ch] == 0) continue;
        const std::size_t c = c0 + 16 * ch;
        const __m512 p = _mm512_maskz_loadu_ps(lanes[ch], data + c);
        const __m512 v = _mm512_maskz_mul_ps(upd[ch], p, l[ch]);
        _mm512_mask_storeu_ps(data + c, upd[ch], v);
        likely = _mm512_add_pd(likely, _mm512_cvtps_pd(_mm512_castps512_ps256(v)));
        likely = _mm512_add_pd(
            likely,
            _mm512_cvtps_pd(_mm256_castpd_ps(_mm512_extractf64x4_pd(_mm512_castps_pd(v), 1))));
        out.evaluated += static_cast<std::size_t>(__builtin_popcount(upd[ch]));
      }
    }
  }
  alignas(64) double l8[8], u8[8];
  _mm512_store_pd(l8, likely);
  _mm512_store_pd(u8, unlikely);
  out.likely = ((l8[0] + l8[1]) + (l8[2] + l8[3])) + ((l8[4] + l8[5]) + (l8[6] + l8[7]));
  out.unlikely = ((u8[0] + u8[1]) + (u8[2] + u8[3])) + ((u8[4] + u8[5]) + (u8[6] + u8[7]));
  return out;
}

MARKOV_AVX512 float ScaleLayerAvx512(float* data, const std::uint8_t* flags,
                                     const std::uint8_t* mask, const std::uint32_t* spans,
                                     std::size_t num_spans, float a_likely, float a_unlikely,
                                     float floor) {
  const __m512 al = _mm512_set1_ps(a_likely), au = _mm512_set1_ps(a_unlikely);
  const __m512 fl = _mm512_set1_ps(floor);
  __m512 vmx = _mm512_setzero_ps();
  for (std::size_t s = 0; s < num_spans; ++s) {
    const std::size_t end = spans[2 * s + 1];
    for (std::size_t c = spans[2 * s]; c < end; c += 16) {
      const std::size_t n = std::min<std::size_t>(16, end - c);
      const __mmask16 lanes = static_cast<__mmask16>(n == 16 ? 0xFFFFu : (1u << n) - 1u);
      const __m128i f = _mm_maskz_loadu_epi8(lanes, flags + c);
      const __m128i st = _mm_maskz_loadu_epi8(lanes, mask + c);
      const __mmask16 updated = _mm_test_epi8_mask(f, f);
      const __mmask16 state = _mm_test_epi8_mask(st, st);
      const __m512 d = _mm512_maskz_loadu_ps(state, data + c);
      const __m512 nv = _mm512_max_ps(_mm512_mul_ps(d, _mm512_mask_blend_ps(updated, au, al)), fl);
      _mm512_mask_storeu_ps(data + c, state, nv);
      vmx = _mm512_mask_max_ps(vmx, state, vmx, nv);
    }
  }
  return _mm512_reduce_max_ps(vmx);
}

#endif  // MARKOV_X86_KERNELS

}  // namespace

Isa SupportedIsa() {
  static const Isa isa = DetectIsa();
  return isa;
}

Isa ActiveIsa() { return static_cast<Isa>(ActiveSlot().load(std::memory_order_relaxed)); }

Isa ForceIsa(Isa isa) {
  const Isa use = static_cast<int>(isa) <= static_cast<int>(SupportedIsa()) ? isa : SupportedIsa();
  ActiveSlot().store(static_cast<int>(use), std::memory_order_relaxed);
  return use;
}

const char* IsaName(Isa isa) {
  switch (isa) {
    case Isa::kAvx512:
      return "avx512";
    case Isa::kAvx2:
      return "avx2";
    default:
      return "scalar";
  }
}

std::vector<std::uint32_t> StateSpans(const std::vector<std::uint8_t>& mask, std::size_t min_gap) {
  std::vector<std::uint32_t> spans;
  const std::size_t n = mask.size();
  std::size_t c = 0;
  while (c < n) {
    while (c < n && !mask[c]) ++c;
    if (c == n) break;
    std::size_t e = c;
    while (e < n && mask[e]) ++e;
    if (!spans.empty() && c - spans.back() < min_gap) {
      spans.back() = static_cast<std::uint32_t>(e);
    } else {
      spans.push_back(static_cast<std::uint32_t>(c));
      spans.push_back(static_cast<std::uint32_t>(e));
    }
    c = e;
  }
  return spans;
}

SensorLayerOut SensorLayer(const SensorLayerIn& in) {
  switch (ActiveIsa()) {
#ifdef MARKOV_X86_KERNELS
    case Isa::kAvx512:
      return SensorLayerAvx512(in);
    case Isa::kAvx2:
      return SensorLayerAvx2(in);
#endif
    default:
      return SensorLayerScalar(in);
  }
}

float ScaleLayer(float* data, const std::uint8_t* flags, const std::uint8_t* state_mask,
                 const std::uint32_t* spans, std::size_t num_spans, float a_likely,
                 float a_unlikely, float floor) {
  switch (ActiveIsa()) {
#ifdef MARKOV_X86_KERNELS
    case Isa::kAvx512:
      return ScaleLayerAvx512(data, flags, state_mask, spans, num_spans, a_likely, a_unlikely,
                              floor);
    case Isa::kAvx2:
      return ScaleLayerAvx2(data, flags, state_mask, spans, num_spans, a_likely, a_unlikely, floor);
#endif
    default:
      return ScaleLayerScalar(data, flags, state_mask, spans, num_spans, a_likely, a_unlikely,
                              floor);
  }
}

}  // namespace kernels
}  // namespace markov_localization

// ---- motion update ---------------------------------------------------------------------------

namespace markov_localization {
namespace kernels {

// Not under ThreadSanitizer (tools/tsan): the loader runs the clones' ifunc resolvers before
// TSan's runtime is up, and instrumented they crash; a TSan build takes the default versions.
#if defined(MARKOV_X86_KERNELS) && defined(__has_attribute) && !defined(__SANITIZE_THREAD__)
#if __has_attribute(target_clones)
#define MARKOV_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#endif
#endif
#ifndef MARKOV_CLONES
#define MARKOV_CLONES
#endif

namespace {

// One row of the shift: sources r1 (row ty-oy-1) and r0 (row ty-oy), either may be nullptr.
MARKOV_CLONES void ShiftRow(const float* r1, const float* r0, float* out, int w, int ox, float w00,
                            float w10, float w01, float w11) {
  // Target tx reads source columns tx-ox-1 (weights w11, w10) and tx-ox (w01, w00).
  auto at = [w](const float* r, int x) { return r && x >= 0 && x < w ? r[x] : 0.0f; };
  auto cell = [&](int tx) {
    const int a = tx - ox - 1, b = tx - ox;
    return ((at(r1, a) * w11 + at(r1, b) * w01) + at(r0, a) * w10) + at(r0, b) * w00;
  };
  // Interior: both source columns inside the row.
  const int lo = std::max(0, ox + 1), hi = std::min(w, w + ox);  // tx in [lo, hi)
  if (lo >= hi) {
    for (int tx = 0; tx < w; ++tx) out[tx] = cell(tx);
    return;
  }
  for (int tx = 0; tx < lo; ++tx) out[tx] = cell(tx);
  const float* a1 = r1 ? r1 - ox - 1 : nullptr;
  const float* a0 = r0 ? r0 - ox - 1 : nullptr;
  if (r1 && r0) {
    for (int tx = lo; tx < hi; ++tx)
      out[tx] = ((a1[tx] * w11 + a1[tx + 1] * w01) + a0[tx] * w10) + a0[tx + 1] * w00;
  } else if (r0) {
    for (int tx = lo; tx < hi; ++tx) out[tx] = a0[tx] * w10 + a0[tx + 1] * w00;
  } else if (r1) {
    for (int tx = lo; tx < hi; ++tx) out[tx] = a1[tx] * w11 + a1[tx + 1] * w01;
  } else {
    for (int tx = lo; tx < hi; ++tx) out[tx] = 0.0f;
  }
  for (int tx = hi; tx < w; ++tx) out[tx] = cell(tx);
}

// new = k (left + right) + c centre over one padded line: in[0] and in[n + 1] are 0.
MARKOV_CLONES void Blur3(const float* in, float* out, int n, float k, float c) {
  for (int i = 0; i < n; ++i) out[i] = k * (in[i] + in[i + 2]) + c * in[i + 1];
}

MARKOV_CLONES void Blur3Rows(const float* up, const float* centre, const float* down, float* out,
                             int n, float k, float c) {
  for (int i = 0; i < n; ++i) out[i] = k * (up[i] + down[i]) + c * centre[i];
}

}  // namespace

void ShiftBilinear(const float* in, float* out, int w, int h, int ox, int oy, float w00, float w10,
                   float w01, float w11) {
  for (int ty = 0; ty < h; ++ty) {
    const int y1 = ty - oy - 1, y0 = ty - oy;
    const float* r1 = y1 >= 0 && y1 < h ? in + static_cast<std::size_t>(y1) * w : nullptr;
    const float* r0 = y0 >= 0 && y0 < h ? in + static_cast<std::size_t>(y0) * w : nullptr;
    ShiftRow(r1, r0, out + static_cast<std::size_t>(ty) * w, w, ox, w00, w10, w01, w11);
  }
}

void BlurX(float* data, int w, int h, int passes, float k, std::vector<float>& line) {
  const float c = 1.0f - 2.0f * k;
  line.assign(w + 2, 0.0f);
  for (int y = 0; y < h; ++y) {
    float* row = data + static_cast<std::size_t>(y) * w;
    for (int p = 0; p < passes; ++p) {
      std::copy(row, row + w, line.begin() + 1);
      Blur3(line.data(), row, w, k, c);
    }
  }
}

void BlurY(float* data, int w, int h, int passes, float k, std::vector<float>& line) {
  const float c = 1.0f - 2.0f * k;
  // Rows y - 1 (old), y (old) kept in two buffers; row y + 1 is still old in place.
  line.assign(3 * static_cast<std::size_t>(w), 0.0f);
  float* zero = line.data();
  float* prev = zero + w;
  float* cur = prev + w;
  for (int p = 0; p < passes; ++p) {
    const float* up = zero;
    for (int y = 0; y < h; ++y) {
      float* row = data + static_cast<std::size_t>(y) * w;
      std::copy(row, row + w, cur);
      const float* down = y + 1 < h ? row + w : zero;
      Blur3Rows(up, cur, down, row, w, k, c);
      std::swap(prev, cur);
      up = prev;
    }
  }
}

MARKOV_CLONES void MaskedCopy(float* dst, const float* src, const std::uint8_t* mask,
                              std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) dst[i] = mask[i] ? src[i] : 0.0f;
}

namespace {
template <int kTerms>
inline double HeadingBlendLoop(float* dst, const float* cur, const float* a, const float* b,
                               float c0, float k, std::size_t n) {
  double acc[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  std::size_t i = 0;
  auto value = [&](std::size_t j) {
    float v = c0 * cur[j];
    if (kTerms >= 1) v += k * a[j];
    if (kTerms >= 2) v += k * b[j];
    return v;
  };
  for (; i + 8 <= n; i += 8) {
    for (int l = 0; l < 8; ++l) {
      const float v = value(i + l);
      dst[i + l] = v;
      acc[l] += v;
    }
  }
  for (; i < n; ++i) {
    const float v = value(i);
    dst[i] = v;
    acc[i % 8] += v;
  }
  return ((acc[0] + acc[1]) + (acc[2] + acc[3])) + ((acc[4] + acc[5]) + (acc[6] + acc[7]));
}

MARKOV_CLONES double HeadingBlend2(float* dst, const float* cur, const float* a, const float* b,
                                   float c0, float k, std::size_t n) {
  return HeadingBlendLoop<2>(dst, cur, a, b, c0, k, n);
}
MARKOV_CLONES double HeadingBlend1(float* dst, const float* cur, const float* a, float c0, float k,
                                   std::size_t n) {
  return HeadingBlendLoop<1>(dst, cur, a, nullptr, c0, k, n);
}
MARKOV_CLONES double HeadingBlend0(float* dst, const float* cur, float c0, std::size_t n) {
  return HeadingBlendLoop<0>(dst, cur, nullptr, nullptr, c0, 0.0f, n);
}
}  // namespace

double HeadingBlend(float* dst, const float* cur, const float* prev, const float* next, float c0,
                    float k, std::size_t n) {
  if (prev && next) return HeadingBlend2(dst, cur, prev, next, c0, k, n);
  if (prev || next) return HeadingBlend1(dst, cur, prev ? prev : next, c0, k, n);
  return HeadingBlend0(dst, cur, c0, n);
}

MARKOV_CLONES double Sum(const float* data, std::size_t n) {
  double acc[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8)
    for (int l = 0; l < 8; ++l) acc[l] += data[i + l];
  for (; i < n; ++i) acc[i % 8] += data[i];
  return ((acc[0] + acc[1]) + (acc[2] + acc[3])) + ((acc[4] + acc[5]) + (acc[6] + acc[7]));
}

MARKOV_CLONES float Max(const float* data, std::size_t n) {
  float mx = 0.0f;
  for (std::size_t i = 0; i < n; ++i) mx = mx < data[i] ? data[i] : mx;
  return mx;
}

MARKOV_CLONES void Scale(float* data, std::size_t n, float factor) {
  for (std::size_t i = 0; i < n; ++i) data[i] *= factor;
}

}  // namespace kernels
}  // namespace markov_localization
