// SPDX-License-Identifier: BSD-3-Clause
/// The real library's testlib driver: one registered test per property of fixed64.
#include "testlib/testlib_register.h"

DECLARE(test_fixed64_construction);
DECLARE(test_fixed64_comparisons);
DECLARE(test_fixed64_rounding_functions);
DECLARE(test_fixed64_numeric_limits);
DECLARE(test_fixed64_saturation_counting);
DECLARE(test_real_picks_configured_type);
DECLARE(test_fixed64_generic_code);
DECLARE(test_fixed64_add_subtract);
DECLARE(test_fixed64_multiply);
DECLARE(test_fixed64_divide);
DECLARE(test_fixed64_sqrt);
DECLARE(test_fixed64_norm_and_dot_product);
DECLARE(test_fixed64_multiply_fast_path);
DECLARE(test_fixed64_divide_fast_path);
DECLARE(test_wide_uint_reciprocal_and_division);
DECLARE(test_wide_uint_square_root);
DECLARE(test_fixed64_sin_cos);
DECLARE(test_fixed64_tan);
DECLARE(test_fixed64_atan_atan2);
DECLARE(test_fixed64_asin_acos);
DECLARE(test_fixed64_exp_log);

void register_tests() {
  REGISTER(test_fixed64_construction);
  REGISTER(test_fixed64_comparisons);
  REGISTER(test_fixed64_rounding_functions);
  REGISTER(test_fixed64_numeric_limits);
  REGISTER(test_fixed64_saturation_counting);
  REGISTER(test_real_picks_configured_type);
  REGISTER(test_fixed64_generic_code);
  REGISTER(test_fixed64_add_subtract);
  REGISTER(test_fixed64_multiply);
  REGISTER(test_fixed64_divide);
  REGISTER(test_fixed64_sqrt);
  REGISTER(test_fixed64_norm_and_dot_product);
  REGISTER(test_fixed64_multiply_fast_path);
  REGISTER(test_fixed64_divide_fast_path);
  REGISTER(test_wide_uint_reciprocal_and_division);
  REGISTER(test_wide_uint_square_root);
  REGISTER(test_fixed64_sin_cos);
  REGISTER(test_fixed64_tan);
  REGISTER(test_fixed64_atan_atan2);
  REGISTER(test_fixed64_asin_acos);
  REGISTER(test_fixed64_exp_log);
}

DEFINE_MAIN
