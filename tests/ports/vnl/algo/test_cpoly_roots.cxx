// SPDX-License-Identifier: BSD-3-Clause
// vnl_cpoly_roots as upstream's algo test_cpoly_roots.cxx: the roots of 6 t^5 + 5 t^4 + ... + 1
// (monic, imaginary parts zero) make the polynomial vanish to 1e-12; plus a polynomial with
// complex coefficients and known roots, and one with a double root.
#include <algorithm>
#include <complex>
#include <vector>

#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_cpoly_roots.h"
#include "vnl/vnl_real_polynomial.h"

namespace {
using C = std::complex<double>;
/// Whether every expected root is within tol of one found.
bool found_all(const vnl_vector<C>& found, const std::vector<C>& expected, double tol) {
  return std::all_of(expected.begin(), expected.end(), [&](const C& r) {
    return std::any_of(found.begin(), found.end(), [&](const C& s) { return std::abs(s - r) < tol; });
  });
}
}  // namespace

static void test_cpoly_roots() {
  const double coeffs[] = {6, 5, 4, 3, 2, 1};
  const vnl_vector<double> a(coeffs, 6);
  const vnl_vector<double> monic((a / a[0]).extract(a.size() - 1, 1));
  const vnl_cpoly_roots roots(monic, 0.0 * monic);
  TEST("Number of solutions", roots.solns.size(), monic.size());
  const vnl_real_polynomial f(a);
  for (int i = 0; i < f.degree(); ++i) TEST_NEAR("Root residual", std::abs(f.evaluate(roots.solns[i])), 0.0, 1e-12);

  // (t - i)(t + 2)(t - 1 - i), its coefficients from its roots.
  const std::vector<C> expected = {C(0, 1), C(-2, 0), C(1, 1)};
  vnl_vector<C> c(3);
  c[0] = -(expected[0] + expected[1] + expected[2]);
  c[1] = expected[0] * expected[1] + expected[0] * expected[2] + expected[1] * expected[2];
  c[2] = -(expected[0] * expected[1] * expected[2]);
  TEST("complex coefficients: the known roots", found_all(vnl_cpoly_roots(c).solns, expected, 1e-12), true);
  vnl_vector<C> double_root(2);
  double_root[0] = C(-6);  // (t - 3)^2
  double_root[1] = C(9);
  TEST("a double root, to the square root of epsilon", found_all(vnl_cpoly_roots(double_root).solns, {C(3)}, 1e-7),
       true);
}

TESTMAIN(test_cpoly_roots)
