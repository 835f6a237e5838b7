// SPDX-License-Identifier: BSD-3-Clause
// Every vnl template definition file (.hxx) compiles together with the others (upstream's
// test_template_include.cxx), so a user can instantiate vnl for a scalar of their own.
#include "vnl/vnl_least_squares_function.hxx"
#include "vnl/vnl_matrix.hxx"
#include "vnl/vnl_polynomial.hxx"
#include "vnl/vnl_quaternion.hxx"
#include "vnl/vnl_rotation_matrix.hxx"
#include "vnl/vnl_sparse_lst_sqr_function.hxx"
#include "vnl/vnl_sparse_matrix.hxx"
#include "vnl/vnl_vector.hxx"
#include "testlib/testlib_test.h"

// A scalar the library does not instantiate: long double.
template class vnl_vector<long double>;
template class vnl_matrix<long double>;

static void test_template_include() {
  vnl_matrix<long double> m(2, 2, vnl_matrix_identity);
  TEST("vnl_matrix<long double> instantiated from the .hxx files", (m * m).is_identity(), true);
}

TESTMAIN(test_template_include)
