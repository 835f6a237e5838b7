// SPDX-License-Identifier: BSD-3-Clause
// vnl_ldl_cholesky as upstream's algo test_ldl_cholesky.cxx, on A = R R^T for a random 3 x 3 R:
// L D L^T = A, rank-1, rank-2 and rank-4 updates, the inverse against vnl_inverse, solves of
// A x = b and L x = b, x^T A^-1 x and x^T A x; plus the determinant, rcond and a non-definite M.
#include <string>

#include "algo_test_support.h"
#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_ldl_cholesky.h"
#include "vnl/vnl_det.h"
#include "vnl/vnl_diag_matrix.h"
#include "vnl/vnl_inverse.h"

namespace {
vnl_matrix<double> recomposed(const vnl_ldl_cholesky& chol) {
  return chol.lower_triangle() * vnl_diag_matrix<double>(chol.diagonal()).as_matrix() * chol.upper_triangle();
}
}  // namespace

static void test_ldl_cholesky() {
  vnl_matrix<double> A = random_matrix<double>(3, 3, 1000);
  A = A * A.transpose();
  vnl_matrix<double> I(3, 3);
  I.set_identity();
  {
    const vnl_ldl_cholesky chol(A);
    TEST_NEAR("LDL'=A", (A - recomposed(chol)).fro_norm(), 0.0, 1e-12);
    TEST("L is unit lower triangular", chol.lower_triangle()(0, 0) == 1 && chol.lower_triangle()(0, 2) == 0, true);
    TEST_NEAR("the determinant is the product of D", chol.determinant(), vnl_det(A), 1e-12);
  }
  {
    const vnl_vector<double> v = random_matrix<double>(3, 1, 1001).get_column(0);
    vnl_matrix<double> Mv(3, 1);
    Mv.set_column(0, v);
    vnl_ldl_cholesky chol(A);
    chol.rank1_update(v);
    TEST_NEAR("Rank 1 update", (A + Mv * Mv.transpose() - recomposed(chol)).fro_norm(), 0.0, 1e-12);
  }
  for (unsigned k : {2u, 4u}) {
    const vnl_matrix<double> W = random_matrix<double>(3, k, 1002 + k);
    vnl_ldl_cholesky chol(A);
    chol.update(W);
    TEST_NEAR("Rank " + std::to_string(k) + " update", (A + W * W.transpose() - recomposed(chol)).fro_norm(), 0.0,
              1e-12);
  }
  {
    const vnl_ldl_cholesky chol(A);
    // Relative: this A (not upstream's random one) has |A^-1| = 436.
    TEST_NEAR("vnl_inverse() ~= cholesky.inverse()",
              (chol.inverse() - vnl_inverse(A)).fro_norm() / vnl_inverse(A).fro_norm(), 0.0, 1e-13);
    TEST_NEAR("Ai * A - I", (chol.inverse() * A - I).fro_norm(), 0.0, 1e-12);
    TEST_NEAR("A * Ai - I", (A * chol.inverse() - I).fro_norm(), 0.0, 1e-12);
  }
  {
    const vnl_ldl_cholesky chol(A, vnl_ldl_cholesky::estimate_condition);
    TEST_NEAR("Ai * A - I (estimate_condition)", (chol.inverse() * A - I).fro_norm(), 0.0, 1e-12);
    TEST_NEAR("rcond is 1 / (|A|_1 |A^-1|_1)", chol.rcond(),
              1 / (A.operator_one_norm() * vnl_inverse(A).operator_one_norm()), 1e-12);
  }
  {
    const vnl_vector<double> x0 = random_matrix<double>(3, 1, 1010).get_column(0);
    const vnl_ldl_cholesky chol(A);
    TEST_NEAR("Solve Ax=b", (chol.solve(A * x0) - x0).one_norm(), 0, 1e-6);
    vnl_ldl_cholesky chol2(A);
    vnl_vector<double> x = chol2.lower_triangle() * x0;
    chol2.solve_lx(x);
    TEST_NEAR("Solve Lx=b", (x - x0).one_norm(), 0, 1e-6);
    TEST_NEAR("x' * inv(M) * x", chol.xt_m_inv_x(x0), dot_product(x0, chol.inverse() * x0), 1e-12);
    TEST_NEAR("x' * M * x", chol.xt_m_x(x0), dot_product(x0, A * x0), 1e-12);
  }
  vnl_matrix<double> indefinite(2, 2, 0.0);
  indefinite(0, 0) = 1;
  indefinite(1, 1) = -1;
  const vnl_ldl_cholesky bad(indefinite, vnl_ldl_cholesky::quiet);
  TEST("a non-definite matrix reports the first bad pivot", bad.rank_deficiency(), 2);
}

TESTMAIN(test_ldl_cholesky)
