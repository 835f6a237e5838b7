// SPDX-License-Identifier: BSD-3-Clause
/// Definitions of pose_problem::Residuals<T>; include once per program for each scalar used.
#pragma once

#include "pose_problem.h"
#include "vnl/vnl_least_squares_function.hxx"
#include "vnl/vnl_rotation_matrix.hxx"

namespace pose_problem {

template <class T>
Residuals<T>::Residuals(const Problem& problem)
    : vnl_least_squares_function_of<T>(6, static_cast<unsigned>(problem.points.size())),
      px_(T(problem.px)),
      py_(T(problem.py)),
      u0_(T(problem.u0)),
      v0_(T(problem.v0)),
      aspect_(T(problem.py / problem.px)) {
  for (const ControlPoint& c : problem.points) {
    const Vec3 y = problem.start.rotation * c.point_in_model * problem.units_per_metre;
    y_.emplace_back(T(y[0]), T(y[1]), T(y[2]));
    q_.push_back(T(c.q[0]));
    q_.push_back(T(c.q[1]));
    n_.push_back(T(c.n[0]));
    n_.push_back(T(c.n[1]));
  }
  for (unsigned i = 0; i < 3; ++i) t0_[i] = T(problem.start.translation[i] * problem.units_per_metre);
}

template <class T>
vnl_vector<T> Residuals<T>::start() const {
  vnl_vector<T> x(6);
  for (unsigned i = 0; i < 3; ++i) x[3 + i] = t0_[i];
  return x;
}

template <class T>
void Residuals<T>::camera_point(const vnl_matrix_fixed<T, 3, 3>& R, const T* t, int i, vnl_vector_fixed<T, 3>& rotated,
                                vnl_vector_fixed<T, 3>& in_camera) const {
  rotated = R * y_[i];
  for (unsigned k = 0; k < 3; ++k) in_camera[k] = rotated[k] + t[k];
}

template <class T>
void Residuals<T>::residuals(const T* x, T* f) const {
  const vnl_matrix_fixed<T, 3, 3> R = vnl_rotation_matrix(vnl_vector_fixed<T, 3>(x));
  vnl_vector_fixed<T, 3> rotated, c;
  for (int i = 0; i < static_cast<int>(y_.size()); ++i) {
    camera_point(R, x + 3, i, rotated, c);
    // px / z (~2 px/mm) carries the division's rounding as a relative error of 2^-23 / 2 only,
    // where 1 / z (~0.007 per mm) would carry 2^-23 / 0.007, i.e. 1e-4 px in fixed point.
    const T pixels_per_mm = px_ / c[2];
    const T u = u0_ + c[0] * pixels_per_mm;
    const T v = v0_ + c[1] * (pixels_per_mm * aspect_);
    f[i] = (q_[2 * i] - u) * n_[2 * i] + (q_[2 * i + 1] - v) * n_[2 * i + 1];
  }
}

template <class T>
void Residuals<T>::jacobian_strided(const T* x, T* J, int row_step, int column_step) const {
  // d(exp([w]x) Y)/dw = -[R Y]x J_l(w), J_l(w) = I + b [w]x + c [w]x^2 (the left Jacobian).
  const vnl_vector_fixed<T, 3> w(x);
  const vnl_matrix_fixed<T, 3, 3> R = vnl_rotation_matrix(w);
  const vnl_rotation_coefficients<T> k = vnl_rotation_exp_coefficients(w);
  const vnl_matrix_fixed<T, 3, 3> W = vnl_rotation_hat(w);
  vnl_matrix_fixed<T, 3, 3> left_jacobian = W * k.b + (W * W) * k.c;
  for (unsigned d = 0; d < 3; ++d) left_jacobian(d, d) += T(1);
  vnl_vector_fixed<T, 3> rotated, c;
  for (int i = 0; i < static_cast<int>(y_.size()); ++i) {
    camera_point(R, x + 3, i, rotated, c);
    // dr/dc = -n . d(u, v)/dc.
    const T inv_z = T(1) / c[2];
    const T a = n_[2 * i] * px_ * inv_z;
    const T b = n_[2 * i + 1] * py_ * inv_z;
    const vnl_vector_fixed<T, 3> dr_dc(-a, -b, (a * c[0] + b * c[1]) * inv_z);
    // dr/dw = dr/dc . (-[R Y]x J_l) = (R Y x dr/dc)^T J_l, since -g^T [p]x = (p x g)^T.
    const vnl_vector_fixed<T, 3> g = vnl_cross_3d(rotated, dr_dc);
    for (unsigned col = 0; col < 3; ++col) {
      T* const row = J + i * row_step;
      row[col * column_step] =
          g[0] * left_jacobian(0, col) + g[1] * left_jacobian(1, col) + g[2] * left_jacobian(2, col);
      row[(3 + col) * column_step] = dr_dc[col];
    }
  }
}

}  // namespace pose_problem
