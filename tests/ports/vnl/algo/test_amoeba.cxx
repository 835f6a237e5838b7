// SPDX-License-Identifier: BSD-3-Clause
// vnl_amoeba as upstream's algo test_amoeba.cxx: a 1-D parabola from 77, and n-D quadratics
// with their minimum at x_i = i (n = 1..4) from (1, ...), from 0 with more iterations, from 0
// with an absolute start simplex, and through the static forms; plus a least-squares function.
#include <cmath>

#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_amoeba.h"
#include "vnl/vnl_cost_function.h"
#include "vnl/vnl_least_squares_function.h"

namespace {
struct amoeba_cubic : public vnl_cost_function {
  amoeba_cubic() : vnl_cost_function(1) {}
  double f(const vnl_vector<double>& x) override { return (2 - x[0]) * (2 - x[0]) + 10; }
};
struct amoeba_cost1 : public vnl_cost_function {
  explicit amoeba_cost1(int n) : vnl_cost_function(n) {}
  double f(const vnl_vector<double>& x) override {
    double sum = 0;
    for (unsigned i = 0; i < x.size(); ++i) sum += (x[i] - i) * (x[i] - i);
    return sum;
  }
};
struct line_residuals : public vnl_least_squares_function {
  line_residuals() : vnl_least_squares_function(2, 3, no_gradient) {}
  void f(const vnl_vector<double>& x, vnl_vector<double>& fx) override {
    for (unsigned i = 0; i < 3; ++i) fx[i] = x[0] * i + x[1] - (3.0 * i - 1);
  }
};
double distance_to_minimum(const vnl_vector<double>& x) {
  double err = 0;
  for (unsigned i = 0; i < x.size(); ++i) err += std::fabs(x[i] - i);
  return err;
}
}  // namespace

static void test_amoeba() {
  amoeba_cubic c;
  vnl_amoeba amoeba1(c);
  vnl_vector<double> x(1, 77.0);
  amoeba1.minimize(x);
  TEST_NEAR("amoeba1", x[0], 2, 1e-5);
  TEST_NEAR("the end error is f at the minimum", amoeba1.get_end_error(), 10, 1e-8);
  TEST("maxiter defaults to 200 per unknown", amoeba1.maxiter, 200);

  for (unsigned n = 1; n <= 4; ++n) {
    const std::string dims = " (" + std::to_string(n) + "-D)";
    amoeba_cost1 cost1(static_cast<int>(n));
    vnl_amoeba amoeba2(cost1);
    x.set_size(n);
    x.fill(1);
    amoeba2.minimize(x);
    TEST_NEAR("Quadratic, starting at (1,1,1...)" + dims, distance_to_minimum(x), 0.0, 1e-5);
    TEST("evaluations are counted" + dims, amoeba2.get_num_evaluations() > static_cast<int>(n), true);
    x.fill(0);
    amoeba2.set_max_iterations(10000);
    amoeba2.minimize(x);
    TEST_NEAR("Quadratic, starting at (0,0,0...)" + dims, distance_to_minimum(x), 0.0, 1e-5);
    vnl_vector<double> dx(n, 0.1);
    x.fill(0);
    amoeba2.minimize(x, dx);
    TEST_NEAR("Quadratic, starting at (0,0,0...) using minimize(x, dx)" + dims, distance_to_minimum(x), 0.0, 1e-5);
    x.fill(0);
    vnl_amoeba::minimize(cost1, x, dx);
    TEST_NEAR("the static minimize(f, x, dx)" + dims, distance_to_minimum(x), 0.0, 1e-5);
  }

  vnl_amoeba few(c);
  few.set_max_iterations(5);
  x.set_size(1);
  x[0] = 77;
  few.minimize(x);
  TEST("set_max_iterations bounds the evaluations", few.get_num_evaluations() <= 5 + 3, true);
  TEST("and stops short of the minimum", std::fabs(x[0] - 2) > 1, true);

  line_residuals residuals;
  vnl_vector<double> line(2, 0.0);
  vnl_amoeba::minimize(residuals, line);
  TEST_NEAR("a least-squares function: its sum of squares is minimised (slope)", line[0], 3, 1e-4);
  TEST_NEAR("a least-squares function: its sum of squares is minimised (intercept)", line[1], -1, 1e-4);
}

TESTMAIN(test_amoeba)
