// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_quaternion.h: a unit quaternion for 3-D rotations, stored as
/// upstream stores it, (x, y, z, r): the imaginary part first, the real part last.
/// Upstream's conventions kept: rotation_matrix_transpose() is R^T for the rotation R that
/// rotate() applies (rotate(v) == R v), and the matrix constructor takes that same R^T.
/// Angles are in radians; for fixed-point T the trigonometry runs in T.
#pragma once

#ifdef vnl_quaternion_h_
#error "edgetrack's drop-in vnl/vnl_quaternion.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <iosfwd>

#include "vnl/vnl_matrix_fixed.h"
#include "vnl/vnl_vector_fixed.h"

inline namespace edgetrack_ports {

template <class T>
class vnl_quaternion : public vnl_vector_fixed<T, 4> {
  using Base = vnl_vector_fixed<T, 4>;

 public:
  /// The identity rotation (0, 0, 0, 1) (upstream: uninitialised).
  vnl_quaternion() : Base(T(0), T(0), T(0), T(1)) {}
  vnl_quaternion(T x, T y, T z, T r) : Base(x, y, z, r) {}
  /// The rotation by `angle` radians about the unit vector `axis`.
  vnl_quaternion(const vnl_vector_fixed<T, 3>& axis, double angle);
  /// The rotation whose transposed matrix is `transform` (see rotation_matrix_transpose).
  explicit vnl_quaternion(const vnl_matrix_fixed<T, 3, 3>& transform);
  /// The pure quaternion (vec, 0); implicit, as upstream's.
  vnl_quaternion(const vnl_vector_fixed<T, 3>& vec);
  /// The four values in (x, y, z, r) order; implicit, as upstream's.
  vnl_quaternion(const vnl_vector_fixed<T, 4>& vec) : Base(vec) {}
  /// Rotation about X by theta_x, then Y by theta_y, then Z by theta_z (Rz * Ry * Rx).
  vnl_quaternion(T theta_x, T theta_y, T theta_z);

  T& x() { return (*this)[0]; }
  T& y() { return (*this)[1]; }
  T& z() { return (*this)[2]; }
  T& r() { return (*this)[3]; }
  T x() const { return (*this)[0]; }
  T y() const { return (*this)[1]; }
  T z() const { return (*this)[2]; }
  T r() const { return (*this)[3]; }
  T real() const { return r(); }
  vnl_vector_fixed<T, 3> imaginary() const { return vnl_vector_fixed<T, 3>(x(), y(), z()); }

  /// The unit rotation axis; (0, 0, 1) for a quaternion with no imaginary part.
  vnl_vector_fixed<T, 3> axis() const;
  /// The rotation angle in [0, 2 pi], 2 atan2(|imaginary|, real).
  double angle() const;
  /// R^T for the rotation this unit quaternion applies.
  vnl_matrix_fixed<T, 3, 3> rotation_matrix_transpose() const;
  /// The same in the top-left block of a 4x4 identity.
  vnl_matrix_fixed<T, 4, 4> rotation_matrix_transpose_4() const;
  /// (theta_x, theta_y, theta_z) with vnl_quaternion(theta_x, theta_y, theta_z) == *this.
  vnl_vector_fixed<T, 3> rotation_euler_angles() const;

  vnl_quaternion conjugate() const { return vnl_quaternion(-x(), -y(), -z(), r()); }
  /// conjugate() / |q|^2.
  vnl_quaternion inverse() const;
  /// The Hamilton product: rotating by (q1 * q2) rotates by q2, then by q1.
  vnl_quaternion operator*(const vnl_quaternion& rhs) const;
  /// R v for the rotation this unit quaternion represents.
  vnl_vector_fixed<T, 3> rotate(const vnl_vector_fixed<T, 3>& v) const;
};

/// Prints x y z r.
template <class T>
std::ostream& operator<<(std::ostream& os, const vnl_quaternion<T>& q);

}  // inline namespace edgetrack_ports
