// SPDX-License-Identifier: BSD-3-Clause
/// vpMeResponse's AVX2 kernel: the baseline kernel's body built for AVX2 by the function's
/// attribute, whatever the build's target; called only when vector_kernels::avx2() says the CPU
/// runs it.
#include "visp3/me/vpMeResponse.h"

#if defined(__SSE2__)

inline namespace edgetrack_ports {

[[gnu::target("avx2")]] void vpMeResponse::padded_block_5_avx2(const int16_t* padded, const unsigned char* top_left,
                                                              std::ptrdiff_t stride, int sign, int* out) {
  padded_block_5(padded, top_left, stride, sign, out);
}

}  // inline namespace edgetrack_ports
#endif
