// SPDX-License-Identifier: BSD-3-Clause
// vnl_solve_qp as upstream's algo test_solve_qp.cxx: min |x|^2 and min |x|^2 / 2 - x.(1, -1, 1, 1)
// on the simplex, through the general and the sum-one forms; plus the equality forms and an
// infeasible start.
#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_solve_qp.h"

namespace {
constexpr unsigned n = 4;

vnl_matrix<double> identity() {
  vnl_matrix<double> H(n, n, 0.0);
  for (unsigned i = 0; i < n; ++i) H(i, i) = 1.0;
  return H;
}

vnl_vector<double> tilted_g() {
  vnl_vector<double> g(n, -1.0);
  g[1] = 1.0;
  return g;
}

vnl_vector<double> corner() {
  vnl_vector<double> x(n, 0.0);
  x[0] = 1.0;  // satisfies sum(x) = 1, x >= 0
  return x;
}

vnl_vector<double> tilted_solution() {
  vnl_vector<double> sol(n, 1.0 / 3);
  sol[1] = 0.0;
  return sol;
}
}  // namespace

static void test_solve_qp() {
  const vnl_matrix<double> A(1, n, 1.0);
  const vnl_vector<double> b(1, 1.0);
  vnl_vector<double> x = corner();
  TEST("with_non_neg_constraints succeeds",
       vnl_solve_qp_with_non_neg_constraints(identity(), vnl_vector<double>(n, 0.0), A, b, x), true);
  TEST_NEAR("|x-x_true|^2 (non-neg 1)", (x - vnl_vector<double>(n, 1.0 / n)).squared_magnitude(), 0, 1e-5);
  x = corner();
  vnl_solve_qp_with_non_neg_constraints(identity(), tilted_g(), A, b, x);
  TEST_NEAR("|x-x_true|^2 (non-neg 2)", (x - tilted_solution()).squared_magnitude(), 0, 1e-5);
  x = corner();
  vnl_solve_qp_non_neg_sum_one(identity(), vnl_vector<double>(n, 0.0), x);
  TEST_NEAR("|x-x_true|^2 (sum one 1)", (x - vnl_vector<double>(n, 1.0 / n)).squared_magnitude(), 0, 1e-5);
  x = corner();
  vnl_solve_qp_non_neg_sum_one(identity(), tilted_g(), x);
  TEST_NEAR("|x-x_true|^2 (sum one 2)", (x - tilted_solution()).squared_magnitude(), 0, 1e-5);

  // Without x >= 0: x = -g - lambda 1 with sum(x) = 2 - 4 lambda. sum(x) = 1 gives lambda = 1/4,
  // x = (0.75, -1.25, 0.75, 0.75); sum(x) = 0 gives lambda = 1/2, x = (0.5, -1.5, 0.5, 0.5).
  vnl_vector<double> xe;
  TEST("with_equality_constraints succeeds", vnl_solve_qp_with_equality_constraints(identity(), tilted_g(), A, b, xe),
       true);
  TEST_NEAR("with_equality_constraints x[1]", xe[1], -1.25, 1e-12);
  TEST_NEAR("with_equality_constraints x[0]", xe[0], 0.75, 1e-12);
  vnl_vector<double> xz;
  vnl_solve_qp_zero_sum(identity(), tilted_g(), xz);
  TEST_NEAR("zero_sum keeps sum(x) = 0", xz.sum(), 0.0, 1e-12);
  TEST_NEAR("zero_sum x[1]", xz[1], -1.5, 1e-12);
  vnl_vector<double> bad(n, 0.0);
  TEST("an infeasible start is refused", vnl_solve_qp_non_neg_sum_one(identity(), tilted_g(), bad, false), false);
}

TESTMAIN(test_solve_qp)
