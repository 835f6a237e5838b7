// SPDX-License-Identifier: BSD-3-Clause
// A program written the way a VXL user writes one, against upstream's headers and types only
// (double throughout, as upstream): it builds unchanged against ports/ for the host and for
// the PXA270, in every `real` build. It rotates points with a quaternion, recovers that
// rotation with an SVD (the orthogonal Procrustes problem), solves a sparse tridiagonal
// system, and finds a polynomial's root with Newton's method. Exit status 0 when each result
// is what the maths says it must be.
#include <cmath>
#include <iostream>

#include <vnl/algo/vnl_svd.h>
#include <vnl/vnl_double_3.h>
#include <vnl/vnl_double_3x3.h>
#include <vnl/vnl_math.h>
#include <vnl/vnl_matrix.h>
#include <vnl/vnl_quaternion.h>
#include <vnl/vnl_real_polynomial.h>
#include <vnl/vnl_sparse_matrix.h>
#include <vnl/vnl_vector.h>

namespace {

bool check(const char* what, double error, double tolerance) {
  const bool ok = error <= tolerance;
  std::cout << (ok ? "ok   " : "FAIL ") << what << ": error " << error << '\n';
  return ok;
}

// Rotates four points with a quaternion, then recovers the rotation from the point pairs:
// R = V U^T from the SVD of sum p q^T (Kabsch), and compares it with the quaternion's matrix.
bool quaternion_and_svd() {
  const vnl_double_3 axis = vnl_double_3(1.0, 2.0, 2.0) / 3.0;
  const vnl_quaternion<double> q(axis, 0.8);
  const vnl_double_3 points[4] = {{1, 0, 0}, {0, 2, 0}, {0, 0, 3}, {1, 1, 1}};
  vnl_matrix<double> covariance(3, 3, 0.0);
  for (const vnl_double_3& p : points) {
    const vnl_double_3 r = q.rotate(p);
    for (unsigned i = 0; i < 3; ++i)
      for (unsigned j = 0; j < 3; ++j) covariance(i, j) += p[i] * r[j];
  }
  vnl_svd<double> svd(covariance);
  const vnl_matrix<double> rotation = svd.V() * svd.U().transpose();
  const vnl_double_3x3 expected = q.rotation_matrix_transpose().transpose();
  return check("rotation recovered by SVD", (rotation - expected.as_matrix()).frobenius_norm(), 1e-12) &&
         check("quaternion angle", std::fabs(q.angle() - 0.8), 1e-15);
}

// The 1-D Poisson matrix tridiag(-1, 2, -1) times x = (1, ..., n) is zero except at the ends.
bool sparse_matrix() {
  const unsigned n = 50;
  vnl_sparse_matrix<double> a(n, n);
  for (unsigned i = 0; i < n; ++i) {
    a(i, i) = 2;
    if (i > 0) a(i, i - 1) = -1;
    if (i + 1 < n) a(i, i + 1) = -1;
  }
  vnl_vector<double> x(n), ax;
  for (unsigned i = 0; i < n; ++i) x[i] = i + 1.0;
  a.mult(x, ax);
  double interior = 0;
  for (unsigned i = 1; i + 1 < n; ++i) interior = std::fmax(interior, std::fabs(ax[i]));
  return check("sparse tridiagonal product, interior", interior, 0.0) &&
         check("sparse tridiagonal product, last row", std::fabs(ax[n - 1] - (n + 1.0)), 0.0);
}

// x^3 - 2x - 5 (Wallis's cubic) has one real root near 2.0945514815423265.
bool polynomial() {
  const double coefficients[] = {1, 0, -2, -5};
  const vnl_real_polynomial p(coefficients, 4);
  double x = 2;
  for (int i = 0; i < 8; ++i) x -= p.evaluate(x) / p.devaluate(x);
  return check("Newton on Wallis's cubic", std::fabs(x - 2.0945514815423265), 1e-15) &&
         check("p(root)", std::fabs(p.evaluate(x)), 1e-13);
}

}  // namespace

int main() {
  const bool ok = quaternion_and_svd() & sparse_matrix() & polynomial();
  std::cout << (ok ? "all checks passed" : "a check failed") << '\n';
  return ok ? 0 : 1;
}
