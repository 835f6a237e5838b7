// SPDX-License-Identifier: BSD-3-Clause
// The vnl_algo driver (upstream: core/vnl/algo/tests/test_driver.cxx).
#include "testlib/testlib_register.h"

DECLARE(test_include);
DECLARE(test_svd);
DECLARE(test_qr);
DECLARE(test_cholesky);
DECLARE(test_symmetric_eigensystem);
DECLARE(test_determinant);
DECLARE(test_svd_fixed);
DECLARE(test_matrix_update);
DECLARE(test_integral);
DECLARE(test_brent_minimizer);
DECLARE(test_bracket_minimum);
DECLARE(test_amoeba);
DECLARE(test_powell);
DECLARE(test_minimizers);
DECLARE(test_algo);
DECLARE(test_fft1d);
DECLARE(test_fft2d);
DECLARE(test_fft);
DECLARE(test_convolve);
DECLARE(test_ldl_cholesky);
DECLARE(test_scatter_3x3);
DECLARE(test_generalized_eigensystem);
DECLARE(test_cpoly_roots);
DECLARE(test_real_eigensystem);
DECLARE(test_rnpoly_roots);
DECLARE(test_gaussian_kernel_1d);
DECLARE(test_complex_eigensystem);
DECLARE(test_sparse_lu);
DECLARE(test_sparse_matrix);
DECLARE(test_solve_qp);
DECLARE(test_template_include);

void register_tests() {
  REGISTER(test_include);
  REGISTER(test_svd);
  REGISTER(test_qr);
  REGISTER(test_cholesky);
  REGISTER(test_symmetric_eigensystem);
  REGISTER(test_determinant);
  REGISTER(test_svd_fixed);
  REGISTER(test_matrix_update);
  REGISTER(test_integral);
  REGISTER(test_brent_minimizer);
  REGISTER(test_bracket_minimum);
  REGISTER(test_amoeba);
  REGISTER(test_powell);
  REGISTER(test_minimizers);
  REGISTER(test_algo);
  REGISTER(test_fft1d);
  REGISTER(test_fft2d);
  REGISTER(test_fft);
  REGISTER(test_convolve);
  REGISTER(test_ldl_cholesky);
  REGISTER(test_scatter_3x3);
  REGISTER(test_generalized_eigensystem);
  REGISTER(test_cpoly_roots);
  REGISTER(test_real_eigensystem);
  REGISTER(test_rnpoly_roots);
  REGISTER(test_gaussian_kernel_1d);
  REGISTER(test_complex_eigensystem);
  REGISTER(test_sparse_lu);
  REGISTER(test_sparse_matrix);
  REGISTER(test_solve_qp);
  REGISTER(test_template_include);
}

DEFINE_MAIN
