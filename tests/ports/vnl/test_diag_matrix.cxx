// SPDX-License-Identifier: BSD-3-Clause
// vnl_diag_matrix as upstream's test_diag_matrix.cxx: sums, differences and products with
// diagonal, full matrices and vectors, and its own determinant, inverse and solve.
#include <string>

#include "testlib/testlib_test.h"
#include "vnl/vnl_diag_matrix.h"
#include "vnl_test_types.h"

namespace {

template <class T>
struct CheckDiag {
  static void run(const std::string& type) {
    const std::string in = " (" + type + ")";
    vnl_diag_matrix<T> d1(3), d2(3);
    for (unsigned i = 0; i < 3; ++i) d1[i] = T(int(i) + 1), d2[i] = T(2 * int(i) - 1);  // (1,2,3), (-1,1,3)
    TEST("sum" + in, (d1 + d2)[2] == T(6), true);
    TEST("difference" + in, (d1 - d2)[0] == T(2), true);
    TEST("product" + in, (d1 * d2)[1] == T(2), true);
    vnl_vector<T> v(3, T(2));
    TEST("vector product D v" + in, (d1 * v)[2] == T(6), true);
    TEST("vector product v D" + in, (v * d1)[1] == T(4), true);
    vnl_matrix<T> m(3, 3, T(1));
    TEST("matrix sum M + D" + in, (m + d1)(1, 1) == T(3) && (m + d1)(0, 1) == T(1), true);
    TEST("matrix sum D + M" + in, (d1 + m)(2, 2) == T(4), true);
    TEST("matrix difference M - D" + in, (m - d1)(2, 2) == T(-2), true);
    TEST("matrix difference D - M" + in, (d1 - m)(0, 1) == T(-1) && (d1 - m)(2, 2) == T(2), true);
    TEST("matrix product M D scales columns" + in, (m * d1)(0, 2) == T(3), true);
    TEST("matrix product D M scales rows" + in, (d1 * m)(2, 0) == T(3), true);
    const vnl_diag_matrix<T>& c1 = d1;  // reading (i, j) off the diagonal is const-only, as upstream
    TEST("off-diagonal elements are zero" + in, c1(0, 2) == T(0) && c1(1, 1) == T(2), true);
    TEST("as_matrix" + in, d1.as_matrix()(2, 2) == T(3) && d1.as_matrix()(2, 1) == T(0), true);
    TEST("determinant is the product" + in, d1.determinant() == T(6), true);
    const vnl_vector<T> x = d1.solve(vnl_vector<T>(3, T(6)));
    TEST("solve divides by the diagonal" + in, x[0] == T(6) && x[1] == T(3) && x[2] == T(2), true);
    vnl_diag_matrix<T> inverse(d1);
    inverse.invert_in_place();
    TEST_NEAR("invert_in_place" + in, inverse[2], 1.0 / 3, ulps<T>(2));
  }
};

void test_diag_matrix() { for_each_test_scalar<CheckDiag>(); }

}  // namespace

TESTMAIN(test_diag_matrix)
