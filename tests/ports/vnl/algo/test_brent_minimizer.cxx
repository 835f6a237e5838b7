// SPDX-License-Identifier: BSD-3-Clause
// vnl_brent_minimizer as upstream's algo test_brent_minimizer.cxx: the minimum of a parabola
// and of a quartic, from starting points near and far, and from a given bracket.
#include <cmath>

#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_brent_minimizer.h"

namespace {
struct parabola : public vnl_cost_function {
  parabola() : vnl_cost_function(1) {}
  double f(const vnl_vector<double>& x) override { return (2 - x[0]) * (2 - x[0]) + 10; }
};
struct quartic : public vnl_cost_function {
  quartic() : vnl_cost_function(1) {}
  double f(const vnl_vector<double>& x) override {
    const double y = (2 - x[0]) * (2 - x[0]);
    return y * y + 10;
  }
};
}  // namespace

static void test_brent_minimizer() {
  parabola f1;
  vnl_brent_minimizer brent1(f1);
  TEST_NEAR("f1 minimize(77)", brent1.minimize(77), 2, 1e-6);
  TEST_NEAR("f1 minimize(13)", brent1.minimize(13), 2, 1e-6);
  TEST_NEAR("f1 at the minimum", brent1.f_at_last_minimum(), 10, 1e-10);
  TEST_NEAR("f1 minimize_given_bounds(-1, 0.5, 7)", brent1.minimize_given_bounds(-1, 0.5, 7), 2, 1e-6);
  quartic f2;
  vnl_brent_minimizer brent2(f2);
  TEST_NEAR("f2 minimize(-5): a flat quartic minimum", brent2.minimize(-5), 2, 1e-3);
  TEST("and it converged on x", brent2.get_failure_code(), vnl_brent_minimizer::CONVERGED_XTOL);
}

TESTMAIN(test_brent_minimizer)
