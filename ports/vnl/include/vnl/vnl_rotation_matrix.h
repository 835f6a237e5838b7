// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_rotation_matrix.h (Rodrigues' formula from a rotation vector),
/// extended with what a pose solver on the exponential map needs: the inverse (the paper's
/// thetaU, i.e. the logarithm), the cross-product matrix, and the series coefficients of exp.
/// Every function is templated on the scalar and stays accurate near zero angle in fixed
/// point: the angle comes from a scaled norm and the sin/cos ratios switch to their Taylor
/// series wherever the series is exact to the type's epsilon.
///
/// Conventions: a rotation vector w = theta * u (unit axis u, angle theta in radians, the
/// right-hand rule); R = exp([w]x) rotates column vectors, p' = R * p.
#pragma once

#ifdef vnl_rotation_matrix_h_
#error "edgetrack's drop-in vnl/vnl_rotation_matrix.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/vnl_matrix_fixed.h"
#include "vnl/vnl_vector_fixed.h"

inline namespace edgetrack_ports {

/// The coefficients of exp([w]x) = I + a [w]x + b [w]x^2 and of the translation part of the
/// SE(3) exponential, V = I + b [w]x + c [w]x^2, for angle theta = |w|.
template <class T>
struct vnl_rotation_coefficients {
  T theta;  ///< |w|, computed without squaring underflow
  T a;      ///< sin(theta) / theta
  T b;      ///< (1 - cos(theta)) / theta^2
  T c;      ///< (theta - sin(theta)) / theta^3
};

/// a, b and c for the rotation vector w (see vnl_rotation_coefficients); exact limits 1, 1/2
/// and 1/6 at w = 0.
template <class T>
vnl_rotation_coefficients<T> vnl_rotation_exp_coefficients(const vnl_vector_fixed<T, 3>& w);

/// The cross-product matrix [w]x, so that [w]x * p == vnl_cross_3d(w, p).
template <class T>
vnl_matrix_fixed<T, 3, 3> vnl_rotation_hat(const vnl_vector_fixed<T, 3>& w);

/// The inverse of vnl_rotation_hat: w from [w]x, using the antisymmetric part of m.
template <class T>
vnl_vector_fixed<T, 3> vnl_rotation_vee(const vnl_matrix_fixed<T, 3, 3>& m);

/// Rodrigues' formula: the rotation matrix exp([w]x) for the rotation vector w.
template <class T>
vnl_matrix_fixed<T, 3, 3> vnl_rotation_matrix(const vnl_vector_fixed<T, 3>& w);

/// Upstream's double overloads: the rotation about `axis` by the angle |axis| into R (given as
/// rows, a row-pointer table, a C array or a vnl matrix); true as upstream (they cannot fail).
bool vnl_rotation_matrix(const double axis[3], double R[3][3]);
bool vnl_rotation_matrix(const double axis[3], double** R);
bool vnl_rotation_matrix(const double axis[3], double* R0, double* R1, double* R2);
bool vnl_rotation_matrix(const vnl_vector<double>& axis, vnl_matrix<double>& R);
bool vnl_rotation_matrix(const vnl_vector_fixed<double, 3>& axis, vnl_matrix_fixed<double, 3, 3>& R);
/// The rotation about a 3-element vnl_vector, as a 3 x 3 vnl_matrix.
vnl_matrix<double> vnl_rotation_matrix(const vnl_vector<double>& axis);

/// The logarithm: the rotation vector thetaU (theta in [0, pi]) with
/// vnl_rotation_matrix(thetaU) == R, for a rotation matrix R. Near theta = pi the axis comes
/// from the symmetric part of R, so it stays accurate there too.
template <class T>
vnl_vector_fixed<T, 3> vnl_rotation_thetau(const vnl_matrix_fixed<T, 3, 3>& R);

}  // inline namespace edgetrack_ports
