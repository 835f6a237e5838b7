// SPDX-License-Identifier: BSD-3-Clause
// vnl_powell as upstream's algo test_powell.cxx: quadratics with their minimum at x_i = i in 2
// to 15 dimensions, and Rosenbrock's function from (-2, 2).
#include <cmath>
#include <string>

#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_powell.h"
#include "vnl/vnl_double_2.h"

namespace {
class powell_quadratic : public vnl_cost_function {
 public:
  explicit powell_quadratic(int n) : vnl_cost_function(n) {}
  double f(const vnl_vector<double>& x) override {
    double sum = 0;
    for (unsigned i = 0; i < x.size(); ++i) sum += (x[i] - i) * (x[i] - i);
    return sum;
  }
};
class powell_rosenbrock : public vnl_cost_function {
 public:
  powell_rosenbrock() : vnl_cost_function(2) {}
  double f(const vnl_vector<double>& x) override {
    const double a = 10 * (x[1] - x[0] * x[0]);
    const double b = 1 - x[0];
    return a * a + b * b;
  }
};
double distance_to_minimum(const vnl_vector<double>& x) {
  double err = 0;
  for (unsigned i = 0; i < x.size(); ++i) err += std::fabs(x[i] - i);
  return err;
}
}  // namespace

static void test_powell() {
  {
    vnl_vector<double> x(2);
    x[0] = 2;
    x[1] = 1;
    powell_quadratic cost(2);
    vnl_powell powell(&cost);
    TEST("2-D quadratic from (2, 1) converges", powell.minimize(x), vnl_powell::CONVERGED_FTOL);
    TEST_NEAR("to (0, 1)", distance_to_minimum(x), 0.0, 1e-5);
  }
  for (unsigned n = 1; n < 16; ++n) {
    vnl_vector<double> x(n, 1.0);
    powell_quadratic cost(static_cast<int>(n));
    vnl_powell powell(&cost);
    powell.minimize(x);
    TEST_NEAR("Starting at (1,1,1...), " + std::to_string(n) + "-D", distance_to_minimum(x), 0.0, 1e-5);
    TEST("the evaluations are counted, " + std::to_string(n) + "-D", powell.get_num_evaluations() > int(n), true);
  }
  powell_rosenbrock c;
  vnl_powell powell(&c);
  vnl_vector<double> x = vnl_double_2(-2, 2).as_vector();
  powell.minimize(x);
  TEST_NEAR("test_rosenbrock_2d", (x - vnl_double_2(1, 1).as_vector()).magnitude(), 0, 1e-6);
  TEST_NEAR("the end error is the lowest value seen", powell.get_end_error(), 0, 1e-12);
  TEST("the start error is f at the start", powell.get_start_error(), c.f(vnl_double_2(-2, 2).as_vector()));

  vnl_powell once(&c);
  once.set_max_function_evals(1);
  x = vnl_double_2(-2, 2).as_vector();
  TEST("max_function_evals bounds the iterations", once.minimize(x), vnl_powell::TOO_MANY_ITERATIONS);
}

TESTMAIN(test_powell)
