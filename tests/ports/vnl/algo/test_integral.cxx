// SPDX-License-Identifier: BSD-3-Clause
// vnl_simpson_integral and vnl_adaptsimpson_integral as upstream's algo test_integral.cxx:
// x/(1+x^2) over [0, 1] is ln(2)/2, and a Gaussian filter over [-10, 10] integrates to 1;
// plus vnl_chi_squared and vnl_fit_parabola.
#include <cmath>

#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_adaptsimpson_integral.h"
#include "vnl/algo/vnl_chi_squared.h"
#include "vnl/algo/vnl_fit_parabola.h"
#include "vnl/algo/vnl_simpson_integral.h"

namespace {
class ratio : public vnl_integrant_fnct {
 public:
  double f_(double x) override { return x / (1 + x * x); }
};
class gaussian : public vnl_integrant_fnct {
 public:
  double f_(double x) override { return std::exp(-x * x / 2) / std::sqrt(2 * 3.14159265358979323846); }
};
}  // namespace

static void test_integral() {
  ratio f;
  gaussian g;
  vnl_simpson_integral simpson;
  vnl_adaptsimpson_integral adaptive;
  TEST_NEAR("simpson integral of x/(1+x^2) from 0 to 1", simpson.integral(&f, 0, 1, 100), 0.5 * std::log(2.0), 1e-8);
  TEST_NEAR("adaptive simpson integral of x/(1+x^2) from 0 to 1", adaptive.integral(&f, 0, 1, 1e-11),
            0.5 * std::log(2.0), 1e-11);
  TEST_NEAR("simpson integral of a Gaussian from -10 to 10", simpson.integral(&g, -10, 10, 1000), 1.0, 1e-9);
  TEST_NEAR("adaptive simpson integral of a Gaussian from -10 to 10", adaptive.integral(&g, -10, 10, 1e-6), 1.0,
            1e-6);
  TEST_NEAR("chi-squared CDF with 2 dof at 2 is 1 - exp(-1)", vnl_chi_squared_cumulative(2.0, 2),
            1 - std::exp(-1.0), 1e-14);
  const int a[] = {10, 20, 30}, b[] = {12, 18, 30};
  TEST_NEAR("chi-squared statistic 1", vnl_chi_squared_statistic_1(a, b, 3, false), 4.0 / 10 + 4.0 / 20, 1e-15);
  TEST_NEAR("chi-squared statistic 2", vnl_chi_squared_statistic_2(a, b, 3, false), 4.0 / 12 + 4.0 / 18, 1e-15);
  TEST_NEAR("chi-squared statistic 12", vnl_chi_squared_statistic_12(a, b, 3, false), 4.0 / 22 + 4.0 / 38, 1e-15);
  double p = 0, q = 0;
  vnl_fit_parabola(0, 1, 3, 4, 1, 1, p, q);  // (x - 2)^2: extremum at 2 = 1 + p/q
  TEST_NEAR("vnl_fit_parabola finds the vertex", 1 + p / q, 2.0, 1e-15);
}

TESTMAIN(test_integral)
