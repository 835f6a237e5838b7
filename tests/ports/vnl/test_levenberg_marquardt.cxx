// SPDX-License-Identifier: BSD-3-Clause
// vnl_levenberg_marquardt keeps upstream's interface and meaning: it minimises a
// vnl_least_squares_function with (lmder) or without (lmdif) its Jacobian, reports the counts,
// start and end errors and termination code, honours its tolerances, reports dodgy input and
// failures of the function, and gives J^T J at the solution. Run for every scalar.
#include <sstream>
#include <string>

#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_levenberg_marquardt.h"
#include "vnl/algo/vnl_levenberg_marquardt.hxx"
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

void test_levenberg_marquardt() {
  for_each_test_scalar<CheckLm>();
  // The drop-in names: vnl_levenberg_marquardt works on vnl_vector<real>.
  Rosenbrock<real> f(true);
  vnl_levenberg_marquardt lm(f);
  vnl_vector<real> x(2);
  x[0] = real(-1.2);
  x[1] = real(1);
  TEST("vnl_levenberg_marquardt minimises on vnl_vector<real>", lm.minimize(x), true);
}

}  // namespace

TESTMAIN(test_levenberg_marquardt)
