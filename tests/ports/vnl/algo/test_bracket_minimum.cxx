// SPDX-License-Identifier: BSD-3-Clause
// vnl_bracket_minimum as upstream's algo test_bracket_minimum.cxx: from starts on either side
// the bracket a, b, c has b between a and c and f(b) below f(a) and f(c).
#include <cmath>

#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_bracket_minimum.h"

namespace {
struct shifted_parabola : public vnl_cost_function {
  shifted_parabola() : vnl_cost_function(1) {}
  double f(const vnl_vector<double>& x) override { return (x[0] - 3.5) * (x[0] - 3.5) + 1; }
};

bool brackets(double a, double b, double c, double fa, double fb, double fc) {
  return ((a < b && b < c) || (c < b && b < a)) && fb <= fa && fb <= fc;
}
}  // namespace

static void test_bracket_minimum() {
  shifted_parabola f;
  double a = 0, b = 1, c = 0, fa = 0, fb = 0, fc = 0;
  vnl_bracket_minimum(f, a, b, c, fa, fb, fc);
  TEST("bracket from the left", brackets(a, b, c, fa, fb, fc), true);
  TEST("it contains the minimum 3.5", std::fmin(a, c) < 3.5 && std::fmax(a, c) > 3.5, true);
  a = 100, b = 99;
  vnl_bracket_minimum(f, a, b, c, fa, fb, fc);
  TEST("bracket from the right", brackets(a, b, c, fa, fb, fc), true);
  TEST("the values are f's", fb, (b - 3.5) * (b - 3.5) + 1);
}

TESTMAIN(test_bracket_minimum)
