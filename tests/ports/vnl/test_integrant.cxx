// SPDX-License-Identifier: BSD-3-Clause
// The integrand classes as upstream's test_integrant.cxx uses them: a user's integrand is
// evaluated through vnl_integrant_fnct, and a definite integrator holds the one it was given.
#include <cmath>

#include "testlib/testlib_test.h"
#include "vnl/vnl_analytic_integrant.h"
#include "vnl/vnl_definite_integral.h"

namespace {
class ratio_integrant : public vnl_analytic_integrant {
 public:
  double f_(double x) override { return x / (1 + x * x); }
};

// A midpoint-rule integrator, to see the integrand set through set_fnct.
class midpoint_integral : public vnl_definite_integral {
 public:
  double integral(double a, double b, int n) const {
    double total = 0;
    const double h = (b - a) / n;
    for (int i = 0; i < n; ++i) total += pfnct_->f_(a + (i + 0.5) * h);
    return total * h;
  }
};
}  // namespace

static void test_integrant() {
  ratio_integrant f;
  vnl_integrant_fnct& g = f;
  TEST_NEAR("test integrand f = x/(1+x^2) when x=1, f is 0.5", g.f_(1), 0.5, 1e-13);
  midpoint_integral integral;
  integral.set_fnct(&f);
  TEST_NEAR("the integrator sees its integrand: int_0^1 = ln(2)/2", integral.integral(0, 1, 1000), 0.5 * std::log(2.0),
            1e-6);
}

TESTMAIN(test_integrant)
