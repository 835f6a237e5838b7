// SPDX-License-Identifier: BSD-3-Clause
// vnl_determinant as upstream's algo test_determinant.cxx: row-pointer forms, small and large
// matrices (closed form and QR), balancing, integer matrices and fixed-size matrices.
#include <string>

#include "algo_test_support.h"
#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_determinant.h"
#include "vnl/vnl_matrix_fixed.h"

namespace {

template <class T>
struct CheckDeterminant {
  static void run(const std::string& type) {
    const std::string in = " (" + type + ")";
    const double tol = decomposition_tol<T>();
    const T r0[] = {T(1), T(2), T(0)}, r1[] = {T(3), T(-1), T(2)}, r2[] = {T(0), T(1), T(1)};
    TEST_NEAR("2x2 from rows" + in, vnl_determinant(r0, r1), -7.0, 0.0);
    TEST_NEAR("3x3 from rows" + in, vnl_determinant(r0, r1, r2), -9.0, 0.0);
    // A 6x6 tridiagonal [-1 2 -1] matrix has determinant n + 1 = 7 (QR path).
    vnl_matrix<T> t(6, 6);
    for (unsigned i = 0; i < 6; ++i) {
      t(i, i) = T(2);
      if (i + 1 < 6) t(i, i + 1) = t(i + 1, i) = T(-1);
    }
    TEST_NEAR("6x6 tridiagonal by QR" + in, vnl_determinant(t), 7.0, tol * 64);
    TEST_NEAR("6x6 tridiagonal balanced" + in, vnl_determinant(t, true), 7.0, tol * 256);
    vnl_matrix_fixed<T, 3, 3> f;
    f.set_row(0, vnl_vector_fixed<T, 3>(r0));
    f.set_row(1, vnl_vector_fixed<T, 3>(r1));
    f.set_row(2, vnl_vector_fixed<T, 3>(r2));
    TEST_NEAR("vnl_matrix_fixed" + in, vnl_determinant(f), -9.0, 0.0);
    vnl_matrix<T> swapped = t;
    swapped.set_row(0, t.get_row(1));
    swapped.set_row(1, t.get_row(0));
    TEST_NEAR("swapping two rows negates" + in, vnl_determinant(swapped), -7.0, tol * 64);
  }
};

void test_determinant() {
  for_each_test_scalar<CheckDeterminant>();
  vnl_matrix<int> m(5, 5, 0);
  for (unsigned i = 0; i < 5; ++i) m(i, i) = int(i) + 1;
  m(0, 4) = 7;
  TEST("integer 5x5 triangular: 5! = 120", vnl_determinant(m), 120);
}

}  // namespace

TESTMAIN(test_determinant)
