// SPDX-License-Identifier: BSD-3-Clause
/// vpColVector and vpMatrix: element-wise arithmetic, products and transpose, and the SVD
/// (A = U diag(w) V^T, orthonormal V, w sorted), pseudo-inverse (A A+ A = A) and null space.
#include <cmath>

#include "real/real.h"
#include "real_tolerance.h"
#include "testlib/testlib_test.h"
#include "visp3/core/vpColVector.h"
#include "visp3/core/vpMatrix.h"

namespace {

vpMatrix from_rows(unsigned int rows, unsigned int cols, const double* values) {
  vpMatrix M(rows, cols);
  for (unsigned int r = 0; r < rows; ++r)
    for (unsigned int c = 0; c < cols; ++c) M[r][c] = real(values[r * cols + c]);
  return M;
}

double max_abs_difference(const vpMatrix& A, const vpMatrix& B) {
  double worst = 0;
  for (unsigned int r = 0; r < A.getRows(); ++r)
    for (unsigned int c = 0; c < A.getCols(); ++c)
      worst = std::fmax(worst, std::fabs(static_cast<double>(A[r][c] - B[r][c])));
  return worst;
}

void test_col_vector() {
  vpColVector v(3, real(2));
  vpColVector w(3);
  w[0] = 1;
  w[1] = -2;
  w[2] = 2;
  TEST_NEAR("sum of a sum", (v + w).sum(), 7, 0);
  TEST_NEAR("difference", (v - w)[1], 4, 0);
  TEST_NEAR("scaling", (w * real(3))[2], 6, 0);
  TEST_NEAR("norm of (1, -2, 2)", w.frobeniusNorm(), 3, 1e-6);
  TEST_NEAR("dot product", vpColVector::dotProd(v, w), 2, 0);
  w = real(5);
  TEST_NEAR("assign a scalar to every element", w.sum(), 15, 0);
  w.resize(5);
  TEST_EQUAL("resize", w.size(), 5u);
  TEST_NEAR("resize zeroes", w.sum(), 0, 0);
}

void test_products() {
  const double a[] = {1, 2, 3, 4, 5, 6};
  const vpMatrix A = from_rows(2, 3, a);
  const vpMatrix At = A.t();
  TEST_EQUAL("transpose rows", At.getRows(), 3u);
  TEST_NEAR("transpose element", At[2][1], 6, 0);
  const vpMatrix AAt = A * At;
  TEST_NEAR("A A^T (0, 0)", AAt[0][0], 14, 0);
  TEST_NEAR("A A^T (0, 1)", AAt[0][1], 32, 0);
  TEST_NEAR("A A^T (1, 1)", AAt[1][1], 77, 0);
  vpColVector x(3, real(1));
  TEST_NEAR("A x", (A * x)[1], 15, 0);
  vpMatrix I;
  I.eye(3);
  TEST_NEAR("A I = A", max_abs_difference(A * I, A), 0, 0);
  vpMatrix B(4, 4);
  B.insert(A, 1, 1);
  TEST_NEAR("insert at (1, 1)", B[2][3], 6, 0);
  TEST_NEAR("insert leaves the rest", B[0][0], 0, 0);
  TEST_NEAR("frobenius norm", A.frobeniusNorm(), std::sqrt(91.0), 1e-5);
}

/// The SVD's tolerances at the real's resolution (within_resolution). In fixed point each entry
/// of U w = A V and of V carries the roundings of the ~20 plane rotations it went through (4
/// sweeps, 5 partners each), U's columns are those divided by w (1/w_min = 5.5 here), and each
/// check sums 6 or 7 products of them: V^T V within 32 ulps, U diag(w) V^T within 48, U^T U
/// within 64, A A+ A (through A twice, norms up to 3.5) within 128, the unit null vector (6
/// squares) within 4. S47.16 measures 5, 12, 43, 23 and 1 ulps.
void test_svd() {
  // Columns of very different scale, as the conic rows of an ellipse fit.
  const double a[] = {0.64, 0.01, 0.16, 1.6, 0.2, 1,  0.09, 0.81, -0.54, -0.6, 1.8, 1,  0.25, 0.25, -0.5, 1, -1, 1,
                      0.01, 0.49, 0.14, 0.2, 1.4, 1,  0.81, 0.04, 0.36, -1.8, -0.4, 1,  0.36, 0.36, 0.72, 1.2, 1.2, 1,
                      0.04, 0.64, -0.32, 0.4, -1.6, 1};
  const vpMatrix A = from_rows(7, 6, a);
  vpMatrix U(A), V;
  vpColVector w;
  U.svd(w, V);
  bool sorted = true;
  for (unsigned int k = 1; k < 6; ++k) sorted = sorted && w[k] <= w[k - 1];
  TEST("singular values in decreasing order", sorted, true);
  vpMatrix W(6, 6);
  for (unsigned int k = 0; k < 6; ++k) W[k][k] = w[k];
  TEST_NEAR("U diag(w) V^T reconstructs A", max_abs_difference(U * W * V.t(), A), 0, within_resolution(1e-5, 48));
  vpMatrix I;
  I.eye(6);
  TEST_NEAR("V is orthonormal", max_abs_difference(V.t() * V, I), 0, within_resolution(1e-5, 32));
  TEST_NEAR("U has orthonormal columns", max_abs_difference(U.t() * U, I), 0, within_resolution(1e-5, 64));

  const vpMatrix P = A.pseudoInverse();
  TEST_EQUAL("pseudo-inverse is 6 x 7", P.getRows() * 10 + P.getCols(), 67u);
  TEST_NEAR("A A+ A = A", max_abs_difference(A * P * A, A), 0, within_resolution(1e-4, 128));
  const vpMatrix Pt = A.t().pseudoInverse();
  TEST_NEAR("wide matrix: (A^T)+ = (A+)^T", max_abs_difference(Pt, P.t()), 0, 1e-4);

  // Five points of one conic: the null space is one-dimensional and holds its coefficients.
  const double b[] = {1, 0, 0, 2, 0, 1,   0, 1, 0, 0, 2, 1,   0.25, 0.25, 0.5, 1, 1, 1,
                      1, 1, -2, -2, 2, 1,  0.04, 0.36, 0.24, 0.4, 1.2, 1};
  const vpMatrix B = from_rows(5, 6, b);
  vpMatrix kernel;
  const unsigned int dim = B.nullSpace(kernel, 1);
  TEST_EQUAL("five independent rows in six columns: null space of dimension 1", dim, 1u);
  vpColVector k = kernel.getCol(0);
  TEST_NEAR("null vector has unit norm", k.frobeniusNorm(), 1, within_resolution(1e-5, 4));
  TEST_NEAR("B k = 0", (B * k).frobeniusNorm(), 0, 1e-5);
}

}  // namespace

static void test_matrix() {
  test_col_vector();
  test_products();
  test_svd();
}

TESTMAIN(test_matrix)
