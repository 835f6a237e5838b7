// SPDX-License-Identifier: BSD-3-Clause
// vnl_least_squares_cost_function (upstream has no test of its own): the cost is the squared
// norm of the residuals and its gradient 2 J^T r, from the function's Jacobian; without a
// Jacobian the gradient is left as it was, as upstream.
#include "testlib/testlib_test.h"
#include "vnl/vnl_least_squares_cost_function.h"

namespace {
/// r(x) = (x0 - 1, 2 x1 + 6, x0 x1): J = [1 0; 0 2; x1 x0].
class residuals : public vnl_least_squares_function {
 public:
  explicit residuals(UseGradient g) : vnl_least_squares_function(2, 3, g) {}
  void f(const vnl_vector<real>& x, vnl_vector<real>& fx) override {
    fx[0] = x[0] - real(1);
    fx[1] = real(2) * x[1] + real(6);
    fx[2] = x[0] * x[1];
  }
  void gradf(const vnl_vector<real>& x, vnl_matrix<real>& J) override {
    J(0, 0) = real(1), J(0, 1) = real(0);
    J(1, 0) = real(0), J(1, 1) = real(2);
    J(2, 0) = x[1], J(2, 1) = x[0];
  }
};
}  // namespace

static void test_least_squares_cost_function() {
  residuals with_jacobian(vnl_least_squares_function::use_gradient);
  vnl_least_squares_cost_function cost(&with_jacobian);
  const vnl_vector<double> x{3.0, -2.0};  // r = (2, 2, -6)
  TEST("unknowns from the residual function", cost.get_number_of_unknowns(), 2);
  TEST_NEAR("f is |r|^2", cost.f(x), 44.0, 1e-9);
  vnl_vector<double> g(2, 0.0);
  cost.gradf(x, g);
  // 2 J^T r = 2 (2 - 6 * -2, 2 * 2 - 6 * 3) = (28, -28)
  TEST_NEAR("gradient 2 J^T r, first", g[0], 28.0, 1e-9);
  TEST_NEAR("gradient 2 J^T r, second", g[1], -28.0, 1e-9);

  residuals without_jacobian(vnl_least_squares_function::no_gradient);
  vnl_least_squares_cost_function cost_without(&without_jacobian);
  vnl_vector<double> untouched(2, 5.0);
  cost_without.gradf(x, untouched);
  TEST("no Jacobian: the gradient is left unchanged", untouched[0] == 5.0 && untouched[1] == 5.0, true);
}

TESTMAIN(test_least_squares_cost_function)
