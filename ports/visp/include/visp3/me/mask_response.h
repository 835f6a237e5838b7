// SPDX-License-Identifier: BSD-3-Clause
/// New (not in upstream): the response of one site's oriented mask at any pixel of an image,
/// with the mask, its sign and upstream's border limits looked up once. vpMeSite's
/// convolution() and track() go through it, and so do searches that read some thirty pixels
/// per site (the tracker's path and sub-pixel searches): inlined there, a response costs the
/// window's products and nothing else. The sums are integers, the same in every `real` build.
#pragma once

#include <cstddef>
#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#elif defined(__ARM_NEON)
#include <arm_neon.h>
#endif

#include "real/vector_kernels.h"
#include "visp3/core/vpImage.h"
#include "visp3/me/vpMe.h"

inline namespace edgetrack_ports {

class MaskResponse {
 public:
  /// The response of mask `mask_index` of `me`, times `sign` (+1 or -1), in I. I must outlive it.
  MaskResponse(const vpImage<unsigned char>& I, const vpMe& me, unsigned int mask_index, int sign)
      : image_(I),
        weights_(me.maskWeights(mask_index)),
        padded_(me.paddedMaskWeights(mask_index)),
        size_(static_cast<int>(me.getMaskSize())),
        half_((static_cast<int>(me.getMaskSize()) - 1) >> 1),
        sign_(sign),
        antisymmetric_(me.masksAntisymmetric()) {
    // Upstream's border rule: the mask centred at (i, j) keeps `margin` (half mask + strip) plus
    // one pixel from the top and left, and margin plus three from the bottom and right.
    const int margin = half_ + me.getStrip();
    first_ = margin + 1;
    last_i_ = static_cast<int>(I.getHeight()) - margin - 3;
    last_j_ = static_cast<int>(I.getWidth()) - margin - 3;
    // A padded row reads kPaddedRow pixels from the window's left: they must lie in the row.
    if (padded_ && last_j_ - half_ + static_cast<int>(vpMe::kPaddedRow) > static_cast<int>(I.getWidth()))
      padded_ = nullptr;
    // The scalar reference (vector_kernels.h) sums without the padded rows.
    if (vector_kernels::chosen() == vector_kernels::Choice::kScalar) padded_ = nullptr;
    avx2_ = padded_ && size_ == 5 && vector_kernels::avx2();
  }

  /// True when the mask centred at (i, j) would reach the border strip.
  bool outside(int i, int j) const { return i < first_ || i > last_i_ || j < first_ || j > last_j_; }

  /// at(i[k], j[k]) into out[k] for k < n. With the vector path the mask's rows are loaded once
  /// for the batch (a site's path, a refinement's lines) instead of once per pixel.
  void at_each(const int* i, const int* j, int n, int* out) const {
    // The limits in locals: stores to `out` could otherwise alias them and reload them per pixel.
#if defined(__SSE2__) || defined(__ARM_NEON)
    if (padded_ && size_ == 5) {
      padded_each_5<true>(i, j, n, out);
      return;
    }
#endif
    const int first = first_, last_i = last_i_, last_j = last_j_, sign = sign_, half = half_;
    const bool antisymmetric_5 = antisymmetric_ && size_ == 5;
    for (int k = 0; k < n; ++k) {
      const int row = i[k], column = j[k];
      if (row < first || row > last_i || column < first || column > last_j) {
        out[k] = 0;
        continue;
      }
      out[k] = sign * (antisymmetric_5 ? antisymmetric_sum_5(row - half, column - half) : other_sum(row - half, column - half));
    }
  }

  /// at_each for pixels that lie in the box whose opposite corners are the first and the last
  /// (a straight path in order, a block listed from corner to corner): when both lie inside, no
  /// pixel needs the border test.
  void at_each_in_box(const int* i, const int* j, int n, int* out) const {
#if defined(__SSE2__) || defined(__ARM_NEON)
    if (padded_ && size_ == 5 && n > 0 && !outside(i[0], j[0]) && !outside(i[n - 1], j[n - 1])) {
      padded_each_5<false>(i, j, n, out);
      return;
    }
#endif
    at_each(i, j, n, out);
  }

#if defined(__SSE2__)
  /// True when this response runs the AVX2 kernels (a 5 x 5 mask with padded rows, AVX2 chosen).
  bool runs_avx2() const { return avx2_; }
  /// With the AVX2 kernels (runs_avx2()), a straight path in one pass: its pixels, i[t] and j[t]
  /// the truncated y + (k0 + t) dy and x + (k0 + t) dx for t < n (each lane the product, then the
  /// sum, in double: a scalar walk's values), into i[] and j[]; then, when the windows of the
  /// first and the last pixel lie inside, at() of each into out[] and true, else false (out[]
  /// left to the caller). n is at most kMaxPathEach (else false, nothing written), and i[], j[] and
  /// out[] hold n rounded up to a multiple of 4.
  static constexpr int kMaxPathEach = 32;
  bool path_each_5_avx2(double y, double x, double dy, double dx, int k0, int n, int* i, int* j, int* out) const;
#endif

  /// The responses at the 3 x 3 pixels around (i, j), row by row: out[3 (di + 1) + dj + 1] is
  /// at(i + di, j + dj), for di and dj in -1..1; `centre` is at(i, j), which the caller read
  /// already. With the vector path, when the block lies inside, the windows share their pixels'
  /// loads; else the eight others in one batch (at_each).
  void at_block_3x3(int i, int j, int centre, int* out) const {
#if defined(__SSE2__) || defined(__ARM_NEON)
    if (padded_ && size_ == 5 && !outside(i - 1, j - 1) && !outside(i + 1, j + 1)) {
      const std::ptrdiff_t stride = static_cast<std::ptrdiff_t>(image_.getWidth());
      const unsigned char* top_left = image_.bitmap + (i - 1 - half_) * stride + (j - 1 - half_);
#if defined(__SSE2__)
      if (avx2_) {
        padded_block_5_avx2(padded_, top_left, stride, sign_, out);
        return;
      }
#endif
      padded_block_5(padded_, top_left, stride, sign_, out);
      return;
    }
#endif
    int rows[8], columns[8], others[8];
    for (int k = 0; k < 8; ++k) {
      const int m = k < 4 ? k : k + 1;  // the block's pixels without the centre
      rows[k] = i + m / 3 - 1;
      columns[k] = j + m % 3 - 1;
    }
    at_each_in_box(rows, columns, 8, others);
    for (int k = 0; k < 4; ++k) out[k] = others[k];
    out[4] = centre;
    for (int k = 4; k < 8; ++k) out[k + 1] = others[k];
  }

  /// sign * sum of weight * pixel over the window centred at (i, j); 0 when outside(i, j).
  int at(int i, int j) const {
    if (outside(i, j)) return 0;
#if defined(__SSE2__) || defined(__ARM_NEON)
    if (padded_ && size_ == 5) return sign_ * padded_sum<5>(i - half_, j - half_);
#endif
    // Only the vector path inlined: the others' weights and row pointers, inlined in a caller's
    // loop, are spilled to the stack and reloaded at every call. The antisymmetric 5 x 5 sum
    // (upstream's default masks) has a function of its own, its weights loaded where used.
    if (antisymmetric_ && size_ == 5) return sign_ * antisymmetric_sum_5(i - half_, j - half_);
    return sign_ * other_sum(i - half_, j - half_);
  }

 private:
  [[gnu::noinline]] int other_sum(int i0, int j0) const { return sum(i0, j0); }
  [[gnu::noinline]] int antisymmetric_sum_5(int i0, int j0) const { return antisymmetric_sum<5>(i0, j0); }

  /// Sum of weight * pixel over the window whose top-left pixel is (i0, j0).
  int sum(int i0, int j0) const {
    if (size_ == 5) {
      if (padded_) return padded_sum<5>(i0, j0);
      return antisymmetric_ ? antisymmetric_sum<5>(i0, j0) : unrolled_sum<5>(i0, j0);
    }
    int total = 0;
    for (int a = 0; a < size_; ++a) {
      const unsigned char* row = image_[i0 + a] + j0;
      const int16_t* weights = weights_ + a * size_;
      for (int b = 0; b < size_; ++b) total += weights[b] * row[b];
    }
    return total;
  }

  /// The loops unrolled (upstream's default 5 x 5 masks: a third of the instructions of the
  /// general loop on ARMv5TE).
  template <int Size>
  int unrolled_sum(int i0, int j0) const {
    int total = 0;
#pragma GCC unroll 8
    for (int a = 0; a < Size; ++a) {
      const unsigned char* row = image_[i0 + a] + j0;
      const int16_t* weights = weights_ + a * Size;
#pragma GCC unroll 8
      for (int b = 0; b < Size; ++b) total += weights[b] * row[b];
    }
    return total;
  }

  /// For antisymmetric masks (vpMe::masksAntisymmetric): window pixel m (row-major) and pixel
  /// Size^2 - 1 - m, its mirror through the centre, have opposite weights, so each pair takes one
  /// product of the weight and the two pixels' difference, and the centre (weight 0) none.
  template <int Size>
  int antisymmetric_sum(int i0, int j0) const {
    constexpr int kPairs = Size * Size / 2;
    const unsigned char* window = image_[i0] + j0;
    const std::ptrdiff_t stride = static_cast<std::ptrdiff_t>(image_.getWidth());
    int total = 0;
#pragma GCC unroll 16
    for (int m = 0; m < kPairs; ++m) {
      const int a = m / Size, b = m % Size;
      total += weights_[m] * (window[a * stride + b] - window[(Size - 1 - a) * stride + (Size - 1 - b)]);
    }
    return total;
  }

#if defined(__SSE2__) || defined(__ARM_NEON)
  /// Rows padded with zero weights to vpMe::kPaddedRow (8) entries, 8 products of 16 bits per row
  /// (weight * pixel < 2^15, sums in 32 bits; integers, exact in any order): one multiply-add on
  /// SSE2, two widening multiply-accumulates with NEON. Reads the kPaddedRow - Size pixels right
  /// of the window, which the constructor checked lie in the row.
  template <int Size>
  int padded_sum(int i0, int j0) const {
    static_assert(Size == 5, "the padded rows of a 5 x 5 mask");
    Row weights[5];
    for (int a = 0; a < 5; ++a) weights[a] = load_row(padded_ + a * 8);
    const std::ptrdiff_t stride = static_cast<std::ptrdiff_t>(image_.getWidth());
    return padded_sum_5(weights, image_.bitmap + i0 * stride + j0, stride);
  }

  /// at_each's vector path for the 5 x 5 mask: the mask's rows loaded once for the batch; with
  /// kBorderTest false the caller knows every pixel lies inside.
  template <bool kBorderTest>
  void padded_each_5(const int* i, const int* j, int n, int* out) const {
    const int first = first_, last_i = last_i_, last_j = last_j_, sign = sign_, half = half_;
    const unsigned char* bitmap = image_.bitmap;
    const std::ptrdiff_t stride = static_cast<std::ptrdiff_t>(image_.getWidth());
#if defined(__SSE2__)
    if (!kBorderTest && avx2_) {
      padded_each_5_avx2(padded_, bitmap, stride, half, sign, i, j, n, out);
      return;
    }
#endif
    Row weights[5];
    for (int a = 0; a < 5; ++a) weights[a] = load_row(padded_ + a * 8);
    for (int k = 0; k < n; ++k) {
      const int row = i[k], column = j[k];
      const bool out_of_image = kBorderTest && (row < first || row > last_i || column < first || column > last_j);
      out[k] = out_of_image ? 0 : sign * padded_sum_5(weights, bitmap + (row - half) * stride + (column - half), stride);
    }
  }
#endif

#if defined(__SSE2__)
  /// A padded mask row in a register.
  using Row = __m128i;
  static Row load_row(const int16_t* weights) { return _mm_loadu_si128(reinterpret_cast<const __m128i*>(weights)); }

  /// The 3 x 3 block's padded sums, times `sign`, row-major into out[9]: the 7 x 7 pixels under
  /// the nine windows (top-left at `top_left`, 8 read per row) each loaded once, every window row
  /// one 16-bit multiply-add with its mask row shifted to the window's column (weight * pixel
  /// < 2^15, integer sums: exact in any order). Inlined in the baseline and the AVX2 kernels.
  [[gnu::always_inline]] static inline void padded_block_5(const int16_t* padded, const unsigned char* top_left,
                                                         std::ptrdiff_t stride, int sign, int* out) {
    static_assert(vpMe::kPaddedRow == 8, "one 128-bit register of 16-bit weights per row");
    // shifted[3 a + s]: mask row a moved s pixels right, for the window s - 1 columns off.
    __m128i shifted[15];
    for (int a = 0; a < 5; ++a) {
      const __m128i row = _mm_loadu_si128(reinterpret_cast<const __m128i*>(padded + a * 8));
      shifted[3 * a] = row;
      shifted[3 * a + 1] = _mm_slli_si128(row, 2);
      shifted[3 * a + 2] = _mm_slli_si128(row, 4);
    }
    const __m128i zero = _mm_setzero_si128();
    __m128i total[9];
    for (int w = 0; w < 9; ++w) total[w] = zero;
#pragma GCC unroll 7
    for (int r = 0; r < 7; ++r) {
      const __m128i pixels = _mm_unpacklo_epi8(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(top_left + r * stride)), zero);
#pragma GCC unroll 3
      for (int di = 0; di < 3; ++di) {
        const int a = r - di;  // the row of window row di's mask that image row r meets
        if (a < 0 || a > 4) continue;
#pragma GCC unroll 3
        for (int s = 0; s < 3; ++s) total[3 * di + s] = _mm_add_epi32(total[3 * di + s], _mm_madd_epi16(pixels, shifted[3 * a + s]));
      }
    }
    // Four windows' lanes summed at once: a transpose by unpacks, then two adds.
    for (int w = 0; w < 8; w += 4) {
      const __m128i ab = _mm_add_epi32(_mm_unpacklo_epi32(total[w], total[w + 1]), _mm_unpackhi_epi32(total[w], total[w + 1]));
      const __m128i cd = _mm_add_epi32(_mm_unpacklo_epi32(total[w + 2], total[w + 3]), _mm_unpackhi_epi32(total[w + 2], total[w + 3]));
      __m128i sums = _mm_add_epi32(_mm_unpacklo_epi64(ab, cd), _mm_unpackhi_epi64(ab, cd));
      if (sign < 0) sums = _mm_sub_epi32(zero, sums);
      _mm_storeu_si128(reinterpret_cast<__m128i*>(out + w), sums);
    }
    __m128i last = _mm_add_epi32(total[8], _mm_shuffle_epi32(total[8], _MM_SHUFFLE(1, 0, 3, 2)));
    last = _mm_add_epi32(last, _mm_shuffle_epi32(last, _MM_SHUFFLE(2, 3, 0, 1)));
    out[8] = sign * _mm_cvtsi128_si32(last);
  }
  /// padded_block_5 with AVX2 (mask_response_avx2.cpp, whatever the build's target): the same
  /// products, two windows per 256-bit multiply-add.
  static void padded_block_5_avx2(const int16_t* padded, const unsigned char* top_left, std::ptrdiff_t stride, int sign,
                                  int* out);
  /// padded_each_5<false> with AVX2 (mask_response_avx2.cpp): two windows per 256-bit multiply-add
  /// and four windows' lanes summed together; every window lies inside.
  static void padded_each_5_avx2(const int16_t* padded, const unsigned char* bitmap, std::ptrdiff_t stride, int half,
                                 int sign, const int* i, const int* j, int n, int* out);

  static int padded_sum_5(const Row (&weights)[5], const unsigned char* window, std::ptrdiff_t stride) {
    static_assert(vpMe::kPaddedRow == 8, "one 128-bit register of 16-bit weights per row");
    const __m128i zero = _mm_setzero_si128();
    __m128i total = _mm_setzero_si128();
    for (int a = 0; a < 5; ++a) {
      const __m128i pixels =
          _mm_unpacklo_epi8(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(window + a * stride)), zero);
      total = _mm_add_epi32(total, _mm_madd_epi16(pixels, weights[a]));
    }
    total = _mm_add_epi32(total, _mm_shuffle_epi32(total, _MM_SHUFFLE(1, 0, 3, 2)));
    total = _mm_add_epi32(total, _mm_shuffle_epi32(total, _MM_SHUFFLE(2, 3, 0, 1)));
    return _mm_cvtsi128_si32(total);
  }
