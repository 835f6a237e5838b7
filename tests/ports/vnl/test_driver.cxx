// SPDX-License-Identifier: BSD-3-Clause
// The vnl driver (upstream: core/vnl/tests/test_driver.cxx).
#include "testlib/testlib_register.h"

DECLARE(test_vector);
DECLARE(test_matrix);
DECLARE(test_math);
DECLARE(test_rotation_matrix);
DECLARE(test_levenberg_marquardt);
DECLARE(test_quaternion);
DECLARE(test_real_polynomial);
DECLARE(test_sparse_matrix);
DECLARE(test_diag_matrix);
DECLARE(test_inverse);
DECLARE(test_numeric_traits);
DECLARE(test_random);
DECLARE(test_transpose);
DECLARE(test_vector_fixed_ref);
DECLARE(test_matrix_fixed_ref);
DECLARE(test_include);
DECLARE(test_template_include);
DECLARE(test_rational);
DECLARE(test_polynomial);
DECLARE(test_sym_matrix);
DECLARE(test_power);
DECLARE(test_matrix_exp);
DECLARE(test_vnl_index_sort);
DECLARE(test_complexify);
DECLARE(test_diag_matrix_fixed);
DECLARE(test_gamma);
DECLARE(test_bessel);
DECLARE(test_na);
DECLARE(test_file_matrix);
DECLARE(test_crs_index);
DECLARE(test_fastops);
DECLARE(test_block_and_matops);
DECLARE(test_hungarian_algorithm);
DECLARE(test_rank);

void register_tests() {
  REGISTER(test_vector);
  REGISTER(test_matrix);
  REGISTER(test_math);
  REGISTER(test_rotation_matrix);
  REGISTER(test_levenberg_marquardt);
  REGISTER(test_quaternion);
  REGISTER(test_real_polynomial);
  REGISTER(test_sparse_matrix);
  REGISTER(test_diag_matrix);
  REGISTER(test_inverse);
  REGISTER(test_numeric_traits);
  REGISTER(test_random);
  REGISTER(test_transpose);
  REGISTER(test_vector_fixed_ref);
  REGISTER(test_matrix_fixed_ref);
  REGISTER(test_include);
  REGISTER(test_template_include);
  REGISTER(test_rational);
  REGISTER(test_polynomial);
  REGISTER(test_sym_matrix);
  REGISTER(test_power);
  REGISTER(test_matrix_exp);
  REGISTER(test_vnl_index_sort);
  REGISTER(test_complexify);
  REGISTER(test_diag_matrix_fixed);
  REGISTER(test_gamma);
  REGISTER(test_bessel);
  REGISTER(test_na);
  REGISTER(test_file_matrix);
  REGISTER(test_crs_index);
  REGISTER(test_fastops);
  REGISTER(test_block_and_matops);
  REGISTER(test_hungarian_algorithm);
  REGISTER(test_rank);
}

DEFINE_MAIN
