// SPDX-License-Identifier: BSD-3-Clause
// Upstream's algo test_algo.cxx: short checks of vnl_adjugate, vnl_svd_economy,
// vnl_matrix_inverse, vnl_orthogonal_complement, vnl_conjugate_gradient, vnl_lbfgs,
// vnl_powell, vnl_fft_1d/2d, vnl_lsqr and vnl_discrete_diff_fwd/_sym, plus
// vnl_least_squares_cost_function. Upstream also checks vnl_lbfgsb and vnl_generalized_schur,
// not ported.
#include <complex>
#include <vector>

#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_adjugate.h"
#include "vnl/algo/vnl_conjugate_gradient.h"
#include "vnl/algo/vnl_discrete_diff.h"
#include "vnl/algo/vnl_fft_1d.h"
#include "vnl/algo/vnl_fft_2d.h"
#include "vnl/algo/vnl_lbfgs.h"
#include "vnl/algo/vnl_lsqr.h"
#include "vnl/algo/vnl_matrix_inverse.h"
#include "vnl/algo/vnl_orthogonal_complement.h"
#include "vnl/algo/vnl_powell.h"
#include "vnl/algo/vnl_svd.h"
#include "vnl/algo/vnl_svd_economy.h"
#include "vnl/vnl_least_squares_cost_function.h"
#include "vnl/vnl_sparse_matrix_linear_system.h"
#include "vnl/vnl_least_squares_function.h"

namespace {

void test_adjugate() {
  int data[] = {1, -1, 1, -1, 1, 1, -1, -1, 1, 1, 1, 1, 1, -1, -1, 1};
  const vnl_matrix<int> m(data, 4, 4);
  vnl_matrix<int> identity(4, 4);
  identity.set_identity();
  TEST("vnl_adjugate", (m * vnl_adjugate(m) - 16 * identity).array_inf_norm(), 0);
}

void test_matrix_inverse() {
  double data[] = {1., -1., 1., -1., 1., 1., -1., -1., 1., 1., 1., 1., 1., -1., -1., 1.};
  const vnl_matrix<double> m(data, 4, 4);
  vnl_svd_economy<double> economy(m);
  vnl_svd<double> svd(m);
  TEST_NEAR("vnl_svd_economy", std::fabs(economy.V()[0][1]), std::fabs(svd.V()[0][1]), 1e-6);
  const vnl_matrix<double> inverse = vnl_matrix_inverse<double>(m).as_matrix();
  vnl_matrix<double> identity(4, 4);
  identity.set_identity();
  TEST_NEAR("vnl_matrix_inverse", (m * inverse - identity).array_inf_norm(), 0, 1e-6);
}

void test_fft() {
  std::vector<std::complex<double>> v(256);
  for (int i = 0; i < 256; ++i) v[i] = 0.5 + i;
  vnl_fft_1d<double> fft1d(256);
  fft1d.fwd_transform(v);
  fft1d.bwd_transform(v);
  TEST_NEAR("vnl_fft_1d", std::abs(v[10] - 256 * 10.5), 0.0, 1e-6);
  vnl_matrix<std::complex<double>> m(10, 9);
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 9; ++j) m[i][j] = 0.5 + i + j;
  vnl_fft_2d<double> fft2d(10, 9);
  fft2d.fwd_transform(m);
  fft2d.bwd_transform(m);
  TEST_NEAR("vnl_fft_2d", std::abs(m[5][5] - 10 * 9 * 10.5), 0.0, 1e-6);
}

void test_orthogonal_complement() {
  vnl_vector<double> v(20);
  for (int i = 0; i < 20; ++i) v[i] = 0.5 + i;
  const vnl_matrix<double> oc = vnl_orthogonal_complement(v);
  TEST("vnl_orthogonal_complement is orthogonal to v", (v * oc).inf_norm() < 1e-10, true);
}

/// Local minimum near (0, 0) at (1, 1), value 1.
class F_test_powell : public vnl_cost_function {
 public:
  F_test_powell() : vnl_cost_function(2) {}
  double f(const vnl_vector<double>& x) override {
    const double u = x[0] - x[1] * x[1];
    const double v = x[1] - 1;
    return u * u + v * v + 1;
  }
  void gradf(const vnl_vector<double>& x, vnl_vector<double>& g) override {
    g[0] = 2 * x[0] - 2 * x[1] * x[1];
    g[1] = 4 * x[1] * x[1] * x[1] - 4 * x[0] * x[1] + 2 * x[1] - 2;
  }
};

/// A constant whose gradient claims a slope: no step can lower it.
class F_broken : public vnl_cost_function {
 public:
  F_broken() : vnl_cost_function(1) {}
  double f(const vnl_vector<double>&) override { return 0; }
  void gradf(const vnl_vector<double>&, vnl_vector<double>& gradient) override { gradient[0] = 1; }
};

