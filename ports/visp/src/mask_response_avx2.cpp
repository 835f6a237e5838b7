// SPDX-License-Identifier: BSD-3-Clause
/// MaskResponse's AVX2 kernels, built for AVX2 by the functions' attribute whatever the build's
/// target; called only when vector_kernels::avx2() says the CPU runs it.
#include "visp3/me/mask_response.h"

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#if defined(__SSE2__)

inline namespace edgetrack_ports {

[[gnu::target("avx2")]] void MaskResponse::padded_block_5_avx2(const int16_t* padded, const unsigned char* top_left,
                                                              std::ptrdiff_t stride, int sign, int* out) {
  static_assert(vpMe::kPaddedRow == 8, "one 128-bit register of 16-bit weights per row");
  // shifted[a + 1][s]: mask row a moved s pixels right, for the windows s - 1 columns off; rows
  // -1 and 5 are zero, so that a window pair whose other window has no row there adds nothing.
  const __m128i zero = _mm_setzero_si128();
  __m128i shifted[7][3];
  for (int s = 0; s < 3; ++s) shifted[0][s] = shifted[6][s] = zero;
  for (int a = 0; a < 5; ++a) {
    const __m128i row = _mm_loadu_si128(reinterpret_cast<const __m128i*>(padded + a * 8));
    shifted[a + 1][0] = row;
    shifted[a + 1][1] = _mm_slli_si128(row, 2);
    shifted[a + 1][2] = _mm_slli_si128(row, 4);
  }
  // Window (di, s) is block row di, column s. Two windows per 256-bit multiply-add: (di, 0) and
  // (di, 1) side by side for each di, (0, 2) beside (1, 2); (2, 2) alone in 128 bits.
  __m256i left_pairs[3] = {_mm256_setzero_si256(), _mm256_setzero_si256(), _mm256_setzero_si256()};
  __m256i right_pair = _mm256_setzero_si256();
  __m128i last = zero;
#pragma GCC unroll 7
  for (int r = 0; r < 7; ++r) {
    const __m128i pixels = _mm_cvtepu8_epi16(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(top_left + r * stride)));
    const __m256i both = _mm256_broadcastsi128_si256(pixels);
#pragma GCC unroll 3
    for (int di = 0; di < 3; ++di) {
      const int a = r - di;  // the row of window row di's mask that image row r meets
      if (a < 0 || a > 4) continue;
      left_pairs[di] = _mm256_add_epi32(
          left_pairs[di], _mm256_madd_epi16(both, _mm256_set_m128i(shifted[a + 1][1], shifted[a + 1][0])));
    }
    if (r <= 5)  // rows r and r - 1 of the mask, for windows (0, 2) and (1, 2)
      right_pair = _mm256_add_epi32(right_pair, _mm256_madd_epi16(both, _mm256_set_m128i(shifted[r][2], shifted[r + 1][2])));
    if (r >= 2) last = _mm_add_epi32(last, _mm_madd_epi16(pixels, shifted[r - 1][2]));
  }
  // Each window's four lanes summed: two pairwise passes leave {w0 w2 w3 w6 | w1 w5 w4 w7}.
  const __m256i sums = _mm256_hadd_epi32(_mm256_hadd_epi32(left_pairs[0], right_pair),
                                         _mm256_hadd_epi32(left_pairs[1], left_pairs[2]));
  __m256i in_order = _mm256_permutevar8x32_epi32(sums, _mm256_setr_epi32(0, 4, 1, 2, 6, 5, 3, 7));
  if (sign < 0) in_order = _mm256_sub_epi32(_mm256_setzero_si256(), in_order);
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(out), in_order);
  last = _mm_hadd_epi32(last, last);
  last = _mm_hadd_epi32(last, last);
  out[8] = sign * _mm_cvtsi128_si32(last);
}

