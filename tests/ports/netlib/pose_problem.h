// SPDX-License-Identifier: BSD-3-Clause
/// Synthetic edge-based pose problems, shared by the LM tests and the LM benchmark: the
/// paper's pose step (section 2, equations (2)-(3)) on a 60 mm cube about 150 mm in front of a
/// QVGA camera (px = py = 300, u0 = 160, v0 = 120), with ~60 control points on the visible
/// edges, each observed with seeded Gaussian noise along its projected edge normal.
///
/// Frames and units: camera_from_model maps model points (metres) to camera points; pixels for
/// residuals. The six parameters x = (w, t) give the pose R = exp([w]x) R0, translation t in
/// millimetres (see kMillimetresPerMetre), where R0 is the start rotation (so the start is
/// w = 0, t = t0). Residual i is eq. (3) without the absolute value, (q_i - p_i(x)) . n_i: the
/// signed distance in pixels from the projected control point p_i to the observed edge line
/// through q_i with normal n_i.
#pragma once

#include <cstdint>
#include <vector>

#include "vnl/vnl_least_squares_function.h"
#include "vnl/vnl_matrix_fixed.h"
#include "vnl/vnl_rotation_matrix.h"
#include "vnl/vnl_vector_fixed.h"

namespace pose_problem {

/// The solver works in millimetres (the parameters t and the points inside Residuals). In
/// metres the Jacobian's translation columns are ~2000 px/m, past the 512 below which S40.23's
/// multiply is one 32 x 32-bit product (ports/real/include/real/fixed64.h), both in the Jacobian
/// and in MINPACK's QR of it; in millimetres they are ~2 px/mm, and the model points get 1000x
/// finer fixed-point resolution. MINPACK (mode 1) scales each column by its norm, so in exact
/// arithmetic the iterations do not depend on the unit (docs/results/lm.md: what it saves).
constexpr double kMillimetresPerMetre = 1000;

using Vec3 = vnl_vector_fixed<double, 3>;
using Mat33 = vnl_matrix_fixed<double, 3, 3>;

struct Pose {
  Mat33 rotation;    ///< camera_from_model rotation
  Vec3 translation;  ///< metres
};

struct ControlPoint {
  Vec3 point_in_model;  ///< on a visible cube edge, metres
  double q[2];          ///< observed edge point, pixels
  double n[2];          ///< unit normal of the projected edge at the true pose
};

/// One problem: the camera, the true pose, the start pose and the control points.
struct Problem {
  double px = 300, py = 300, u0 = 160, v0 = 120;
  /// The solver's length unit (its t and points): millimetres; 1 gives the paper's metres.
  double units_per_metre = kMillimetresPerMetre;
  Pose truth;
  Pose start;
  std::vector<ControlPoint> points;
};

/// Problem number `seed`: a random cube orientation, the cube's centre within 10 mm of the
/// optical axis at 150 mm, 60 control points spread evenly over the visible edges, noise of
/// sigma 0.3 px, and a start pose off by a random rotation of up to 5 degrees and a random
/// translation of up to 5 mm. Deterministic for a given seed on every platform.
Problem generate(std::uint32_t seed);

/// The pose (translation in metres) given by the parameters x = (w, t in the problem's unit).
Pose pose_from_parameters(const Problem& problem, const double x[6]);
/// Angle of R_a R_b^T in degrees.
double rotation_error_deg(const Pose& a, const Pose& b);
/// |t_a - t_b| in millimetres.
double translation_error_mm(const Pose& a, const Pose& b);

/// The residuals and their analytic Jacobian in scalar T. The problem's data are converted to
/// T once, here; evaluating runs T arithmetic only.
template <class T>
class Residuals : public vnl_least_squares_function_of<T> {
 public:
  explicit Residuals(const Problem& problem);

  /// f (size m) at x (size 6).
  void residuals(const T* x, T* f) const;
  /// The m x 6 Jacobian, column-major with leading dimension ld.
  void jacobian(const T* x, T* fjac, int ld) const { jacobian_strided(x, fjac, 1, ld); }
  /// The start parameters (0, 0, 0, t0 in millimetres).
  vnl_vector<T> start() const;

  void f(const vnl_vector<T>& x, vnl_vector<T>& fx) override { residuals(x.data_block(), fx.data_block()); }
  void gradf(const vnl_vector<T>& x, vnl_matrix<T>& J) override {
    jacobian_strided(x.data_block(), J.data_block(), 6, 1);
  }

 private:
  /// Writes d f_i / d x_j to J[i * row_step + j * column_step].
  void jacobian_strided(const T* x, T* J, int row_step, int column_step) const;
  /// Camera point of control point i for rotation exp(w) R0 and translation t, plus R Y_i.
  void camera_point(const vnl_matrix_fixed<T, 3, 3>& R, const T* t, int i, vnl_vector_fixed<T, 3>& rotated,
                    vnl_vector_fixed<T, 3>& in_camera) const;

  T px_, py_, u0_, v0_;
  T aspect_;                               ///< py / px
  std::vector<vnl_vector_fixed<T, 3>> y_;  ///< R0 * point_in_model, millimetres
  std::vector<T> q_;                       ///< 2 per point
  std::vector<T> n_;                       ///< 2 per point
  vnl_vector_fixed<T, 3> t0_;              ///< start translation, millimetres
};

}  // namespace pose_problem
