// SPDX-License-Identifier: BSD-3-Clause
// vnl_real_polynomial as upstream's test_real_polynomial.cxx: sums, products, derivative,
// primitive, integral, RMS difference and the printed form.
#include <cmath>
#include <complex>
#include <sstream>
#include <string>

#include "testlib/testlib_test.h"
#include "vnl/vnl_real_polynomial.h"

namespace {
std::string printed(const vnl_real_polynomial& p) {
  std::ostringstream out;
  p.print(out);
  return out.str();
}
}  // namespace

static void test_real_polynomial() {
  const double a1[] = {1, 2, 3, 4};  // X^3 + 2 X^2 + 3 X + 4
  const double a2[] = {2, -1, 5};    // 2 X^2 - X + 5
  const vnl_real_polynomial f1(a1, 4), f2(a2, 3);
  TEST("f1 prints as X^3 +2 X^2 +3 X +4", printed(f1), std::string(" X^3 +2 X^2 +3 X +4"));
  TEST("degree of f1 is 3", f1.degree(), 3);
  TEST_NEAR("f1(2) = 8 + 8 + 6 + 4", f1.evaluate(2.0), 26.0, 0.0);
  TEST_NEAR("f1 at the complex point i is (4-2) + (3-1)i", f1.evaluate(std::complex<double>(0, 1)),
            std::complex<double>(2, 2), 1e-15);
  const double a3[] = {1, 4, 2, 9};
  TEST("f1+f2=f3", f1 + f2 == vnl_real_polynomial(a3, 4), true);
  const double a4[] = {1, 0, 4, -1};
  TEST("f1-f2=f4", f1 - f2 == vnl_real_polynomial(a4, 4), true);
  const vnl_real_polynomial f5 = f1 * f2;
  TEST("f1*f2 has correct degree", f5.degree(), 5);
  const double a5[] = {2, 3, 9, 15, 11, 20};
  TEST("f1*f2=f5", f5 == vnl_real_polynomial(a5, 6), true);
  const double d1[] = {3, 4, 3};
  TEST("Derivative", f1.derivative() == vnl_real_polynomial(d1, 3), true);
  TEST_NEAR("devaluate(1) is f1'(1) = 10", f1.devaluate(1.0), 10.0, 0.0);
  const double p1[] = {0.25, 2.0 / 3, 1.5, 4, 0};
  TEST("Primitive", (f1.primitive() - vnl_real_polynomial(p1, 5)).coefficients().inf_norm() < 1e-15, true);
  TEST_NEAR("Integral from -1 to 2", f1.evaluate_integral(-1.0, 2.0), 4 * 3 + 1.5 * 3 + (2.0 / 3) * 9 + 0.25 * 15,
            1e-12);
  TEST("Polynomial of degree 0", vnl_real_polynomial(3.5).degree(), 0);
  const vnl_vector<double> v(a2, 3);
  TEST("Vector initialisation", vnl_real_polynomial(v) == f2, true);
  // f1 - f2 = X^3 + 4X - 1; its square integrated over [0, 1]: 1/7 + 8/5 + 16/3 - 2/4 - 8/2 + 1.
  TEST_NEAR("RMS difference(f1,f2)", vnl_rms_difference(f1, f2, 0, 1),
            std::sqrt(1.0 / 7 + 8.0 / 5 + 16.0 / 3 - 0.5 - 4 + 1), 1e-12);
  const double a6[] = {1, 1}, a7[] = {1, -1}, a8[] = {0, 0};
  TEST("f6 prints as X +1", printed(vnl_real_polynomial(a6, 2)), std::string(" X +1"));
  TEST("f7 prints as X -1", printed(vnl_real_polynomial(a7, 2)), std::string(" X -1"));
  TEST("f8 prints as 0", printed(vnl_real_polynomial(a8, 2)), std::string(" 0"));
  const double a9[] = {-1, 0, -2.5};
  TEST("-X^2 -2.5 prints with its signs", printed(vnl_real_polynomial(a9, 3)), std::string(" -X^2 -2.5"));
}

TESTMAIN(test_real_polynomial)
