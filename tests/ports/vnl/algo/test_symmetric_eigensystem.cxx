// SPDX-License-Identifier: BSD-3-Clause
// vnl_symmetric_eigensystem as upstream's algo test_symmetric_eigensystem.cxx: V D V^T
// recomposes M, V is orthonormal, eigenvalues ascend and match a known matrix's, M v = l v,
// and the 3x3 eigenvalue function. Our algorithm is cyclic Jacobi (upstream: EISPACK rs).
#include <string>

#include "algo_test_support.h"
#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_symmetric_eigensystem.h"

namespace {

template <class T>
struct CheckEigen {
  static void run(const std::string& type) {
    const std::string in = " (" + type + ")";
    const double tol = decomposition_tol<T>();
    // [[2,1,0],[1,2,1],[0,1,2]]: eigenvalues 2 - sqrt 2, 2, 2 + sqrt 2.
    const T d[] = {T(2), T(1), T(0), T(1), T(2), T(1), T(0), T(1), T(2)};
    const vnl_matrix<T> m(d, 3, 3);
    const vnl_symmetric_eigensystem<T> eig(m);
    TEST_NEAR("smallest eigenvalue is 2 - sqrt 2" + in, eig.get_eigenvalue(0), 2 - std::sqrt(2.0), tol * 8);
    TEST_NEAR("middle eigenvalue is 2" + in, eig.get_eigenvalue(1), 2.0, tol * 8);
    TEST_NEAR("largest eigenvalue is 2 + sqrt 2" + in, eig.get_eigenvalue(2), 2 + std::sqrt(2.0), tol * 8);
    TEST_NEAR("V D V^T recomposes M" + in, distance(eig.recompose(), m), 0.0, tol * 8);
    TEST_NEAR("V is orthonormal" + in, orthonormality_error(eig.V), 0.0, tol * 8);
    const vnl_vector<T> v = eig.get_eigenvector(2);
    TEST_NEAR("M v = l v" + in, static_cast<double>((m * v - v * eig.get_eigenvalue(2)).inf_norm()), 0.0, tol * 8);
    TEST_NEAR("determinant is the eigenvalue product, 4" + in, eig.determinant(), 4.0, tol * 32);
    TEST_NEAR("square_root squared is M" + in, distance(eig.square_root() * eig.square_root(), m), 0.0, tol * 32);
    TEST_NEAR("inverse * M is I" + in, distance(eig.inverse() * m, vnl_matrix<T>(3, 3, vnl_matrix_identity)), 0.0,
              tol * 32);
    vnl_vector<T> b(3, T(1));
    TEST_NEAR("solve: M x = b" + in, static_cast<double>((m * vnl_symmetric_eigensystem<T>(m).solve(b) - b).inf_norm()),
              0.0, tol * 32);

    const vnl_matrix<T> r = random_matrix<T>(5, 5, 31);
    const vnl_matrix<T> sym = (r + r.transpose()) / T(2);
    const vnl_symmetric_eigensystem<T> e5(sym);
    bool ascending = true;
    for (int i = 0; i + 1 < 5; ++i) ascending = ascending && e5.get_eigenvalue(i) <= e5.get_eigenvalue(i + 1);
    TEST("eigenvalues of a random 5x5 ascend" + in, ascending, true);
    TEST_NEAR("random 5x5 recomposes" + in, distance(e5.recompose(), sym), 0.0, tol * 16);
    T l1, l2, l3;
    vnl_symmetric_eigensystem_compute_eigenvals(T(2), T(1), T(0), T(2), T(1), T(2), l1, l2, l3);
    TEST_NEAR("3x3 eigenvalue function: l1" + in, l1, 2 - std::sqrt(2.0), tol * 8);
    TEST_NEAR("3x3 eigenvalue function: l3" + in, l3, 2 + std::sqrt(2.0), tol * 8);
  }
};

void test_symmetric_eigensystem() { for_each_test_scalar<CheckEigen>(); }

}  // namespace

TESTMAIN(test_symmetric_eigensystem)
