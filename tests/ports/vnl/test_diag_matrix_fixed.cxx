// SPDX-License-Identifier: BSD-3-Clause
// vnl_diag_matrix_fixed as upstream's test_diag_matrix_fixed.cxx: sums, products with
// vectors and fixed matrices, determinant, solve and inverse.
#include <string>

#include "testlib/testlib_test.h"
#include "vnl/vnl_diag_matrix_fixed.h"
#include "vnl_test_types.h"

namespace {

template <class T>
struct CheckDiagFixed {
  static void run(const std::string& type) {
    const std::string in = " (" + type + ")";
    const vnl_diag_matrix_fixed<T, 3> d(vnl_vector_fixed<T, 3>(T(1), T(2), T(4)));
    const vnl_diag_matrix_fixed<T, 3> e(T(2));
    TEST("sum" + in, (d + e)[2] == T(6), true);
    TEST("difference" + in, (d - e)[0] == T(-1), true);
    TEST("product" + in, (d * e)[1] == T(4), true);
    TEST("vector product" + in, (d * vnl_vector_fixed<T, 3>(T(1)))[2] == T(4), true);
    const vnl_matrix_fixed<T, 3, 3> ones(T(1));
    TEST("matrix product M D scales columns" + in, (ones * d)(0, 2) == T(4), true);
    TEST("matrix product D M scales rows" + in, (d * ones)(2, 0) == T(4), true);
    TEST("determinant" + in, d.determinant() == T(8), true);
    TEST("solve" + in, d.solve(vnl_vector_fixed<T, 3>(T(4)))[2] == T(1), true);
    vnl_diag_matrix_fixed<T, 3> inv(d);
    inv.invert_in_place();
    TEST("invert_in_place" + in, inv[1] == T(1) / T(2), true);
    TEST("as_matrix" + in, d.as_matrix()(1, 1) == T(2) && d.as_matrix()(1, 0) == T(0), true);
  }
};

void test_diag_matrix_fixed() { for_each_test_scalar<CheckDiagFixed>(); }

}  // namespace

TESTMAIN(test_diag_matrix_fixed)