namespace {

/// The padded 5 x 5 responses, times `sign`, of the windows whose top-left pixels are at
/// bitmap + offset[k], k < n, into out[k]: two windows per 256-bit multiply-add and four windows'
/// lanes summed together; every window lies inside.
[[gnu::target("avx2")]] void padded_windows_5_avx2(const int16_t* padded, const unsigned char* bitmap,
                                                   std::ptrdiff_t stride, int sign, const int* offset, int n, int* out) {
  static_assert(vpMe::kPaddedRow == 8, "one 128-bit register of 16-bit weights per row");
  // Each mask row in both 128-bit halves: one half meets one window's pixels, the other another's.
  __m256i weights[5];
  for (int a = 0; a < 5; ++a)
    weights[a] = _mm256_broadcastsi128_si256(_mm_loadu_si128(reinterpret_cast<const __m128i*>(padded + a * 8)));
  int k = 0;
  for (; k + 4 <= n; k += 4) {
    const unsigned char* window[4];
    for (int w = 0; w < 4; ++w) window[w] = bitmap + offset[k + w];
    // Windows 0 and 1 side by side, 2 and 3 side by side: the 8 pixels of each row, widened.
    __m256i first = _mm256_setzero_si256(), second = _mm256_setzero_si256();
    for (int a = 0; a < 5; ++a) {
      const std::ptrdiff_t row = a * stride;
      const __m128i pair_01 = _mm_castpd_si128(_mm_loadh_pd(
          _mm_castsi128_pd(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(window[0] + row))),
          reinterpret_cast<const double*>(window[1] + row)));
      const __m128i pair_23 = _mm_castpd_si128(_mm_loadh_pd(
          _mm_castsi128_pd(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(window[2] + row))),
          reinterpret_cast<const double*>(window[3] + row)));
      first = _mm256_add_epi32(first, _mm256_madd_epi16(_mm256_cvtepu8_epi16(pair_01), weights[a]));
      second = _mm256_add_epi32(second, _mm256_madd_epi16(_mm256_cvtepu8_epi16(pair_23), weights[a]));
    }
    // Lanes {0 | 1} and {2 | 3} to {0, 1, 2, 3}: pairwise sums twice, then one lane per half.
    __m256i sums = _mm256_hadd_epi32(first, second);  // {0 0 2 2 | 1 1 3 3}
    sums = _mm256_hadd_epi32(sums, sums);             // {0 2 0 2 | 1 3 1 3}
    __m128i in_order = _mm_unpacklo_epi32(_mm256_castsi256_si128(sums), _mm256_extracti128_si256(sums, 1));
    if (sign < 0) in_order = _mm_sub_epi32(_mm_setzero_si128(), in_order);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + k), in_order);
  }
  for (; k < n; ++k) {
    // The last windows one by one: the 8 pixels of each row against the mask row, summed.
    __m128i total = _mm_setzero_si128();
    for (int a = 0; a < 5; ++a) {
      const __m128i pixels = _mm_cvtepu8_epi16(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(bitmap + offset[k] + a * stride)));
      total = _mm_add_epi32(total, _mm_madd_epi16(pixels, _mm256_castsi256_si128(weights[a])));
    }
    total = _mm_hadd_epi32(total, total);
    total = _mm_hadd_epi32(total, total);
    out[k] = sign * _mm_cvtsi128_si32(total);
  }
}

/// offset[k] = (i[k] - half) stride + (j[k] - half) for k < n, four at a time.
[[gnu::target("avx2")]] void window_offsets_avx2(const int* i, const int* j, int n, int half, std::ptrdiff_t stride,
                                                 int* offset) {
  const __m128i halves = _mm_set1_epi32(half), rows = _mm_set1_epi32(static_cast<int>(stride));
  int k = 0;
  for (; k + 4 <= n; k += 4) {
    const __m128i top = _mm_sub_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(i + k)), halves);
    const __m128i left = _mm_sub_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(j + k)), halves);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(offset + k), _mm_add_epi32(_mm_mullo_epi32(top, rows), left));
  }
  for (; k < n; ++k) offset[k] = (i[k] - half) * static_cast<int>(stride) + (j[k] - half);
}

}  // namespace

[[gnu::target("avx2")]] void MaskResponse::padded_each_5_avx2(const int16_t* padded, const unsigned char* bitmap,
                                                             std::ptrdiff_t stride, int half, int sign, const int* i,
                                                             const int* j, int n, int* out) {
  constexpr int kBatch = 32;
  int offset[kBatch];
  for (int start = 0; start < n; start += kBatch) {
    const int count = n - start < kBatch ? n - start : kBatch;
    window_offsets_avx2(i + start, j + start, count, half, stride, offset);
    padded_windows_5_avx2(padded, bitmap, stride, sign, offset, count, out + start);
  }
}

[[gnu::target("avx2")]] bool MaskResponse::path_each_5_avx2(double y, double x, double dy, double dx, int k0, int n,
                                                           int* i, int* j, int* out) const {
  if (n <= 0 || n > kMaxPathEach) return false;
  const std::ptrdiff_t stride = static_cast<std::ptrdiff_t>(image_.getWidth());
  const __m256d start_y = _mm256_set1_pd(y), start_x = _mm256_set1_pd(x);
  const __m256d step_y = _mm256_set1_pd(dy), step_x = _mm256_set1_pd(dx), four = _mm256_set1_pd(4.0);
  const __m128i halves = _mm_set1_epi32(half_), rows = _mm_set1_epi32(static_cast<int>(stride));
  int offset[kMaxPathEach];
  // k0 + t, small integers: exact in double, and so are their steps of 4.
  __m256d k = _mm256_setr_pd(double(k0), double(k0 + 1), double(k0 + 2), double(k0 + 3));
  for (int t = 0; t < n; t += 4, k = _mm256_add_pd(k, four)) {
    // Each lane the scalar walk's product, then sum, truncated towards zero.
    const __m128i row = _mm256_cvttpd_epi32(_mm256_add_pd(start_y, _mm256_mul_pd(k, step_y)));
    const __m128i column = _mm256_cvttpd_epi32(_mm256_add_pd(start_x, _mm256_mul_pd(k, step_x)));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(i + t), row);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(j + t), column);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(offset + t),
                     _mm_add_epi32(_mm_mullo_epi32(_mm_sub_epi32(row, halves), rows), _mm_sub_epi32(column, halves)));
  }
  if (outside(i[0], j[0]) || outside(i[n - 1], j[n - 1])) return false;
  // Past the path, the last window again (inside, unlike the path's continuation).
  const int whole = (n + 3) & ~3;
  for (int t = n; t < whole; ++t) offset[t] = offset[n - 1];
  padded_windows_5_avx2(padded_, image_.bitmap, stride, sign_, offset, whole, out);
  return true;
}

}  // inline namespace edgetrack_ports
#endif
