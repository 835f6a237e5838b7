// SPDX-License-Identifier: BSD-3-Clause
/// The k-th smallest of some numbers without a branch per comparison: a quickselect whose
/// rounds first count the numbers below and above the pivot (a pass built for the widest
/// vectors, vector_kernels.h) and then keep, in place, only the side that holds k, moving the
/// write position by the comparisons' results. On a host CPU std::nth_element's partitions
/// mispredict about one comparison in two on residuals; these loops have no data-dependent branch.
#pragma once

#include <cstddef>

#include "real/vector_kernels.h"

namespace edgetrack {

/// How many of x[0..n) lie below `pivot` and how many above it, one number per lane.
template <class T>
__attribute__((always_inline)) inline void count_around(size_t n, const T* __restrict x, const T& pivot, size_t& below,
                                                        size_t& above) {
  const T p = pivot;
  size_t low = 0, high = 0;
  for (size_t i = 0; i < n; ++i) {
    low += x[i] < p;
    high += p < x[i];
  }
  below = low;
  above = high;
}

/// The k-th smallest (0-based) of values[0..n), k < n, no NaN among them: the number
/// std::nth_element places at k. `values` is work.
template <class T>
T kth_smallest(T* values, size_t n, size_t k) {
  T* const in = values;
  size_t length = n;
  constexpr size_t kSmall = 16;  // below this, an insertion sort
  while (length > kSmall) {
    // The median of the first, middle and last numbers as the pivot.
    const T& x = in[0];
    const T& y = in[length / 2];
    const T& z = in[length - 1];
    const T low = y < x ? y : x, high = y < x ? x : y;
    const T pivot = z < high ? (low < z ? z : low) : high;
    size_t below = 0, above = 0;
    vector_kernels::run([&]() __attribute__((always_inline)) { count_around(length, in, pivot, below, above); });
    // Numbers equal to the pivot hold the ranks [below, length - above) (neither v < pivot nor
    // pivot < v: for magnitudes, the same number).
    if (k >= below && k < length - above) return pivot;
    // Keep the side holding k at the front: each number is written at the next free place,
    // which moves on only when the number is kept (it never passes the number being read).
    size_t kept = 0;
    if (k < below) {
      for (size_t i = 0; i < length; ++i) {
        const T v = in[i];
        in[kept] = v;
        kept += v < pivot;
      }
    } else {
      for (size_t i = 0; i < length; ++i) {
        const T v = in[i];
        in[kept] = v;
        kept += pivot < v;
      }
      k -= length - above;
    }
    length = kept;
  }
  for (size_t i = 1; i < length; ++i) {
    const T v = in[i];
    size_t j = i;
    for (; j > 0 && v < in[j - 1]; --j) in[j] = in[j - 1];
    in[j] = v;
  }
  return in[k];
}

}  // namespace edgetrack
