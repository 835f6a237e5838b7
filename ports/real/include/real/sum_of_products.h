// SPDX-License-Identifier: BSD-3-Clause
/// The sum of products over two arrays in any real: the inner loop of MINPACK's QR and of the
/// tracker's small least-squares sums.
#pragma once

#include <limits>

#include "real/real.h"

/// a[0] b[0] + ... + a[n-1] b[n-1]. Floating point: the plain loop, in order. Fixed point:
/// fixedpoint::dot_product's exact sum rounded once, which is both closer and cheaper than a
/// rounding and a saturation test per product. A template, so that the branch the scalar does
/// not take is not compiled.
template <class T>
T sum_of_products(int n, const T* a, const T* b) {
  if constexpr (!std::numeric_limits<T>::is_iec559) {
    return dot_product(n, a, b);
  } else {
    T sum(0);
    for (int i = 0; i < n; ++i) sum += a[i] * b[i];
    return sum;
  }
}