#elif defined(__ARM_NEON)
  /// A padded mask row in a register.
  using Row = int16x8_t;
  static Row load_row(const int16_t* weights) { return vld1q_s16(weights); }

  /// The 8 pixels from `pixels`, widened to 16 bits.
  static int16x8_t pixel_row(const unsigned char* pixels) { return vreinterpretq_s16_u16(vmovl_u8(vld1_u8(pixels))); }

  /// total + the 8 products of pixels and weights, lane by lane.
  static int32x4_t multiply_add(int32x4_t total, int16x8_t pixels, int16x8_t weights) {
    total = vmlal_s16(total, vget_low_s16(pixels), vget_low_s16(weights));
    return vmlal_s16(total, vget_high_s16(pixels), vget_high_s16(weights));
  }

  /// {sum of a's lanes, b's, c's, d's}.
  static int32x4_t lane_sums(int32x4_t a, int32x4_t b, int32x4_t c, int32x4_t d) {
#if defined(__aarch64__)
    return vpaddq_s32(vpaddq_s32(a, b), vpaddq_s32(c, d));
#else
    const int32x2_t ab = vpadd_s32(vadd_s32(vget_low_s32(a), vget_high_s32(a)), vadd_s32(vget_low_s32(b), vget_high_s32(b)));
    const int32x2_t cd = vpadd_s32(vadd_s32(vget_low_s32(c), vget_high_s32(c)), vadd_s32(vget_low_s32(d), vget_high_s32(d)));
    return vcombine_s32(ab, cd);
#endif
  }

  /// The sum of a's lanes.
  static int lane_sum(int32x4_t a) {
#if defined(__aarch64__)
    return vaddvq_s32(a);
#else
    const int32x2_t pair = vadd_s32(vget_low_s32(a), vget_high_s32(a));
    return vget_lane_s32(vpadd_s32(pair, pair), 0);
#endif
  }

  /// The SSE2 padded_block_5's operations with NEON: the 7 x 7 pixels under the nine windows
  /// (top-left at `top_left`, 8 read per row) each loaded once, every window row multiplied with
  /// its mask row moved to the window's column; sums times `sign`, row-major into out[9].
  static void padded_block_5(const int16_t* padded, const unsigned char* top_left, std::ptrdiff_t stride, int sign,
                             int* out) {
    static_assert(vpMe::kPaddedRow == 8, "one 128-bit register of 16-bit weights per row");
    // shifted[3 a + s]: mask row a moved s lanes up, for the window s - 1 columns off.
    const int16x8_t zero = vdupq_n_s16(0);
    int16x8_t shifted[15];
    for (int a = 0; a < 5; ++a) {
      const int16x8_t row = vld1q_s16(padded + a * 8);
      shifted[3 * a] = row;
      shifted[3 * a + 1] = vextq_s16(zero, row, 7);
      shifted[3 * a + 2] = vextq_s16(zero, row, 6);
    }
    int32x4_t total[9];
    for (int w = 0; w < 9; ++w) total[w] = vdupq_n_s32(0);
#pragma GCC unroll 7
    for (int r = 0; r < 7; ++r) {
      const int16x8_t pixels = pixel_row(top_left + r * stride);
#pragma GCC unroll 3
      for (int di = 0; di < 3; ++di) {
        const int a = r - di;  // the row of window row di's mask that image row r meets
        if (a < 0 || a > 4) continue;
#pragma GCC unroll 3
        for (int s = 0; s < 3; ++s) total[3 * di + s] = multiply_add(total[3 * di + s], pixels, shifted[3 * a + s]);
      }
    }
    for (int w = 0; w < 8; w += 4) {
      int32x4_t sums = lane_sums(total[w], total[w + 1], total[w + 2], total[w + 3]);
      if (sign < 0) sums = vnegq_s32(sums);
      vst1q_s32(out + w, sums);
    }
    out[8] = sign * lane_sum(total[8]);
  }

  static int padded_sum_5(const Row (&weights)[5], const unsigned char* window, std::ptrdiff_t stride) {
    static_assert(vpMe::kPaddedRow == 8, "one 128-bit register of 16-bit weights per row");
    int32x4_t total = vdupq_n_s32(0);
    for (int a = 0; a < 5; ++a) total = multiply_add(total, pixel_row(window + a * stride), weights[a]);
    return lane_sum(total);
  }
#else
  template <int Size>
  int padded_sum(int i0, int j0) const {
    return unrolled_sum<Size>(i0, j0);  // no padded masks here (vpMe::kPaddedRow is 0)
  }
#endif

  const vpImage<unsigned char>& image_;
  const int16_t* weights_;
  const int16_t* padded_;
  int size_, half_, sign_;
  bool antisymmetric_;
  bool avx2_ = false;
  int first_ = 0, last_i_ = 0, last_j_ = 0;
};

}  // inline namespace edgetrack_ports
