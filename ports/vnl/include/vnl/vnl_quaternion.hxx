// SPDX-License-Identifier: BSD-3-Clause
/// Definitions for vnl_quaternion.h (upstream: core/vnl/vnl_quaternion.hxx).
#pragma once

#include <cmath>
#include <limits>
#include <ostream>

#include "vnl/vnl_cross.h"
#include "vnl/vnl_math.h"
#include "vnl/vnl_quaternion.h"

inline namespace edgetrack_ports {

template <class T>
vnl_quaternion<T>::vnl_quaternion(const vnl_vector_fixed<T, 3>& axis, double angle) {
  using std::cos;
  using std::sin;
  const T half = T(angle) / T(2);  // one conversion from the caller's double
  const T s = sin(half);
  for (unsigned i = 0; i < 3; ++i) (*this)[i] = s * axis[i];
  (*this)[3] = cos(half);
}

template <class T>
vnl_quaternion<T>::vnl_quaternion(const vnl_vector_fixed<T, 3>& vec) : Base(vec[0], vec[1], vec[2], T(0)) {}

template <class T>
vnl_quaternion<T>::vnl_quaternion(const vnl_matrix_fixed<T, 3, 3>& m) {
  // m is R^T. Of 4x^2, 4y^2, 4z^2, 4r^2 (each 1 +- the diagonal terms) take the largest, so
  // the division below is by at least 1 (the four sum to 4).
  using std::sqrt;
  const T d0 = m(0, 0), d1 = m(1, 1), d2 = m(2, 2);
  const T terms[4] = {T(1) + d0 - d1 - d2, T(1) - d0 + d1 - d2, T(1) - d0 - d1 + d2, T(1) + d0 + d1 + d2};
  int largest = 3;
  for (int i = 0; i < 3; ++i) {
    if (terms[i] > terms[largest]) largest = i;
  }
  const T four_q = sqrt(terms[largest]) * T(2);  // 4 times the largest component
  const T inverse = T(1) / four_q;
  T q[4];
  q[largest] = four_q / T(4);
  const T r_part[3] = {m(1, 2) - m(2, 1), m(2, 0) - m(0, 2), m(0, 1) - m(1, 0)};  // 4 r (x, y, z)
  if (largest == 3) {
    for (int i = 0; i < 3; ++i) q[i] = r_part[i] * inverse;
  } else {
    q[3] = r_part[largest] * inverse;
    for (int i = 0; i < 3; ++i) {
      if (i != largest) q[i] = (m(largest, i) + m(i, largest)) * inverse;  // 4 q_largest q_i
    }
  }
  for (int i = 0; i < 4; ++i) (*this)[i] = q[i];
}

template <class T>
vnl_quaternion<T>::vnl_quaternion(T theta_x, T theta_y, T theta_z) {
  using std::cos;
  using std::sin;
  const T hx = theta_x / T(2), hy = theta_y / T(2), hz = theta_z / T(2);
  const vnl_quaternion about_x(sin(hx), T(0), T(0), cos(hx));
  const vnl_quaternion about_y(T(0), sin(hy), T(0), cos(hy));
  const vnl_quaternion about_z(T(0), T(0), sin(hz), cos(hz));
  *this = about_z * about_y * about_x;
}

template <class T>
vnl_vector_fixed<T, 3> vnl_quaternion<T>::axis() const {
  vnl_vector_fixed<T, 3> direction = imaginary();
  const T magnitude = direction.magnitude();
  if (magnitude == T(0)) return vnl_vector_fixed<T, 3>(T(0), T(0), T(1));
  return direction / magnitude;
}

template <class T>
double vnl_quaternion<T>::angle() const {
  using std::atan2;
  return static_cast<double>(T(2) * atan2(imaginary().magnitude(), r()));
}

template <class T>
vnl_matrix_fixed<T, 3, 3> vnl_quaternion<T>::rotation_matrix_transpose() const {
  const T xx = x() * x(), yy = y() * y(), zz = z() * z(), rr = r() * r();
  const T xy = x() * y(), yz = y() * z(), zx = z() * x();
  const T rx = r() * x(), ry = r() * y(), rz = r() * z();
  vnl_matrix_fixed<T, 3, 3> m;
  m(0, 0) = rr + xx - yy - zz;
  m(1, 1) = rr - xx + yy - zz;
  m(2, 2) = rr - xx - yy + zz;
  m(0, 1) = T(2) * (xy + rz);
  m(1, 0) = T(2) * (xy - rz);
  m(0, 2) = T(2) * (zx - ry);
  m(2, 0) = T(2) * (zx + ry);
  m(1, 2) = T(2) * (yz + rx);
  m(2, 1) = T(2) * (yz - rx);
  return m;
}

template <class T>
vnl_matrix_fixed<T, 4, 4> vnl_quaternion<T>::rotation_matrix_transpose_4() const {
  vnl_matrix_fixed<T, 4, 4> m;
  m.set_identity();
  const vnl_matrix_fixed<T, 3, 3> r3 = rotation_matrix_transpose();
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned j = 0; j < 3; ++j) m(i, j) = r3(i, j);
  }
  return m;
}

