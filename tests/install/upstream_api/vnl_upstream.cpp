// SPDX-License-Identifier: BSD-3-Clause
/// VXL-style use of vnl_levenberg_marquardt on double: Rosenbrock's function as two residuals.
#include <cmath>
#include <cstdio>

#include <vnl/algo/vnl_levenberg_marquardt.h>
#include <vnl/vnl_least_squares_function.h>
#include <vnl/vnl_vector.h>

class Rosenbrock : public vnl_least_squares_function {
 public:
  Rosenbrock() : vnl_least_squares_function(2, 2, no_gradient) {}
  void f(vnl_vector<double> const& x, vnl_vector<double>& fx) override {
    fx[0] = 10 * (x[1] - x[0] * x[0]);
    fx[1] = 1 - x[0];
  }
};

int main() {
  Rosenbrock function;
  vnl_levenberg_marquardt lm(function);
  vnl_vector<double> x(2);
  x[0] = -1.9;
  x[1] = 2;
  const bool converged = lm.minimize(x);
  std::printf("minimum %.9f %.9f error %.3g\n", x[0], x[1], lm.get_end_error());
  return converged && std::fabs(x[0] - 1) < 1e-6 && std::fabs(x[1] - 1) < 1e-6 ? 0 : 1;
}
