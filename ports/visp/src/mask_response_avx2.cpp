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
  padded_block_5(padded, top_left, stride, sign, out);
}

[[gnu::target("avx2")]] void MaskResponse::padded_each_5_avx2(const int16_t* padded, const unsigned char* bitmap,
                                                             std::ptrdiff_t stride, int half, int sign, const int* i,
                                                             const int* j, int n, int* out) {
  static_assert(vpMe::kPaddedRow == 8, "one 128-bit register of 16-bit weights per row");
  // Each mask row in both 128-bit halves: one half meets one window's pixels, the other another's.
  __m256i weights[5];
  for (int a = 0; a < 5; ++a)
    weights[a] = _mm256_broadcastsi128_si256(_mm_loadu_si128(reinterpret_cast<const __m128i*>(padded + a * 8)));
  int k = 0;
  for (; k + 4 <= n; k += 4) {
    const unsigned char* window[4];
    for (int w = 0; w < 4; ++w) window[w] = bitmap + (i[k + w] - half) * stride + (j[k + w] - half);
    // Windows 0 and 1 side by side, 2 and 3 side by side: the 8 pixels of each row, widened.
    __m256i first = _mm256_setzero_si256(), second = _mm256_setzero_si256();
    for (int a = 0; a < 5; ++a) {
      const std::ptrdiff_t offset = a * stride;
      const __m128i pair_01 = _mm_castpd_si128(_mm_loadh_pd(
          _mm_castsi128_pd(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(window[0] + offset))),
          reinterpret_cast<const double*>(window[1] + offset)));
      const __m128i pair_23 = _mm_castpd_si128(_mm_loadh_pd(
          _mm_castsi128_pd(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(window[2] + offset))),
          reinterpret_cast<const double*>(window[3] + offset)));
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
  if (k < n) {
    __m128i rows[5];
    for (int a = 0; a < 5; ++a) rows[a] = _mm_loadu_si128(reinterpret_cast<const __m128i*>(padded + a * 8));
    for (; k < n; ++k) out[k] = sign * padded_sum_5(rows, bitmap + (i[k] - half) * stride + (j[k] - half), stride);
  }
}

}  // inline namespace edgetrack_ports
#endif
