// SPDX-License-Identifier: BSD-3-Clause
// vnl_svd as upstream's algo test_svd.cxx: U W V^T recomposes M, U and V are orthonormal, the
// singular values of a known matrix, pseudo-inverse and least-squares solve, rank and null
// vector of a rank-deficient matrix. Our algorithm is one-sided Jacobi (upstream: LINPACK).
#include <string>

#include "algo_test_support.h"
#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_matrix_inverse.h"
#include "vnl/algo/vnl_svd.h"
#include "vnl/vnl_math.h"

namespace {

template <class T>
struct CheckSvd {
  static void run(const std::string& type) {
    const std::string in = " (" + type + ")";
    const double tol = decomposition_tol<T>();
    // A 2x2 with known singular values: [[3, 0], [4, 5]] has sigma = 3 sqrt(5), sqrt(5).
    const T d[] = {T(3), T(0), T(4), T(5)};
    const vnl_svd<T> s2(vnl_matrix<T>(d, 2, 2));
    TEST_NEAR("sigma_max of [[3,0],[4,5]] is 3 sqrt 5" + in, s2.sigma_max(), 3 * std::sqrt(5.0), tol * 8);
    TEST_NEAR("sigma_min of [[3,0],[4,5]] is sqrt 5" + in, s2.sigma_min(), std::sqrt(5.0), tol * 8);
    TEST_NEAR("determinant_magnitude is |det| = 15" + in, s2.determinant_magnitude(), 15.0, tol * 64);
    TEST("rank of a full-rank 2x2 is 2" + in, s2.rank(), 2u);

    const vnl_matrix<T> a = random_matrix<T>(5, 3, 17);
    const vnl_svd<T> svd(a);
    TEST("U is 5 x 3, V is 3 x 3" + in, svd.U().rows() == 5 && svd.U().cols() == 3 && svd.V().rows() == 3, true);
    TEST_NEAR("U W V^T recomposes M" + in, distance(svd.recompose(), a), 0.0, tol * 4);
    TEST_NEAR("U^T U is I" + in, orthonormality_error(svd.U()), 0.0, tol * 4);
    TEST_NEAR("V^T V is I" + in, orthonormality_error(svd.V()), 0.0, tol * 4);
    TEST("singular values descend" + in, svd.W(0) >= svd.W(1) && svd.W(1) >= svd.W(2), true);
    TEST("the decomposition converged" + in, svd.valid(), true);
    // The pseudo-inverse solves the least-squares problem: M^T (M x - b) = 0.
    vnl_vector<T> b(5);
    for (unsigned i = 0; i < 5; ++i) b[i] = T(int(i) - 2);
    const vnl_vector<T> x = svd.solve(b);
    TEST_NEAR("solve gives the least-squares x (normal equations)" + in,
              static_cast<double>((a.transpose() * (a * x - b)).inf_norm()), 0.0, tol * 16);
    TEST_NEAR("pinverse * M is I" + in, distance(svd.pinverse() * a, vnl_matrix<T>(3, 3, vnl_matrix_identity)), 0.0,
              tol * 16);
    const vnl_matrix<T> square = random_matrix<T>(3, 3, 5);
    const vnl_matrix<T> inverse = vnl_matrix_inverse<T>(square);
    TEST_NEAR("vnl_matrix_inverse: M * inv(M) is I" + in,
              distance(square * inverse, vnl_matrix<T>(3, 3, vnl_matrix_identity)), 0.0, tol * 64);

    // Rank 2: the third column is the sum of the first two.
    vnl_matrix<T> r(4, 3);
    for (unsigned i = 0; i < 4; ++i) {
      r(i, 0) = T(int(i) + 1);
      r(i, 1) = T(int(i * i) - 1);
      r(i, 2) = r(i, 0) + r(i, 1);
    }
    vnl_svd<T> rs(r, -1e-4);  // zero singular values below 1e-4 sigma_max
    TEST("rank of a rank-2 4x3 matrix is 2" + in, rs.rank(), 2u);
    TEST("singularities() is 1" + in, rs.singularities(), 1);
    const vnl_vector<T> null = rs.nullvector();
    TEST_NEAR("M * nullvector is 0" + in, static_cast<double>((r * null).inf_norm()), 0.0, tol * 64);
    TEST_NEAR("nullvector is (1, 1, -1) / sqrt 3 up to sign" + in, vnl_math::abs(null[0] + null[2]), 0.0, tol * 16);
    TEST("nullspace() has one column" + in, rs.nullspace().cols(), 1u);
    TEST_NEAR("left nullvector is orthogonal to M's columns" + in,
              static_cast<double>((rs.left_nullvector() * r).inf_norm()), 0.0, tol * 64);
    // A wide matrix (m < n) decomposes too.
    const vnl_matrix<T> wide = random_matrix<T>(2, 4, 3);
    const vnl_svd<T> ws(wide);
    TEST_NEAR("a 2x4 matrix recomposes" + in, distance(ws.recompose(), wide), 0.0, tol * 4);
    TEST("a 2x4 matrix has rank 2" + in, ws.rank(), 2u);
  }
};

void test_svd() { for_each_test_scalar<CheckSvd>(); }

}  // namespace

TESTMAIN(test_svd)
