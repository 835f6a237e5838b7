// SPDX-License-Identifier: BSD-3-Clause
// vnl_qr as upstream's algo test_qr.cxx: Q R recomposes M, Q is orthogonal, R is upper
// triangular, solve, determinant and inverse of a known matrix.
#include <string>

#include "algo_test_support.h"
#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_qr.h"

namespace {

template <class T>
struct CheckQr {
  static void run(const std::string& type) {
    const std::string in = " (" + type + ")";
    const double tol = decomposition_tol<T>();
    const T d[] = {T(89), T(21), T(12), T(-3), T(17), T(5), T(-4), T(6), T(15)};  // upstream's test matrix shape
    const vnl_matrix<T> a(d, 3, 3);
    const double det = 89.0 * (17 * 15 - 5 * 6) - 21.0 * (-3 * 15 + 4 * 5) + 12.0 * (-3 * 6 + 17 * 4);
    // Scaled by 1/100 so that fixed point keeps its range.
    const vnl_matrix<T> s = a / T(100);
    const vnl_qr<T> qr(s);
    TEST_NEAR("Q R recomposes M" + in, distance(qr.recompose(), s), 0.0, tol * 4);
    TEST_NEAR("Q is orthogonal" + in, orthonormality_error(qr.Q()), 0.0, tol * 4);
    bool upper = true;
    for (unsigned i = 1; i < 3; ++i) {
      for (unsigned j = 0; j < i; ++j) upper = upper && qr.R()(i, j) == T(0);
    }
    TEST("R is upper triangular" + in, upper, true);
    TEST_NEAR("determinant" + in, qr.determinant(), det / 1e6, tol * 64);
    vnl_vector<T> b(3);
    b[0] = T(1), b[1] = T(-1), b[2] = T(0.5);
    const vnl_vector<T> x = qr.solve(b);
    TEST_NEAR("solve: M x = b" + in, static_cast<double>((s * x - b).inf_norm()), 0.0, tol * 64);
    TEST_NEAR("inverse: M * inv(M) = I" + in, distance(s * qr.inverse(), vnl_matrix<T>(3, 3, vnl_matrix_identity)), 0.0,
              tol * 64);
    TEST_NEAR("QtB is Q^T b" + in, static_cast<double>((qr.QtB(b) - qr.Q().transpose() * b).inf_norm()), 0.0, 0.0);
    // A tall matrix: the least-squares solution satisfies the normal equations.
    const vnl_matrix<T> tall = random_matrix<T>(6, 3, 11);
    const vnl_qr<T> tq(tall);
    TEST_NEAR("tall Q R recomposes M" + in, distance(tq.recompose(), tall), 0.0, tol * 4);
    vnl_vector<T> y(6);
    for (unsigned i = 0; i < 6; ++i) y[i] = T(0.25) * T(int(i));
    const vnl_vector<T> ls = tq.solve(y);
    TEST_NEAR("tall solve is least squares" + in, static_cast<double>((tall.transpose() * (tall * ls - y)).inf_norm()),
              0.0, tol * 16);
  }
};

void test_qr() { for_each_test_scalar<CheckQr>(); }

}  // namespace

TESTMAIN(test_qr)
