// SPDX-License-Identifier: BSD-3-Clause
/// The k-th smallest of some numbers without a branch per comparison: a quickselect whose
/// rounds first count the numbers below and above two pivots taken from a sorted sample around
/// k's place (a pass built for the widest vectors, vector_kernels.h) and then keep, in place, only
/// the numbers of the range that holds k, moving the write position by the comparisons' results.
/// On a host CPU std::nth_element's partitions mispredict about one comparison in two on
/// residuals; these loops have no data-dependent branch.
#pragma once

#include <algorithm>
#include <cstddef>
#include <type_traits>

#include "real/vector_kernels.h"

namespace edgetrack {

/// How many of x[0..n) lie below `low` and how many above `high`, one number per lane.
template <class T>
__attribute__((always_inline)) inline void count_outside(size_t n, const T* __restrict x, const T& low, const T& high,
                                                         size_t& below, size_t& above) {
  const T l = low, h = high;
  size_t under = 0, over = 0;
  for (size_t i = 0; i < n; ++i) {
    under += x[i] < l;
    over += h < x[i];
  }
  below = under;
  above = over;
}

/// Moves the numbers v of in[0..n) with keep(v) to its front, in order; returns how many. Each
/// number is written at the next free place, which moves on only when the number is kept (it
/// never passes the number being read).
template <class T, class Keep>
size_t keep_in_place(T* in, size_t n, const Keep& keep) {
  size_t kept = 0;
  for (size_t i = 0; i < n; ++i) {
    const T v = in[i];
    in[kept] = v;
    kept += keep(v);
  }
  return kept;
}

/// Sorts in[0..n) by insertion.
template <class T>
void insertion_sort(T* in, size_t n) {
  for (size_t i = 1; i < n; ++i) {
    const T v = in[i];
    size_t j = i;
    for (; j > 0 && v < in[j - 1]; --j) in[j] = in[j - 1];
    in[j] = v;
  }
}

/// Two numbers of in[0..n), low <= high, between which the k-th smallest probably lies: of nine
/// spread over the array and sorted, the neighbours of the one whose place matches k's.
template <class T>
void bracket_pivots(const T* in, size_t n, size_t k, T& low, T& high) {
  constexpr size_t kLast = 8;
  T sample[kLast + 1];
  for (size_t s = 0; s <= kLast; ++s) sample[s] = in[s * (n - 1) / kLast];
  insertion_sort(sample, kLast + 1);
  const size_t at = k * kLast / (n - 1);
  low = sample[at > 0 ? at - 1 : 0];
  high = sample[at < kLast ? at + 1 : kLast];
}

/// The median of in's first, middle and last numbers.
template <class T>
T median_of_three(const T* in, size_t n) {
  const T& x = in[0];
  const T& y = in[n / 2];
  const T& z = in[n - 1];
  const T low = y < x ? y : x, high = y < x ? x : y;
  return z < high ? (low < z ? z : low) : high;
}

/// The k-th smallest (0-based) of values[0..n), k < n, no NaN among them: the number
/// std::nth_element places at k. `values` is work.
template <class T>
T kth_smallest(T* values, size_t n, size_t k) {
  T* const in = values;
  size_t length = n;
  constexpr size_t kSmall = 16;      // up to this, an insertion sort
  constexpr size_t kBracketed = 32;  // from this, two pivots from a sample
  while (length > kSmall) {
    T low, high;
    if (length >= kBracketed) {
      bracket_pivots(in, length, k, low, high);
    } else {
      low = high = median_of_three(in, length);
    }
    size_t below = 0, above = 0;
    const auto count = [&]() {
      vector_kernels::run([&]() __attribute__((always_inline)) { count_outside(length, in, low, high, below, above); });
    };
    count();
    if (below + above == 0 && low < high) {
      // Every number lies between the pivots: a round about one of them (a number of the
      // array, so that round keeps fewer).
      high = low;
      count();
    }
    if (k < below) {
      length = keep_in_place(in, length, [&low](const T& v) { return v < low; });
    } else if (k >= length - above) {
      k -= length - above;
      length = keep_in_place(in, length, [&high](const T& v) { return high < v; });
    } else if (!(low < high)) {
      // Numbers equal to the pivot hold the ranks [below, length - above) (neither v < pivot
      // nor pivot < v: for magnitudes, the same number).
      return low;
    } else {
      k -= below;
      length = keep_in_place(in, length, [&low, &high](const T& v) { return !(v < low) & !(high < v); });
    }
  }
  insertion_sort(in, length);
  return in[k];
}

/// The k-th smallest (0-based) of values[0..n), k < n, as std::nth_element places it at k;
/// `values` is work (reordered). The same number either way: floating point by kth_smallest (a
/// host CPU mispredicts nth_element's comparisons), fixed point (ARMv5TE, no such cost) by
/// std::nth_element in place.
template <class T>
T kth_of_values(T* values, size_t n, size_t k) {
  if constexpr (std::is_floating_point<T>::value) {
    return kth_smallest(values, n, k);
  } else {
    std::nth_element(values, values + k, values + n);
    return values[k];
  }
}

/// The median of values[0..n), n > 0, as std::nth_element places it at n / 2 (the upper middle
/// one for an even n); `values` is work (reordered).
template <class T>
T median_of_values(T* values, size_t n) {
  return kth_of_values(values, n, n / 2);
}

}  // namespace edgetrack
