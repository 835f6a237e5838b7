// SPDX-License-Identifier: BSD-3-Clause
// vnl_levenberg_marquardt keeps upstream's interface and meaning: it minimises a
// vnl_least_squares_function with (lmder) or without (lmdif) its Jacobian, reports the counts,
// start and end errors and termination code, honours its tolerances, reports dodgy input and
// failures of the function, and gives J^T J at the solution. Run for every scalar, and as
// upstream's own test on double, in every build.
#include <cmath>
#include <sstream>
#include <string>
#include <type_traits>

#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_levenberg_marquardt.h"
#include "vnl/algo/vnl_levenberg_marquardt.hxx"
#include "vnl/vnl_double_2.h"
#include "vnl/vnl_least_squares_function.h"
#include "vnl_test_types.h"

namespace {

/// Rosenbrock's function as upstream's test writes it: residuals 10 (y - x^2) and 1 - x.
template <class T>
class Rosenbrock : public vnl_least_squares_function_of<T> {
 public:
  explicit Rosenbrock(bool with_gradient)
      : vnl_least_squares_function_of<T>(2, 2, with_gradient ? this->use_gradient : this->no_gradient) {}
  void f(const vnl_vector<T>& x, vnl_vector<T>& fx) override {
    fx[0] = T(10) * (x[1] - x[0] * x[0]);
    fx[1] = T(1) - x[0];
  }
  void gradf(const vnl_vector<T>& x, vnl_matrix<T>& J) override {
    J(0, 0) = T(-20) * x[0];
    J(0, 1) = T(10);
    J(1, 0) = T(-1);
    J(1, 1) = T(0);
  }
};

/// a exp(b t) fitted to 8 samples of 2 exp(-t/2) with +-0.01 added: a nonzero-residual problem.
template <class T>
class ExponentialFit : public vnl_least_squares_function_of<T> {
 public:
  ExponentialFit() : vnl_least_squares_function_of<T>(2, 8, this->no_gradient) {}
  void f(const vnl_vector<T>& x, vnl_vector<T>& fx) override {
    using std::exp;
    static constexpr T kY[8] = {T(2.01), T(1.7550), T(1.5676), T(1.3646), T(1.2231), T(1.0605), T(0.9547), T(0.8237)};
    for (int i = 0; i < 8; ++i) fx[i] = x[0] * exp(x[1] * T(i) / T(4)) - kY[i];
  }
};

/// A line fit whose residual function fails once it has been called `allowed` times.
template <class T>
class FailingLine : public vnl_least_squares_function_of<T> {
 public:
  explicit FailingLine(int allowed) : vnl_least_squares_function_of<T>(2, 4, this->no_gradient), allowed_(allowed) {}
  void f(const vnl_vector<T>& x, vnl_vector<T>& fx) override {
    for (int i = 0; i < 4; ++i) fx[i] = x[0] * T(i) + x[1] - T(2 * i + 1);
    if (--allowed_ < 0) this->throw_failure();
  }

