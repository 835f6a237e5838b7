// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_sse.h: upstream's vector kernels (element product, dot
/// product, squared distance, matrix times vector, sum, min, max and their positions) behind
/// vnl_sse<T>, and its aligned-allocation helpers. The PXA270 has no SIMD unit, so this is
/// upstream's portable path (its template for types without SSE code) for every T, with the
/// same results; VNL_CONFIG_ENABLE_SSE2 is 0.
#pragma once

#ifdef vnl_sse_h_
#error "edgetrack's drop-in vnl/vnl_sse.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cstddef>

#include "vnl/vnl_alloc.h"
#include "vnl/vnl_config.h"

#define VNL_SSE_FORCE_INLINE inline
#if defined(__GNUC__)
#define VNL_SSE_STACK_ALIGNED(x) __attribute__((aligned(x)))
#else
#define VNL_SSE_STACK_ALIGNED(x)
#endif

inline namespace edgetrack_ports {

/// n elements of `size` bytes (at least 8 bytes when n is 0); operator new aligns for every
/// scalar type, which is all the portable kernels need.
VNL_SSE_FORCE_INLINE void* vnl_sse_alloc(std::size_t n, unsigned size) {
  return vnl_alloc::allocate(n == 0 ? 8 : n * size);
}
VNL_SSE_FORCE_INLINE void vnl_sse_dealloc(void* mem, std::size_t n, unsigned size) {
  if (mem) vnl_alloc::deallocate(mem, n == 0 ? 8 : n * size);
}

template <class T>
class vnl_sse {
 public:
  /// r[i] = x[i] * y[i].
  static VNL_SSE_FORCE_INLINE void element_product(const T* x, const T* y, T* r, unsigned n) {
    for (unsigned i = 0; i < n; ++i) r[i] = x[i] * y[i];
  }
  static VNL_SSE_FORCE_INLINE T dot_product(const T* x, const T* y, unsigned n) {
    T sum(0);
    for (unsigned i = 0; i < n; ++i) sum += x[i] * y[i];
    return sum;
  }
  /// The sum of (x[i] - y[i])^2, accumulated from the last element down as upstream.
  static VNL_SSE_FORCE_INLINE T euclid_dist_sq(const T* x, const T* y, unsigned n) {
    T sum(0);
    while (n != 0) {
      --n;
      const T diff = x[n] - y[n];
      sum += diff * diff;
    }
    return sum;
  }
  /// r = v^T m for the row-major rows x cols matrix m.
  static VNL_SSE_FORCE_INLINE void vector_x_matrix(const T* v, const T* m, T* r, unsigned rows, unsigned cols) {
    for (unsigned j = 0; j < cols; ++j) {
      T sum(0);
      for (unsigned i = 0; i < rows; ++i) sum += m[i * cols + j] * v[i];
      r[j] = sum;
    }
  }
  /// r = m v for the row-major rows x cols matrix m.
  static VNL_SSE_FORCE_INLINE void matrix_x_vector(const T* m, const T* v, T* r, unsigned rows, unsigned cols) {
    for (unsigned i = 0; i < rows; ++i) {
      T sum(0);
      for (unsigned j = 0; j < cols; ++j) sum += m[i * cols + j] * v[j];
      r[i] = sum;
    }
  }
  static VNL_SSE_FORCE_INLINE T sum(const T* v, unsigned n) {
    T total(0);
    for (unsigned i = 0; i < n; ++i) total += v[i];
    return total;
  }
  /// The largest element; 0 for an empty range, as upstream.
  static VNL_SSE_FORCE_INLINE T max(const T* v, unsigned n) { return n == 0 ? T(0) : v[arg_max(v, n)]; }
  static VNL_SSE_FORCE_INLINE T min(const T* v, unsigned n) { return n == 0 ? T(0) : v[arg_min(v, n)]; }
  /// The position of the first largest element; unsigned(-1) for an empty range.
  static VNL_SSE_FORCE_INLINE unsigned arg_max(const T* v, unsigned n) {
    if (n == 0) return unsigned(-1);
    unsigned best = 0;
    for (unsigned i = 1; i < n; ++i) {
      if (v[i] > v[best]) best = i;
    }
    return best;
  }
  static VNL_SSE_FORCE_INLINE unsigned arg_min(const T* v, unsigned n) {
    if (n == 0) return unsigned(-1);
    unsigned best = 0;
    for (unsigned i = 1; i < n; ++i) {
      if (v[i] < v[best]) best = i;
    }
    return best;
  }
};

}  // inline namespace edgetrack_ports
