// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_c_na_vector.h: vnl_c_vector's sums and norms that skip
/// "not available" entries (vnl_na, for double and float; other scalars have no NA).
#pragma once

#ifdef vnl_c_na_vector_h_
#error "edgetrack's drop-in vnl/vnl_c_na_vector.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cmath>
#include <type_traits>

#include "vnl/vnl_math.h"
#include "vnl/vnl_na.h"
#include "vnl/vnl_numeric_traits.h"

inline namespace edgetrack_ports {

namespace vnl_c_na_detail {
template <class T>
bool is_na(const T& x) {
  if constexpr (std::is_same_v<T, double> || std::is_same_v<T, float>) {
    return vnl_na_isna(x);
  } else {
    return false;
  }
}
}  // namespace vnl_c_na_detail

template <class T, class S>
void vnl_c_na_vector_one_norm(const T* p, unsigned n, S* out) {
  *out = S(0);
  for (unsigned i = 0; i < n; ++i) {
    if (!vnl_c_na_detail::is_na(p[i])) *out += S(vnl_math::abs(p[i]));
  }
}
template <class T, class S>
void vnl_c_na_vector_two_norm_squared(const T* p, unsigned n, S* out) {
  *out = S(0);
  for (unsigned i = 0; i < n; ++i) {
    if (!vnl_c_na_detail::is_na(p[i])) *out += S(vnl_math::squared_magnitude(p[i]));
  }
}
template <class T, class S>
void vnl_c_na_vector_two_norm(const T* p, unsigned n, S* out) {
  using std::sqrt;
  vnl_c_na_vector_two_norm_squared(p, n, out);
  *out = S(sqrt(*out));
}

template <class T>
class vnl_c_na_vector {
 public:
  using abs_t = typename vnl_numeric_traits<T>::abs_t;
  using real_t = typename vnl_numeric_traits<T>::real_t;

  /// The sum of the entries that are not NA.
  static T sum(const T* v, unsigned n) {
    T total(0);
    for (unsigned i = 0; i < n; ++i) {
      if (!vnl_c_na_detail::is_na(v[i])) total += v[i];
    }
    return total;
  }
  /// Their mean (NA when every entry is NA, for double and float).
  static T mean(const T* p, unsigned n) {
    T total(0);
    unsigned count = 0;
    for (unsigned i = 0; i < n; ++i) {
      if (!vnl_c_na_detail::is_na(p[i])) total += p[i], ++count;
    }
    if (count == 0) {
      if constexpr (std::is_same_v<T, double> || std::is_same_v<T, float>) return vnl_na(T());
      return T(0);
    }
    return total / T(static_cast<int>(count));
  }
  static abs_t squared_magnitude(const T* p, unsigned n) { return two_nrm2(p, n); }
  static abs_t one_norm(const T* p, unsigned n) {
    abs_t v;
    vnl_c_na_vector_one_norm(p, n, &v);
    return v;
  }
  static abs_t two_norm(const T* p, unsigned n) {
    abs_t v;
    vnl_c_na_vector_two_norm(p, n, &v);
    return v;
  }
  static abs_t two_nrm2(const T* p, unsigned n) {
    abs_t v;
    vnl_c_na_vector_two_norm_squared(p, n, &v);
    return v;
  }
};

}  // inline namespace edgetrack_ports
