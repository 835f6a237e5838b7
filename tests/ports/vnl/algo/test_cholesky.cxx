// SPDX-License-Identifier: BSD-3-Clause
// vnl_cholesky as upstream's algo test_cholesky.cxx: L L^T recomposes M, solve and inverse
// agree with the SVD's, the determinant, and a matrix that is not positive definite is reported.
#include <string>

#include "algo_test_support.h"
#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_cholesky.h"
#include "vnl/algo/vnl_svd.h"

namespace {

template <class T>
struct CheckCholesky {
  static void run(const std::string& type) {
    const std::string in = " (" + type + ")";
    const double tol = decomposition_tol<T>();
    const vnl_matrix<T> b = random_matrix<T>(4, 4, 23);
    vnl_matrix<T> spd = b * b.transpose();
    for (unsigned i = 0; i < 4; ++i) spd(i, i) += T(1);  // symmetric positive definite
    const vnl_cholesky_of<T> chol(spd, vnl_cholesky_of<T>::estimate_condition);
    TEST("rank_deficiency of an SPD matrix is 0" + in, chol.rank_deficiency(), 0);
    TEST_NEAR("L L^T recomposes M" + in, distance(chol.lower_triangle() * chol.upper_triangle(), spd), 0.0, tol * 8);
    TEST("L is lower triangular" + in, chol.lower_triangle()(0, 3) == T(0), true);
    vnl_vector<T> rhs(4);
    for (unsigned i = 0; i < 4; ++i) rhs[i] = T(int(i) - 1);
    const vnl_svd<T> svd(spd);
    TEST_NEAR("solve agrees with the SVD's" + in, static_cast<double>((chol.solve(rhs) - svd.solve(rhs)).inf_norm()),
              0.0, tol * 64);
    TEST_NEAR("inverse: M * inv(M) = I" + in,
              distance(spd * chol.inverse(), vnl_matrix<T>(4, 4, vnl_matrix_identity)), 0.0, tol * 64);
    TEST_NEAR("determinant is the product of the singular values" + in, chol.determinant(),
              static_cast<double>(svd.determinant_magnitude()), tol * 256);
    const double rcond = static_cast<double>(svd.sigma_min() / svd.sigma_max());
    TEST("rcond is positive and at most 1" + in, chol.rcond() > T(0) && chol.rcond() <= T(1), true);
    TEST("rcond is within a factor n of sigma_min / sigma_max" + in,
         static_cast<double>(chol.rcond()) > rcond / 16 && static_cast<double>(chol.rcond()) < rcond * 16, true);
    vnl_matrix<T> indefinite(spd);
    indefinite(2, 2) = T(-5);
    const vnl_cholesky_of<T> bad(indefinite, vnl_cholesky_of<T>::quiet);
    TEST("a matrix with a negative leading minor of order 3 is reported" + in, bad.rank_deficiency(), 3);
  }
};

void test_cholesky() {
  for_each_test_scalar<CheckCholesky>();
  // Upstream's spelling: the double class with its enum.
  vnl_matrix<double> m(2, 2);
  m(0, 0) = 4, m(0, 1) = m(1, 0) = 2, m(1, 1) = 3;
  const vnl_cholesky c(m, vnl_cholesky::quiet);
  TEST_NEAR("vnl_cholesky (double) L(1,0) of [[4,2],[2,3]] is 1", c.lower_triangle()(1, 0), 1.0, 1e-15);
  TEST_NEAR("vnl_cholesky (double) L(1,1) is sqrt 2", c.lower_triangle()(1, 1), std::sqrt(2.0), 1e-15);
}

}  // namespace

TESTMAIN(test_cholesky)
