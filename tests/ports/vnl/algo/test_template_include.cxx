// SPDX-License-Identifier: BSD-3-Clause
// Every vnl_algo template definition file (.hxx) compiles together with the others (upstream's
// algo test_template_include.cxx, which only compiles them), so a user can instantiate the
// decompositions for a scalar of their own: here long double, which the library does not have.
#include <limits>

#include "vnl/algo/vnl_cholesky.hxx"
#include "vnl/algo/vnl_levenberg_marquardt.hxx"
#include "vnl/algo/vnl_qr.hxx"
#include "vnl/algo/vnl_scatter_3x3.hxx"
#include "vnl/algo/vnl_svd.hxx"
#include "vnl/algo/vnl_symmetric_eigensystem.hxx"
#include "testlib/testlib_test.h"

template class vnl_qr<long double>;
template class vnl_svd<long double>;

static void test_template_include() {
  vnl_matrix<long double> m(2, 2, 0.0L);
  m(0, 0) = 3;
  m(1, 1) = 2;
  m(0, 1) = 1;
  const vnl_svd<long double> svd(m);
  // 64 ulps of long double (an 80-bit type on x86, double on ARM) times |m|.
  const double tol = 64 * static_cast<double>(std::numeric_limits<long double>::epsilon()) * 4;
  TEST_NEAR("vnl_svd<long double> instantiated from the .hxx files recomposes",
            static_cast<double>((svd.recompose() - m).fro_norm()), 0.0, tol);
  TEST_NEAR("vnl_qr<long double> gives the determinant", static_cast<double>(vnl_qr<long double>(m).determinant()), 6.0,
            6 * tol);
}

TESTMAIN(test_template_include)
