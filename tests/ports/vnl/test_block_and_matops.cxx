// SPDX-License-Identifier: BSD-3-Clause
// vnl_block's array operations and vnl_matops's concatenations and conversions (upstream has
// no test of its own for these two headers).
#include "testlib/testlib_test.h"
#include "vnl/vnl_block.h"
#include "vnl/vnl_matops.h"

static void test_block_and_matops() {
  double x[4] = {3, -1, 4, 2}, y[4] = {1, 1, 1, 1}, z[4];
  TEST("vnl_block_sum", vnl_block_sum(x, 4), 8.0);
  TEST("vnl_block_product", vnl_block_product(x, 4), -24.0);
  TEST("vnl_block_arg_min and min_value", vnl_block_arg_min(x, 4) == 1u && vnl_block_min_value(x, 4) == -1.0, true);
  TEST("vnl_block_arg_max and max_value", vnl_block_arg_max(x, 4) == 2u && vnl_block_max_value(x, 4) == 4.0, true);
  vnl_block_axpy(2.0, x, y, 4);
  TEST("vnl_block_axpy: y += 2 x", y[2], 9.0);
  vnl_block_sub(y, x, z, 4);
  TEST("vnl_block_sub", z[0], 4.0);
  vnl_block_div(x, x, z, 4);
  TEST("vnl_block_div of x by itself is 1", vnl_block_sum(z, 4), 4.0);
  vnl_block_reverse(x, 4);
  TEST("vnl_block_reverse", x[0] == 2 && x[3] == 3, true);
  vnl_block_invert(x, z, 4);
  TEST("vnl_block_invert", z[0], 0.5);

  const vnl_matrix<double> a{{1, 2}, {3, 4}};
  const vnl_vector<double> v{5, 6};
  TEST("vnl_matops::cat appends columns", vnl_matops::cat(a, v)(1, 2), 6.0);
  TEST("vnl_matops::cat prepends a column", vnl_matops::cat(v, a)(0, 1), 1.0);
  TEST("vnl_matops::vcat stacks rows", vnl_matops::vcat(a, a)(3, 0), 3.0);
  TEST_NEAR("homg_diff ignores scale and sign", vnl_matops::homg_diff(a, a * -3.0), 0.0, 1e-15);
  TEST("d2f then f2d", vnl_matops::f2d(vnl_matops::d2f(a)) == a, true);
}

TESTMAIN(test_block_and_matops)