 private:
  int allowed_;
};

template <class T>
struct CheckLm {
  static void run(const std::string& type) {
    const std::string in = " (" + type + ")";
    const double tol = ulps<T>(1e4) > 1e-6 ? ulps<T>(1e4) : 1e-6;
    for (bool with_gradient : {true, false}) {
      const std::string how = with_gradient ? "with the Jacobian" : "with forward differences";
      Rosenbrock<T> f(with_gradient);
      vnl_levenberg_marquardt_of<T> lm(f);
      TEST("default max_function_evals is 400 per unknown" + in, lm.get_max_function_evals(), 800);
      vnl_vector<T> x(2);
      x[0] = T(-1.2);
      x[1] = T(1);
      const bool ok = lm.minimize(x);
      TEST("minimize succeeds on Rosenbrock " + how + in, ok, true);
      TEST_NEAR("minimize reaches x = 1 " + how + in, x[0], 1.0, tol);
      TEST_NEAR("minimize reaches y = 1 " + how + in, x[1], 1.0, tol);
      TEST_NEAR("start error is the RMS residual at (-1.2, 1) " + how + in, lm.get_start_error(),
                std::sqrt((4.4 * 4.4 + 2.2 * 2.2) / 2), 1e3 * tol);
      TEST_NEAR("end error is about zero " + how + in, lm.get_end_error(), 0.0, tol);
      TEST("failure code is a convergence code " + how + in,
           lm.get_failure_code() >= lm.CONVERGED_FTOL && lm.get_failure_code() <= lm.CONVERGED_GTOL, true);
      TEST("evaluations were counted " + how + in, lm.get_num_evaluations() > 2, true);
      if (with_gradient) {
        TEST("with lmder, iterations count evaluations as upstream" + in, lm.get_num_iterations(),
             lm.get_num_evaluations());
        TEST("with lmder, the Jacobian is evaluated once per MINPACK iteration" + in,
             lm.get_num_jacobian_evaluations() > 0 && lm.get_num_jacobian_evaluations() < lm.get_num_evaluations(),
             true);
        // J at (1, 1) is [[-20, 10], [-1, 0]], so J^T J = [[401, -200], [-200, 100]].
        const vnl_matrix<T> jtj = lm.get_JtJ();
        TEST_NEAR("get_JtJ (0,0) at the solution" + in, jtj(0, 0), 401.0, 401 * tol);
        TEST_NEAR("get_JtJ (0,1) at the solution" + in, jtj(0, 1), -200.0, 401 * tol);
        TEST_NEAR("get_JtJ (1,0) at the solution" + in, jtj(1, 0), -200.0, 401 * tol);
        TEST_NEAR("get_JtJ (1,1) at the solution" + in, jtj(1, 1), 100.0, 401 * tol);
      } else {
        TEST("with lmdif, there is one evaluation more per Jacobian than iterations" + in,
             lm.get_num_evaluations() >= 2 * lm.get_num_iterations(), true);
      }
      std::ostringstream out;
      lm.diagnose_outcome(out);
      TEST("diagnose_outcome names the outcome" + in, out.str().find("converged") != std::string::npos, true);
      TEST("diagnose_outcome gives the evaluations" + in,
           out.str().find(std::to_string(lm.get_num_evaluations()) + " evaluations") != std::string::npos, true);
    }

    Rosenbrock<T> f(true);
    vnl_levenberg_marquardt_of<T> limited(f);
    limited.set_max_function_evals(3);
    vnl_vector<T> x(2);
    x[0] = T(-1.2);
    x[1] = T(1);
    TEST("set_max_function_evals stops the solver" + in, limited.minimize_using_gradient(x), false);
    TEST("and reports too many iterations" + in, limited.get_failure_code(), limited.TOO_MANY_ITERATIONS);

    ExponentialFit<T> fit;
    vnl_levenberg_marquardt_of<T> loose(fit);
    loose.set_x_tolerance(T(0.05));
    loose.set_f_tolerance(T(0.05));
    vnl_vector<T> ab(2);
    ab[0] = T(1);
    loose.minimize(ab);
    vnl_levenberg_marquardt_of<T> tight(fit);
    ab[0] = T(1);
    ab[1] = T(0);
    tight.minimize(ab);
    TEST("looser tolerances stop sooner" + in, loose.get_num_evaluations() < tight.get_num_evaluations(), true);
    TEST_NEAR("the exponential fit finds a = 2" + in, ab[0], 2.0, 0.01);
    TEST_NEAR("the exponential fit finds b = -1/2" + in, ab[1], -0.5, 0.01);

    vnl_vector<T> wrong_size(3);
    TEST("an x of the wrong size is rejected" + in, tight.minimize(wrong_size), false);
    TEST("as dodgy input" + in, tight.get_failure_code(), tight.ERROR_DODGY_INPUT);
    Rosenbrock<T> no_gradient(false);
    vnl_levenberg_marquardt_of<T> needs_gradient(no_gradient);
    TEST("minimize_using_gradient needs a gradient" + in, needs_gradient.minimize_using_gradient(x), false);

    FailingLine<T> failing(3);
    vnl_levenberg_marquardt_of<T> stopped(failing);
    vnl_vector<T> line(2);
    TEST("a failing function stops the solver" + in, stopped.minimize(line), false);
    TEST("with ERROR_FAILURE" + in, stopped.get_failure_code(), stopped.ERROR_FAILURE);
    FailingLine<T> fine(1000);
    vnl_levenberg_marquardt_of<T> fits(fine);
    line.fill(T(0));
    fits.minimize(line);
    TEST_NEAR("the line fit finds slope 2" + in, line[0], 2.0, tol);
    TEST_NEAR("the line fit finds intercept 1" + in, line[1], 1.0, tol);
  }
};

// Upstream's test as a user writes it: classes derived from vnl_least_squares_function on
// vnl_vector<double>, minimised by vnl_levenberg_marquardt, whatever `real` is.
struct vnl_rosenbrock : public vnl_least_squares_function {
  explicit vnl_rosenbrock(bool with_grad) : vnl_least_squares_function(2, 2, with_grad ? use_gradient : no_gradient) {}
  void f(const vnl_vector<double>& x, vnl_vector<double>& y) override {
    y[0] = 10 * (x[1] - x[0] * x[0]);
    y[1] = 1 - x[0];
  }
  void gradf(const vnl_vector<double>& x, vnl_matrix<double>& J) override {
    J[0][0] = -20 * x[0];
    J[0][1] = 10;
    J[1][0] = -1;
    J[1][1] = 0;
  }
};

struct linear_est : public vnl_least_squares_function {
  linear_est(const vnl_matrix<double>& A, const vnl_vector<double>& b, bool with_grad)
      : vnl_least_squares_function(A.cols(), A.rows(), with_grad ? use_gradient : no_gradient), A_(A), b_(b) {}
  void f(const vnl_vector<double>& x, vnl_vector<double>& y) override { y = A_ * x - b_; }
  void gradf(const vnl_vector<double>&, vnl_matrix<double>& J) override { J = A_; }
  vnl_matrix<double> A_;
  vnl_vector<double> b_;
};

void do_rosenbrock_test(bool with_grad) {
  vnl_rosenbrock f(with_grad);
  vnl_levenberg_marquardt lm(f);
  vnl_double_2 x0(2.7, -1.3);
  vnl_vector<double> x1 = x0.as_vector();
  if (f.has_gradient())
    lm.minimize_using_gradient(x1);
  else
    lm.minimize_without_gradient(x1);
  const double err = std::abs(x1[0] - 1) + std::abs(x1[1] - 1);
  TEST_NEAR(std::string("upstream's Rosenbrock on double converges to (1, 1) ") + (with_grad ? "with" : "without") +
                " the gradient",
            err, 0.0, 1e-10);
  constexpr bool on_double = std::is_base_of_v<vnl_levenberg_marquardt_of<double>, vnl_levenberg_marquardt> &&
                            std::is_base_of_v<vnl_least_squares_function_of<double>, vnl_least_squares_function>;
  TEST("the upstream classes are the double instantiation", on_double, true);
  // The fixed-size overload and the one-call form.
  x0 = vnl_double_2(2.7, -1.3);
  TEST("minimize on a vnl_double_2", lm.minimize(x0), true);
  TEST_NEAR("moves the vnl_double_2 to (1, 1)", std::abs(x0[0] - 1) + std::abs(x0[1] - 1), 0.0, 1e-10);
  const vnl_vector<double> x2 = vnl_levenberg_marquardt_minimize(f, vnl_double_2(2.7, -1.3).as_vector());
  TEST_NEAR("vnl_levenberg_marquardt_minimize reaches (1, 1)", std::abs(x2[0] - 1) + std::abs(x2[1] - 1), 0.0, 1e-10);
}

void do_linear_test(bool with_grad) {
  vnl_matrix<double> A(6, 2, 1.0);
  vnl_vector<double> b(6);
  const double column[6] = {10, 15, 5.1, 20.2, -0.3, 25};
  const double rhs[6] = {10, 15.5, 4.5, 21, 1, 24.3};
  for (unsigned i = 0; i < 6; ++i) {
    A(i, 1) = column[i];
    b(i) = rhs[i];
  }
  linear_est f(A, b, with_grad);
  vnl_levenberg_marquardt lm(f);
  vnl_vector<double> x(2, -1000.0);
  lm.set_x_tolerance(1e-12);
  lm.set_f_tolerance(1e-12);
  lm.set_g_tolerance(1e-12);
  TEST_NEAR("set_x_tolerance sets the difference step to xtol / 1000, as upstream", lm.get_epsilon_function(), 1e-15,
            1e-28);
  if (f.has_gradient())
    lm.minimize_using_gradient(x);
  else
    lm.minimize_without_gradient(x);
  vnl_vector<double> true_x(2);
  true_x[0] = 0.595607200429874;
  true_x[1] = 0.969684757298943;
  TEST_NEAR("upstream's linear fit on double converges to the true estimate", (true_x - x).two_norm(), 0, 1e-6);
  vnl_matrix<double> true_cov(2, 2);
  true_cov(0, 0) = 6;
  true_cov(1, 0) = 75;
  true_cov(0, 1) = 75;
  true_cov(1, 1) = 1384.14;
  const vnl_matrix<double> covar = lm.get_JtJ();
  TEST_NEAR("and its J^T J is A^T A", (true_cov - covar).array_two_norm(), 0, 1e-5);
  TEST("the error went down", lm.obj_value_reduced(), true);
}

void test_difference_jacobians() {
  vnl_rosenbrock f(true);
  vnl_vector<double> x(2);
  x[0] = 0.5;
  x[1] = 2;
  vnl_matrix<double> exact(2, 2), central(2, 2), forward(2, 2);
  f.gradf(x, exact);
  f.fdgradf(x, central, 1e-4);
  f.ffdgradf(x, forward, 1e-4);
  // Residual 0 is quadratic in x[0]: central differences are exact, forward ones are off by 10 h.
  TEST_NEAR("fdgradf takes central differences", (central - exact).array_inf_norm(), 0.0, 1e-8);
  TEST_NEAR("ffdgradf takes forward differences", forward(0, 0) - exact(0, 0), -10 * 1e-4, 1e-8);
  const vnl_nonlinear_minimizer& base = vnl_levenberg_marquardt(f);
  TEST("vnl_levenberg_marquardt is a vnl_nonlinear_minimizer", base.is_class("vnl_nonlinear_minimizer"), true);
}

void test_levenberg_marquardt() {
  for_each_test_scalar<CheckLm>();
  // The tracker's use: the template on vnl_vector<real>.
  Rosenbrock<real> f(true);
  vnl_levenberg_marquardt_of<real> lm(f);
  vnl_vector<real> x(2);
  x[0] = real(-1.2);
  x[1] = real(1);
  TEST("vnl_levenberg_marquardt_of<real> minimises on vnl_vector<real>", lm.minimize(x), true);
  do_rosenbrock_test(true);
  do_rosenbrock_test(false);
  do_linear_test(true);
  do_linear_test(false);
  test_difference_jacobians();
}

}  // namespace

TESTMAIN(test_levenberg_marquardt)
