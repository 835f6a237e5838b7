// SPDX-License-Identifier: BSD-3-Clause
// vnl_brent as upstream's algo test_minimizers.cxx: the minimum of a parabola from given bounds
// and from a start point; plus its bracketing.
#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_brent.h"

namespace {
struct cubic : public vnl_cost_function {
  cubic() : vnl_cost_function(1) {}
  double f(const vnl_vector<double>& x) override { return (2 - x[0]) * (2 - x[0]) + 10; }
};
}  // namespace

static void test_minimizers() {
  cubic c;
  vnl_brent b(&c);
  double x = 77;
  const double f_min = b.minimize_given_bounds(-100, x, 100, 1e-6, &x);
  TEST_NEAR("brent1", x, 2, 1e-5);
  TEST_NEAR("minimize_given_bounds returns f at the minimum", f_min, 10, 1e-9);
  x = 77;
  x = b.minimize(x);
  TEST_NEAR("brent2", x, 2, 1e-5);
  double ax = 10, bx = 11, cx = 0, fa = 0, fb = 0, fc = 0;
  b.bracket_minimum(&ax, &bx, &cx, &fa, &fb, &fc);
  TEST("bracket_minimum brackets the minimum", (ax - 2) * (cx - 2) < 0 && fb < fa && fb < fc, true);
  TEST("with f(bx) between the ends", (ax - bx) * (bx - cx) > 0, true);
  const double f77 = c.f(vnl_vector<double>(1, 77.0));
  x = 0;
  b.minimize_given_bounds_and_1st_f(-100, 77, f77, 100, 1e-6, &x);
  TEST_NEAR("minimize_given_bounds_and_1st_f", x, 2, 1e-5);
}

TESTMAIN(test_minimizers)
