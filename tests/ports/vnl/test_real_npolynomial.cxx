// SPDX-License-Identifier: BSD-3-Clause
// vnl_real_npolynomial as upstream's test_real_npolynomial.cxx: degrees, evaluation, sums,
// differences and products agreeing with evaluation, partial derivatives and simplification.
#include <cmath>
#include <string>

#include "testlib/testlib_test.h"
#include "vnl/vnl_real_npolynomial.h"

namespace {
vnl_real_npolynomial make(std::initializer_list<double> c, std::initializer_list<std::initializer_list<unsigned>> p) {
  return vnl_real_npolynomial(vnl_vector<double>(c), vnl_matrix<unsigned int>(p));
}
}  // namespace

static void test_real_npolynomial() {
  const vnl_real_npolynomial f0 = make({1, 2, 3}, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}});  // X + 2Y + 3Z
  TEST("f0 has total degree 1", f0.degree(), 1u);
  TEST("f0 has maximal degree 1", f0.maxdegree(), 1u);
  TEST("f0 has degree 1 in X, Y and Z", f0.degrees() == std::vector<unsigned>({1, 1, 1}), true);
  const vnl_real_npolynomial f1 = make({5, -1, 2}, {{2, 1}, {0, 3}, {0, 0}});  // 5 X^2 Y - Y^3 + 2
  const vnl_real_npolynomial f2 = make({1, 4}, {{3, 0}, {1, 2}});              // X^3 + 4 X Y^2
  TEST("f1 has total degree 3", f1.degree(), 3u);
  TEST("f1 has degree 2 in X", f1.degrees()[0], 2u);
  TEST("f2 has total degree 3", f2.degree(), 3u);
  const vnl_vector<double> v{2, -1};
  TEST("f1(2, -1) = -20 + 1 + 2", f1.eval(v), -17.0);
  TEST("f1+f2=f3", (f1 + f2).eval(v), f1.eval(v) + f2.eval(v));
  TEST("f1-f2=f4", (f1 - f2).eval(v), f1.eval(v) - f2.eval(v));
  TEST("f1*f2=f5", (f1 * f2).eval(v), f1.eval(v) * f2.eval(v));
  TEST("f1*f2 has total degree 6", (f1 * f2).degree(), 6u);
  TEST("f1 - f1 has no terms", (f1 - f1).nterms(), 0u);
  TEST("f1 + 3 at (2, -1)", (f1 + 3.0).eval(v), -14.0);
  TEST("2 * f2", (2.0 * f2).eval(v), 2 * f2.eval(v));
  const vnl_real_npolynomial dfx = f1.deriv(0);  // 10 X Y
  TEST("d f1 / dX = 10 X Y", dfx.nterms() == 1 && dfx.eval(v) == -20.0, true);
  TEST("deval in Y: 5 X^2 - 3 Y^2", f1.deval(v, 1), 17.0);
  TEST("gradient", f1.deval(v)[0], -20.0);
  const vnl_real_npolynomial twice = make({1, 1}, {{1, 1}, {1, 1}});
  TEST("simplify merges like terms", twice.nterms() == 1 && twice[0] == 2.0, true);
  TEST("asString", f1.asString(), std::string("5 X^2 Y - Y^3 + 2"));
  vnl_matrix<double> powers(2, 4);
  for (unsigned k = 0; k < 4; ++k) powers(0, k) = std::pow(2.0, k), powers(1, k) = std::pow(-1.0, k);
  TEST("eval from precomputed powers", f1.eval(powers), -17.0);
}

TESTMAIN(test_real_npolynomial)
