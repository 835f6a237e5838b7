// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_c_vector.h: the vector operations on plain T arrays that vnl's
/// containers are built from (sum, norms, dot products, element-wise arithmetic).
#pragma once

#ifdef vnl_c_vector_h_
#error "edgetrack's drop-in vnl/vnl_c_vector.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cmath>
#include <cstddef>

#include "vnl/vnl_math.h"
#include "vnl/vnl_numeric_traits.h"

inline namespace edgetrack_ports {

template <class T>
class vnl_c_vector {
 public:
  using abs_t = typename vnl_numeric_traits<T>::abs_t;
  using real_t = typename vnl_numeric_traits<T>::real_t;

  static T sum(const T* v, unsigned n) {
    T total(0);
    for (unsigned i = 0; i < n; ++i) total += v[i];
    return total;
  }
  static abs_t squared_magnitude(const T* p, unsigned n) { return two_nrm2(p, n); }
  /// Scales p to unit two-norm (p and q may be the same).
  static void normalize(T* v, unsigned n) {
    const abs_t norm = two_norm(v, n);
    if (norm == abs_t(0)) return;
    for (unsigned i = 0; i < n; ++i) v[i] = T(v[i] / norm);
  }
  static void apply(const T* v, unsigned n, T (*f)(T), T* v_out) {
    for (unsigned i = 0; i < n; ++i) v_out[i] = f(v[i]);
  }
  static void apply(const T* v, unsigned n, T (*f)(const T&), T* v_out) {
    for (unsigned i = 0; i < n; ++i) v_out[i] = f(v[i]);
  }
  static void copy(const T* src, T* dst, unsigned n) {
    for (unsigned i = 0; i < n; ++i) dst[i] = src[i];
  }
  /// y = a * x.
  static void scale(const T* x, T* y, unsigned n, const T& a) {
    for (unsigned i = 0; i < n; ++i) y[i] = a * x[i];
  }
  static void add(const T* x, const T* y, T* z, unsigned n) {
    for (unsigned i = 0; i < n; ++i) z[i] = x[i] + y[i];
  }
  static void add(const T* x, const T& y, T* z, unsigned n) {
    for (unsigned i = 0; i < n; ++i) z[i] = x[i] + y;
  }
  static void subtract(const T* x, const T* y, T* z, unsigned n) {
    for (unsigned i = 0; i < n; ++i) z[i] = x[i] - y[i];
  }
  static void subtract(const T* x, const T& y, T* z, unsigned n) {
    for (unsigned i = 0; i < n; ++i) z[i] = x[i] - y;
  }
  static void multiply(const T* x, const T* y, T* z, unsigned n) {
    for (unsigned i = 0; i < n; ++i) z[i] = x[i] * y[i];
  }
  static void multiply(const T* x, const T& y, T* z, unsigned n) {
    for (unsigned i = 0; i < n; ++i) z[i] = x[i] * y;
  }
  static void divide(const T* x, const T* y, T* z, unsigned n) {
    for (unsigned i = 0; i < n; ++i) z[i] = x[i] / y[i];
  }
  static void divide(const T* x, const T& y, T* z, unsigned n) {
    for (unsigned i = 0; i < n; ++i) z[i] = x[i] / y;
  }
  /// y = -x.
  static void negate(const T* x, T* y, unsigned n) {
    for (unsigned i = 0; i < n; ++i) y[i] = -x[i];
  }
  /// y = 1 / x.
  static void invert(const T* x, T* y, unsigned n) {
    for (unsigned i = 0; i < n; ++i) y[i] = T(1) / x[i];
  }
  /// y += a * x.
  static void saxpy(const T& a, const T* x, T* y, unsigned n) {
    for (unsigned i = 0; i < n; ++i) y[i] += a * x[i];
  }
  static void fill(T* x, unsigned n, const T& v) {
    for (unsigned i = 0; i < n; ++i) x[i] = v;
  }
  static void reverse(T* x, unsigned n) {
    for (unsigned i = 0; i + 1 < n - i; ++i) {
      const T t = x[i];
      x[i] = x[n - 1 - i];
      x[n - 1 - i] = t;
    }
  }
  static T dot_product(const T* a, const T* b, unsigned n) {
    T total(0);
    for (unsigned i = 0; i < n; ++i) total += a[i] * b[i];
    return total;
  }
  /// sum a_i * conj(b_i).
  static T inner_product(const T* a, const T* b, unsigned n) {
    T total(0);
    for (unsigned i = 0; i < n; ++i) total += a[i] * vnl_math::conj(b[i]);
    return total;
  }
  /// x_i conjugated into y_i.
  static void conjugate(const T* x, T* y, unsigned n) {
    for (unsigned i = 0; i < n; ++i) y[i] = vnl_math::conj(x[i]);
  }
  static T max_value(const T* v, unsigned n) {
    T best = v[0];
    for (unsigned i = 1; i < n; ++i) {
      if (best < v[i]) best = v[i];
    }
    return best;
  }
  static T min_value(const T* v, unsigned n) {
    T best = v[0];
    for (unsigned i = 1; i < n; ++i) {
      if (v[i] < best) best = v[i];
    }
    return best;
  }
  static unsigned arg_max(const T* v, unsigned n) {
    unsigned best = 0;
    for (unsigned i = 1; i < n; ++i) {
      if (v[best] < v[i]) best = i;
    }
    return best;
  }
  static unsigned arg_min(const T* v, unsigned n) {
    unsigned best = 0;
    for (unsigned i = 1; i < n; ++i) {
      if (v[i] < v[best]) best = i;
    }
    return best;
  }
  static T mean(const T* p, unsigned n) { return T(sum(p, n) / abs_t(static_cast<int>(n))); }
  /// Population standard deviation of p.
  /// The sample standard deviation (1/(n-1) normalisation, as upstream).
  static real_t std(const T* p, unsigned n) {
    using std::sqrt;
    return real_t(sqrt(real_t(sum_sq_diff_means(p, n)) / real_t(static_cast<int>(n) - 1)));
  }
  static abs_t sum_sq_diff_means(const T* v, unsigned n) {
    const T m = mean(v, n);
    abs_t total(0);
    for (unsigned i = 0; i < n; ++i) total += abs_t(vnl_math::squared_magnitude(v[i] - m));
    return total;
  }
  static abs_t one_norm(const T* p, unsigned n) {
    abs_t total(0);
    for (unsigned i = 0; i < n; ++i) total += abs_t(vnl_math::abs(p[i]));
    return total;
  }
  static abs_t two_norm(const T* p, unsigned n) {
    using std::sqrt;
    return abs_t(sqrt(two_nrm2(p, n)));
  }
  static abs_t inf_norm(const T* p, unsigned n) {
    abs_t largest(0);
    for (unsigned i = 0; i < n; ++i) {
      const abs_t a = abs_t(vnl_math::abs(p[i]));
      if (largest < a) largest = a;
    }
    return largest;
  }
  static abs_t two_nrm2(const T* p, unsigned n) {
    abs_t total(0);
    for (unsigned i = 0; i < n; ++i) total += abs_t(vnl_math::squared_magnitude(p[i]));
    return total;
  }
  static abs_t rms_norm(const T* p, unsigned n) {
    using std::sqrt;
    return n == 0 ? abs_t(0) : abs_t(sqrt(two_nrm2(p, n) / abs_t(static_cast<int>(n))));
  }
  /// Euclidean distance squared between a and b.
  static abs_t euclid_dist_sq(const T* a, const T* b, unsigned n) {
    abs_t total(0);
    for (unsigned i = 0; i < n; ++i) total += abs_t(vnl_math::squared_magnitude(a[i] - b[i]));
    return total;
  }
  /// A heap array of n T's, freed with deallocate; allocate_Tptr gives n T* slots.
  static T* allocate_T(std::size_t n) { return new T[n]; }
  static void deallocate(T* p, std::size_t) { delete[] p; }
  static T** allocate_Tptr(std::size_t n) { return new T*[n]; }
  static void deallocate(T** p, std::size_t) { delete[] p; }
};

/// Upstream's free-function spelling of vnl_c_vector<T>::inf_norm etc.
template <class T>
typename vnl_c_vector<T>::abs_t vnl_c_vector_inf_norm(const T* p, unsigned n) {
  return vnl_c_vector<T>::inf_norm(p, n);
}
template <class T>
typename vnl_c_vector<T>::abs_t vnl_c_vector_one_norm(const T* p, unsigned n) {
  return vnl_c_vector<T>::one_norm(p, n);
}
template <class T>
typename vnl_c_vector<T>::abs_t vnl_c_vector_two_norm(const T* p, unsigned n) {
  return vnl_c_vector<T>::two_norm(p, n);
}

}  // inline namespace edgetrack_ports
