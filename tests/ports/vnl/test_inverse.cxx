// SPDX-License-Identifier: BSD-3-Clause
// vnl_inverse and vnl_inverse_transpose of 2x2, 3x3 and 4x4 matrices as upstream's
// test_inverse.cxx: the identity, known inverses and random matrices (M * inv(M) = I), and
// vnl_det alongside.
#include <string>

#include "testlib/testlib_test.h"
#include "vnl/vnl_det.h"
#include "vnl/vnl_inverse.h"
#include "vnl/vnl_random.h"
#include "vnl_test_types.h"

namespace {

template <class T, unsigned n>
double identity_error(const vnl_matrix_fixed<T, n, n>& m) {
  vnl_matrix_fixed<T, n, n> id;
  id.set_identity();
  return static_cast<double>((m - id).frobenius_norm());
}

template <class T>
struct CheckInverse {
  static void run(const std::string& type) {
    const std::string in = " (" + type + ")";
    const double tol = ulps<T>(512) + 1e-13;
    vnl_matrix_fixed<T, 2, 2> id2;
    id2.set_identity();
    TEST("vnl_inverse of 2x2 Id" + in, vnl_inverse(id2) == id2, true);
    TEST("vnl_inverse_transpose of 2x2 Id" + in, vnl_inverse_transpose(id2) == id2, true);
    const T d2[] = {T(4), T(7), T(2), T(6)};  // det 10, inverse [0.6 -0.7; -0.2 0.4]
    const vnl_matrix_fixed<T, 2, 2> m2(d2);
    TEST_NEAR("2x2 vnl_det" + in, vnl_det(m2), 10.0, 0.0);
    TEST_NEAR("2x2 vnl_inverse (0,1)" + in, vnl_inverse(m2)(0, 1), -0.7, tol);
    TEST_NEAR("2x2 vnl_inverse_transpose (0,1)" + in, vnl_inverse_transpose(m2)(0, 1), -0.2, tol);
    const T d3[] = {T(2), T(0), T(1), T(1), T(3), T(2), T(1), T(1), T(2)};  // det 6
    const vnl_matrix_fixed<T, 3, 3> m3(d3);
    TEST_NEAR("3x3 vnl_det" + in, vnl_det(m3), 6.0, 0.0);
    TEST_NEAR("3x3 vnl_inverse (0,0) is 4/6" + in, vnl_inverse(m3)(0, 0), 2.0 / 3, tol);
    TEST_NEAR("3x3 vnl_inverse (2,1) is -2/6" + in, vnl_inverse(m3)(2, 1), -1.0 / 3, tol);
    TEST_NEAR("3x3 M * inv(M) = I" + in, (identity_error<T, 3>(m3 * vnl_inverse(m3))), 0.0, tol);
    vnl_random rng(9667566);
    vnl_matrix_fixed<T, 4, 4> m4;
    for (unsigned i = 0; i < 4; ++i) {
      for (unsigned j = 0; j < 4; ++j) m4(i, j) = T(rng.drand64(-1, 1)) + (i == j ? T(2) : T(0));
    }
    TEST_NEAR("rand 4x4 M * inv(M) = I" + in, (identity_error<T, 4>(m4 * vnl_inverse(m4))), 0.0, 8 * tol);
    TEST_NEAR("rand 4x4 inv_transpose is inv^T" + in,
              static_cast<double>((vnl_inverse_transpose(m4) - vnl_inverse(m4).transpose()).frobenius_norm()), 0.0,
              0.0);
    const vnl_matrix<T> dyn = m4.as_matrix();
    TEST_NEAR("vnl_inverse of a vnl_matrix" + in,
              static_cast<double>((vnl_inverse(dyn) - vnl_inverse(m4).as_matrix()).frobenius_norm()), 0.0, 0.0);
    TEST_NEAR("vnl_det of a vnl_matrix matches the fixed one" + in, vnl_det(dyn), vnl_det(m4), 0.0);
    vnl_matrix_fixed<T, 3, 3> singular(T(1));
    TEST("a singular matrix inverts to zero, as upstream" + in, vnl_inverse(singular).frobenius_norm() == T(0), true);
  }
};

void test_inverse() { for_each_test_scalar<CheckInverse>(); }

}  // namespace

TESTMAIN(test_inverse)