void test_powell() {
  F_test_powell f;
  vnl_vector<double> x(2, 0.0);
  vnl_conjugate_gradient cg(f);
  TEST("vnl_conjugate_gradient converges", cg.minimize(x), true);
  TEST_NEAR("vnl_conjugate_gradient", x[0], 1.0, 1e-5);
  TEST_NEAR("vnl_conjugate_gradient end error", cg.get_end_error(), 1.0, 1e-10);
  F_broken fb;
  vnl_vector<double> x2(1, 0.0);
  vnl_conjugate_gradient cg2(fb);
  TEST("vnl_conjugate_gradient on broken function should fail", cg2.minimize(x2), false);

  vnl_lbfgs lbfgs(f);
  x.fill(0);
  TEST("vnl_lbfgs converges", lbfgs.minimize(x), true);
  // |g| <= 1e-5 bounds |x - x*| by |g| / 0.34, the Hessian's smallest eigenvalue at (1, 1).
  TEST_NEAR("vnl_lbfgs", x[1], 1.0, 4e-5);
  lbfgs.set_g_tolerance(1e-9);
  x.fill(0);
  lbfgs.minimize(x);
  TEST_NEAR("vnl_lbfgs with a tighter gtol", x[1], 1.0, 1e-8);
  TEST("vnl_lbfgs lowered f", lbfgs.obj_value_reduced(), true);
  vnl_lbfgs broken(fb);
  TEST("vnl_lbfgs on broken function should fail", broken.minimize(x2), false);

  vnl_powell powell(&f);
  x.fill(0);
  powell.minimize(x);
  TEST_NEAR("vnl_powell", f.f(x), 1.0, 1e-6);
}

void test_lsqr() {
  vnl_sparse_matrix<double> A(2, 2);
  A(0, 0) = 2;
  A(0, 1) = 3;
  A(1, 0) = 4;
  A(1, 1) = 5;
  vnl_vector<double> b(2);
  b[0] = 5;
  b[1] = 9;
  vnl_sparse_matrix_linear_system<double> ls(A, b);
  vnl_vector<double> x(2, 0.0);
  vnl_lsqr lsqr(ls);
  const int code = lsqr.minimize(x);
  TEST_NEAR("vnl_lsqr", x[1], 1.0, 1e-6);
  TEST_NEAR("vnl_lsqr (x[0])", x[0], 1.0, 1e-6);
  TEST("vnl_lsqr stops on a compatible system", code == 1 || code == 4, true);
  TEST_NEAR("and estimates a zero residual", lsqr.get_resid_norm_estimate(), 0.0, 1e-9);
  // An overdetermined fit: y = 2 t + 1 through 4 points with noise of +-0.1.
  vnl_sparse_matrix<double> F(4, 2);
  vnl_vector<double> y(4);
  const double noise[4] = {0.1, -0.1, -0.1, 0.1};
  for (unsigned i = 0; i < 4; ++i) {
    F(i, 0) = i;
    F(i, 1) = 1;
    y[i] = 2.0 * i + 1 + noise[i];
  }
  vnl_sparse_matrix_linear_system<double> fit(F, y);
  vnl_lsqr lsqr_fit(fit);
  vnl_vector<double> ab;
  lsqr_fit.minimize(ab);
  TEST_NEAR("vnl_lsqr on an overdetermined system gives the least-squares slope", ab[0], 2.0, 1e-9);
  TEST_NEAR("and intercept", ab[1], 1.0, 1e-9);
}

class F_test_discrete_diff : public vnl_least_squares_function {
 public:
  F_test_discrete_diff() : vnl_least_squares_function(2, 2, no_gradient) {}
  void f(const vnl_vector<double>& x, vnl_vector<double>& fx) override {
    fx[0] = x[0] - x[1] * x[1];
    fx[1] = x[1] - 1;
  }
};

void test_discrete_diff() {
  F_test_discrete_diff f;
  vnl_vector<double> x(2);
  x[0] = 5.0;
  x[1] = 9.0;
  vnl_matrix<double> J(2, 2);
  TEST("vnl_discrete_diff_fwd succeeds", vnl_discrete_diff_fwd(&f, 0.1, x, J), true);
  TEST_NEAR("vnl_discrete_diff_fwd", J(0, 1), -18.1, 1e-6);
  TEST_NEAR("vnl_discrete_diff_fwd, the linear entry", J(0, 0), 1, 1e-9);
  TEST("vnl_discrete_diff_sym succeeds", vnl_discrete_diff_sym(&f, 0.1, x, J), true);
  TEST_NEAR("vnl_discrete_diff_sym", J(0, 1), -18, 1e-6);
}

/// r = (x0 - x1^2, x1 - 1) with its Jacobian, for vnl_least_squares_cost_function.
class F_residuals_with_gradient : public F_test_discrete_diff {
 public:
  F_residuals_with_gradient() { use_gradient_ = true; }
  void gradf(const vnl_vector<double>& x, vnl_matrix<double>& J) override {
    J(0, 0) = 1;
    J(0, 1) = -2 * x[1];
    J(1, 0) = 0;
    J(1, 1) = 1;
  }
};

void test_least_squares_cost_function() {
  F_residuals_with_gradient residuals;
  vnl_least_squares_cost_function cost(&residuals);
  vnl_vector<double> x(2);
  x[0] = 5.0;
  x[1] = 2.0;
  TEST_NEAR("vnl_least_squares_cost_function is |r|^2", cost.f(x), 1 + 1, 1e-12);
  vnl_vector<double> g(2);
  cost.gradf(x, g);
  TEST_NEAR("its gradient is 2 J^T r (0)", g[0], 2 * 1, 1e-12);
  TEST_NEAR("its gradient is 2 J^T r (1)", g[1], 2 * (1 * -4 + 1 * 1), 1e-12);
  x.fill(0);
  vnl_lbfgs lbfgs(cost);
  lbfgs.set_g_tolerance(1e-10);
  lbfgs.minimize(x);
  TEST_NEAR("vnl_lbfgs on it finds the zero residual", x[0] + x[1], 2, 1e-6);
}

}  // namespace

static void test_algo() {
  test_adjugate();
  test_matrix_inverse();
  test_fft();
  test_orthogonal_complement();
  test_powell();
  test_lsqr();
  test_discrete_diff();
  test_least_squares_cost_function();
}

TESTMAIN(test_algo)
