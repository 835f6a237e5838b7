// SPDX-License-Identifier: BSD-3-Clause
// vnl_svd_fixed and vnl_svd_economy as upstream's test_svd_fixed.cxx checks them: they agree
// with vnl_svd, recompose the matrix and solve; plus vnl_orthogonal_complement and
// vnl_adjugate, which are built on them.
#include <string>

#include "algo_test_support.h"
#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_adjugate.h"
#include "vnl/algo/vnl_orthogonal_complement.h"
#include "vnl/algo/vnl_svd_economy.h"
#include "vnl/algo/vnl_svd_fixed.h"
#include "vnl/vnl_math.h"

namespace {

template <class T>
struct CheckSvdFixed {
  static void run(const std::string& type) {
    const std::string in = " (" + type + ")";
    const double tol = decomposition_tol<T>();
    const vnl_matrix<T> a = random_matrix<T>(4, 3, 99);
    const vnl_matrix_fixed<T, 4, 3> f(a);
    const vnl_svd_fixed<T, 4, 3> sf(f);
    const vnl_svd<T> s(a);
    TEST_NEAR("singular values agree with vnl_svd" + in, vnl_math::abs(sf.W(2) - s.W(2)), 0.0, 0.0);
    TEST_NEAR("U W V^T recomposes M" + in, distance(sf.recompose().as_matrix(), a), 0.0, tol * 4);
    TEST("rank 3" + in, sf.rank(), 3u);
    const vnl_vector_fixed<T, 4> y(T(1), T(0), T(-1), T(0.5));
    const vnl_vector_fixed<T, 3> x = sf.solve(y);
    TEST_NEAR("solve is the least-squares solution" + in,
              static_cast<double>((a.transpose() * (a * x.as_vector() - y.as_vector())).inf_norm()), 0.0, tol * 16);
    const vnl_svd_economy<T> economy(a);
    TEST_NEAR("vnl_svd_economy's lambdas agree" + in, vnl_math::abs(economy.lambdas()[0] - s.W(0)), 0.0, 0.0);
    const vnl_vector<T> v{T(1), T(2), T(2)};
    const vnl_matrix<T> complement = vnl_orthogonal_complement(v);
    TEST("orthogonal complement is 3 x 2" + in, complement.rows() == 3 && complement.cols() == 2, true);
    TEST_NEAR("its columns are orthogonal to v" + in, static_cast<double>((v * complement).inf_norm()), 0.0, tol * 8);
    TEST_NEAR("and orthonormal" + in, orthonormality_error(complement), 0.0, tol * 8);
    const vnl_matrix<T> sq{{T(2), T(0), T(1)}, {T(1), T(3), T(2)}, {T(1), T(1), T(2)}};
    const vnl_matrix<T> adj = vnl_adjugate(sq);
    vnl_matrix<T> det_i(3, 3, vnl_matrix_identity);
    det_i *= T(6);  // det(sq) = 6
    TEST_NEAR("adj(A) A = det(A) I" + in, distance(adj * sq, det_i), 0.0, tol * 16);
  }
};

void test_svd_fixed() { for_each_test_scalar<CheckSvdFixed>(); }

}  // namespace

TESTMAIN(test_svd_fixed)
