// SPDX-License-Identifier: BSD-3-Clause
/// Definitions for vnl_rotation_matrix.h. Include it only to instantiate the rotation helpers
/// for a scalar that the library does not instantiate.
#pragma once

#include <cmath>
#include <limits>

#include "vnl/vnl_rotation_matrix.h"

inline namespace edgetrack_ports {

namespace vnl_rotation_detail {

/// |w| as m * sqrt(sum (w_i / m)^2), m = max |w_i|: no underflow of the squares in fixed point.
template <class T>
T scaled_norm(const vnl_vector_fixed<T, 3>& w) {
  using std::abs;
  using std::sqrt;
  T m = abs(w[0]);
  if (abs(w[1]) > m) m = abs(w[1]);
  if (abs(w[2]) > m) m = abs(w[2]);
  if (m == T(0)) return T(0);
  T sum(0);
  for (unsigned i = 0; i < 3; ++i) {
    const T r = w[i] / m;
    sum += r * r;
  }
  return m * sqrt(sum);
}

/// a, b, c from theta. The Taylor series below stop at the t^4 term (t = theta^2); their first
/// dropped term is at most t^5 / 11! (for a), so they are used while that is below epsilon.
/// Elsewhere the closed forms have no harmful cancellation.
template <class T>
vnl_rotation_coefficients<T> coefficients_from_theta(const T& theta) {
  using std::cos;
  using std::sin;
  const T series_limit = T(39916800) * std::numeric_limits<T>::epsilon();
  const T t = theta * theta;
  vnl_rotation_coefficients<T> k{theta, T(0), T(0), T(0)};
  if (t * t * t * t * t < series_limit) {
    k.a = T(1) - t / 6 * (T(1) - t / 20 * (T(1) - t / 42 * (T(1) - t / 72)));
    k.b = (T(1) - t / 12 * (T(1) - t / 30 * (T(1) - t / 56 * (T(1) - t / 90)))) / 2;
    k.c = (T(1) - t / 20 * (T(1) - t / 42 * (T(1) - t / 72 * (T(1) - t / 110)))) / 6;
  } else {
    const T s = sin(theta);
    k.a = s / theta;
    k.b = (T(1) - cos(theta)) / t;
    k.c = (T(1) - k.a) / t;
  }
  return k;
}

}  // namespace vnl_rotation_detail

template <class T>
vnl_rotation_coefficients<T> vnl_rotation_exp_coefficients(const vnl_vector_fixed<T, 3>& w) {
  return vnl_rotation_detail::coefficients_from_theta(vnl_rotation_detail::scaled_norm(w));
}

template <class T>
vnl_matrix_fixed<T, 3, 3> vnl_rotation_hat(const vnl_vector_fixed<T, 3>& w) {
  vnl_matrix_fixed<T, 3, 3> m;
  m(0, 1) = -w[2];
  m(0, 2) = w[1];
  m(1, 0) = w[2];
  m(1, 2) = -w[0];
  m(2, 0) = -w[1];
  m(2, 1) = w[0];
  return m;
}

template <class T>
vnl_vector_fixed<T, 3> vnl_rotation_vee(const vnl_matrix_fixed<T, 3, 3>& m) {
  return vnl_vector_fixed<T, 3>((m(2, 1) - m(1, 2)) / 2, (m(0, 2) - m(2, 0)) / 2, (m(1, 0) - m(0, 1)) / 2);
}

template <class T>
vnl_matrix_fixed<T, 3, 3> vnl_rotation_matrix(const vnl_vector_fixed<T, 3>& w) {
  const vnl_rotation_coefficients<T> k = vnl_rotation_exp_coefficients(w);
  // R = I + a [w]x + b [w]x^2, with [w]x^2 = w w^T - theta^2 I.
  vnl_matrix_fixed<T, 3, 3> R;
  const T diagonal = T(1) - k.b * k.theta * k.theta;
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned j = 0; j < 3; ++j) R(i, j) = k.b * (w[i] * w[j]);
    R(i, i) += diagonal;
  }
  const T ax = k.a * w[0];
  const T ay = k.a * w[1];
  const T az = k.a * w[2];
  R(0, 1) -= az;
  R(1, 0) += az;
  R(0, 2) += ay;
  R(2, 0) -= ay;
  R(1, 2) -= ax;
  R(2, 1) += ax;
  return R;
}

template <class T>
vnl_vector_fixed<T, 3> vnl_rotation_thetau(const vnl_matrix_fixed<T, 3, 3>& R) {
  using std::atan2;
  using std::sqrt;
  static constexpr T kHalf = T(0.5);
  static constexpr T kNearPiCos = T(-0.5);
  // v = sin(theta) u, from the antisymmetric part; cos(theta) from the trace.
  const vnl_vector_fixed<T, 3> v = vnl_rotation_vee(R);
  T c = (R(0, 0) + R(1, 1) + R(2, 2) - T(1)) * kHalf;
  if (c > T(1)) c = T(1);
  if (c < T(-1)) c = T(-1);
  const T s = vnl_rotation_detail::scaled_norm(v);
  const T theta = atan2(s, c);
  if (c > kNearPiCos) {
    // theta < 120 degrees: divide v by sin(theta)/theta, which is 1 near zero.
    return v / vnl_rotation_detail::coefficients_from_theta(theta).a;
  }
  // Near pi, sin(theta) is small: take u from (R + R^T)/2 - cos(theta) I = (1 - cos(theta)) u u^T,
  // using its largest diagonal entry, and the sign of u from v.
  vnl_matrix_fixed<T, 3, 3> B;
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned j = 0; j < 3; ++j) B(i, j) = (R(i, j) + R(j, i)) * kHalf;
    B(i, i) -= c;
  }
  unsigned k = 0;
  if (B(1, 1) > B(k, k)) k = 1;
  if (B(2, 2) > B(k, k)) k = 2;
  const T scale = sqrt(B(k, k) * (T(1) - c));
  vnl_vector_fixed<T, 3> u(B(0, k) / scale, B(1, k) / scale, B(2, k) / scale);
  if (dot_product(u, v) < T(0)) u = -u;
  return u * theta;
}

/// Explicitly instantiates the rotation helpers for T (used by instances/).
#define VNL_ROTATION_MATRIX_INSTANTIATE(T)                                                            \
  template vnl_rotation_coefficients<T> vnl_rotation_exp_coefficients(const vnl_vector_fixed<T, 3>&); \
  template vnl_matrix_fixed<T, 3, 3> vnl_rotation_hat(const vnl_vector_fixed<T, 3>&);                 \
  template vnl_vector_fixed<T, 3> vnl_rotation_vee(const vnl_matrix_fixed<T, 3, 3>&);                 \
  template vnl_matrix_fixed<T, 3, 3> vnl_rotation_matrix(const vnl_vector_fixed<T, 3>&);              \
  template vnl_vector_fixed<T, 3> vnl_rotation_thetau(const vnl_matrix_fixed<T, 3, 3>&)

}  // inline namespace edgetrack_ports
