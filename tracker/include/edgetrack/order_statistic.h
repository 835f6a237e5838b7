// SPDX-License-Identifier: BSD-3-Clause
/// The k-th smallest of some numbers without a branch per comparison: a quickselect whose
/// partitions write each number to both ends of a second buffer and move the ends by the
/// comparisons' results. On a host CPU std::nth_element's partitions mispredict about one
/// comparison in two on residuals; this loop has no data-dependent branch.
#pragma once

#include <algorithm>
#include <cstddef>
#include <type_traits>

namespace edgetrack {

/// The k-th smallest (0-based) of values[0..n), k < n, no NaN among them: the number
/// std::nth_element places at k. `values` and `other` (n entries each) are work.
template <class T>
T kth_smallest(T* values, T* other, size_t n, size_t k) {
  T* in = values;
  bool in_values = true;  // which buffer `in` lies in; each partition writes the other
  size_t length = n;
  constexpr size_t kSmall = 16;  // below this, an insertion sort
  while (length > kSmall) {
    // The median of the first, middle and last numbers as the pivot.
    const T& x = in[0];
    const T& y = in[length / 2];
    const T& z = in[length - 1];
    const T low = y < x ? y : x, high = y < x ? x : y;
    const T pivot = z < high ? (low < z ? z : low) : high;
    T* const out = in_values ? other : values;
    // Those below the pivot go to out[0, below), those above to out[above, length); the slots
    // between are free (each step writes both ends, only one end moves).
    size_t below = 0, above = length;
    for (size_t i = 0; i < length; ++i) {
      const T v = in[i];
      out[below] = v;
      out[above - 1] = v;
      below += v < pivot;
      above -= pivot < v;
    }
    // Numbers equal to the pivot fill [below, above) (neither v < pivot nor pivot < v: for
    // magnitudes, the same number).
    if (k >= below && k < above) return pivot;
    if (k < below) {
      in = out;
      length = below;
    } else {
      in = out + above;
      length -= above;
      k -= above;
    }
    in_values = !in_values;
  }
  for (size_t i = 1; i < length; ++i) {
    const T v = in[i];
    size_t j = i;
    for (; j > 0 && v < in[j - 1]; --j) in[j] = in[j - 1];
    in[j] = v;
  }
  return in[k];
}

/// The median of values[0..n), n > 0, as std::nth_element places it at n / 2 (the upper middle
/// one for an even n); `values` and `other` (n entries each) are work. The same number either
/// way: floating point by kth_smallest (a host CPU mispredicts nth_element's comparisons), fixed
/// point (ARMv5TE, no such cost) by std::nth_element in place.
template <class T>
T median_of_values(T* values, T* other, size_t n) {
  const size_t mid = n / 2;
  if constexpr (std::is_floating_point<T>::value) {
    return kth_smallest(values, other, n, mid);
  } else {
    std::nth_element(values, values + mid, values + n);
    return values[mid];
  }
}

}  // namespace edgetrack
