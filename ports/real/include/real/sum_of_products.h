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

/// a0 b0 + a1 b1 (+ a2 b2): the same sum for two or three pairs held in variables, inline.
/// Floating point: in order, as the written-out expression gives it. Fixed point: the few-pairs
/// fixedpoint::dot_product, the exact sum rounded once. Always inline: called once per control
/// point and pose evaluation, where a call costs as much as the sum.
template <class T>
__attribute__((always_inline)) inline T sum_of_products(const T& a0, const T& b0, const T& a1, const T& b1) {
  if constexpr (!std::numeric_limits<T>::is_iec559) {
    return dot_product(a0, b0, a1, b1);
  } else {
    return a0 * b0 + a1 * b1;
  }
}
template <class T>
__attribute__((always_inline)) inline T sum_of_products(const T& a0, const T& b0, const T& a1, const T& b1,
                                                        const T& a2, const T& b2) {
  if constexpr (!std::numeric_limits<T>::is_iec559) {
    return dot_product(a0, b0, a1, b1, a2, b2);
  } else {
    return a0 * b0 + a1 * b1 + a2 * b2;
  }
}

/// a0 b0 - a1 b1, the same way: floating point as written, fixed point
/// fixedpoint::difference_of_products (the exact difference rounded once).
template <class T>
__attribute__((always_inline)) inline T difference_of_products(const T& a0, const T& b0, const T& a1, const T& b1) {
  if constexpr (!std::numeric_limits<T>::is_iec559) {
    return fixedpoint::difference_of_products(a0, b0, a1, b1);
  } else {
    return a0 * b0 - a1 * b1;
  }
}