template <class T>
vnl_vector_fixed<T, 3> vnl_quaternion<T>::rotation_euler_angles() const {
  using std::atan2;
  using std::sqrt;
  const vnl_matrix_fixed<T, 3, 3> m = rotation_matrix_transpose();  // m = R^T
  const T cos_y = sqrt(m(0, 0) * m(0, 0) + m(0, 1) * m(0, 1));
  vnl_vector_fixed<T, 3> angles;
  if (cos_y > std::numeric_limits<T>::epsilon() * T(8)) {
    angles[0] = atan2(m(1, 2), m(2, 2));
    angles[1] = atan2(-m(0, 2), cos_y);
    angles[2] = atan2(m(0, 1), m(0, 0));
  } else {  // gimbal lock: theta_y = +-pi/2, put all of the remaining turn in theta_x
    angles[0] = atan2(-m(2, 1), m(1, 1));
    angles[1] = atan2(-m(0, 2), cos_y);
    angles[2] = T(0);
  }
  return angles;
}

template <class T>
vnl_quaternion<T> vnl_quaternion<T>::inverse() const {
  vnl_quaternion result = conjugate();
  const T norm2 = this->squared_magnitude();
  for (unsigned i = 0; i < 4; ++i) result[i] /= norm2;
  return result;
}

template <class T>
vnl_quaternion<T> vnl_quaternion<T>::operator*(const vnl_quaternion& rhs) const {
  const T r1 = r(), r2 = rhs.r();
  const vnl_vector_fixed<T, 3> i1 = imaginary(), i2 = rhs.imaginary();
  const vnl_vector_fixed<T, 3> im = vnl_cross_3d(i1, i2) + i2 * r1 + i1 * r2;
  return vnl_quaternion(im[0], im[1], im[2], r1 * r2 - dot_product(i1, i2));
}

template <class T>
vnl_vector_fixed<T, 3> vnl_quaternion<T>::rotate(const vnl_vector_fixed<T, 3>& v) const {
  // v + 2 r (i x v) + 2 i x (i x v), for the imaginary part i and real part r.
  const vnl_vector_fixed<T, 3> i = imaginary();
  const vnl_vector_fixed<T, 3> i_cross_v = vnl_cross_3d(i, v);
  return v + i_cross_v * (T(2) * r()) + vnl_cross_3d(i, i_cross_v) * T(2);
}

template <class T>
std::ostream& operator<<(std::ostream& os, const vnl_quaternion<T>& q) {
  return os << static_cast<double>(q.x()) << ' ' << static_cast<double>(q.y()) << ' ' << static_cast<double>(q.z())
            << ' ' << static_cast<double>(q.r());
}

#define VNL_QUATERNION_INSTANTIATE(T) \
  template class vnl_quaternion<T>;   \
  template std::ostream& operator<<(std::ostream&, const vnl_quaternion<T>&)

}  // inline namespace edgetrack_ports
