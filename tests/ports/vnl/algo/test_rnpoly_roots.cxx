// SPDX-License-Identifier: BSD-3-Clause
// vnl_rnpoly_solve as upstream's algo test_rnpoly_roots.cxx: two unit circles meet in two real
// points (the other two Bezout solutions are at infinity), two ellipses in four real points or
// in four complex ones, and a badly scaled quartic (and its rescaled form) has four roots; here
// the quartic's roots are also checked against their closed form.
#include <algorithm>
#include <cmath>
#include <vector>

#include "testlib/testlib_test.h"
#include "vnl/algo/vnl_rnpoly_solve.h"
#include "vnl/vnl_real_npolynomial.h"

namespace {

void unit_circles_intersect() {
  double f1_data[] = {1.0, 1.0, -1.0};
  const vnl_vector<double> f1(f1_data, 3);
  vnl_matrix<unsigned int> p1(3, 2, 0);
  p1(0, 0) = 2;
  p1(1, 1) = 2;
  vnl_real_npolynomial poly1(f1, p1);  // X^2 + Y^2 - 1
  double f2_data[] = {1.0, -1.0};
  vnl_matrix<unsigned int> p2(2, 2, 0);
  p2(0, 0) = 1;
  const vnl_real_npolynomial monom1(vnl_vector<double>(f2_data, 2), p2);  // X - 1
  vnl_matrix<unsigned int> p3(1, 2, 0);
  p3(0, 1) = 2;
  vnl_real_npolynomial poly2 = monom1 * monom1 - 1 + vnl_real_npolynomial(vnl_vector<double>(1, 1.0), p3);
  std::vector<vnl_real_npolynomial*> l = {&poly1, &poly2};
  vnl_rnpoly_solve solver(l);
  const std::vector<vnl_vector<double>*> r = solver.realroots();
  TEST("There should be two real roots", r.size(), 2u);
  TEST("Dimensions should match", r.empty() ? 0u : r[0]->size(), 2u);
  for (const vnl_vector<double>* root : r) {
    TEST_NEAR("x==0.5", (*root)[0], 0.5, 1e-9);
    TEST_NEAR("y==sqrt(0.75)", (*root)[1] * (*root)[1], 0.75, 1e-9);
  }
  TEST("and no more finite imaginary roots", solver.real().size(), 2u);
  TEST("and equally many imaginary parts", solver.imag().size(), 2u);
}

void ellipses_intersect() {
  double f1_data[] = {1.0, 2.0, -1.0};
  vnl_vector<double> f1(f1_data, 3);
  vnl_matrix<unsigned int> p1(3, 2, 0);
  p1(0, 0) = 2;
  p1(1, 1) = 2;
  vnl_real_npolynomial poly3(f1, p1);  // X^2 + 2 Y^2 - 1
  f1(0) = 2;
  f1(1) = 1;
  vnl_real_npolynomial poly4(f1, p1);  // 2 X^2 + Y^2 - 1
  std::vector<vnl_real_npolynomial*> l = {&poly3, &poly4};
  vnl_rnpoly_solve solver(l);
  const std::vector<vnl_vector<double>*> r = solver.realroots();
  TEST("There should be four real roots", r.size(), 4u);
  for (const vnl_vector<double>* root : r) {
    TEST_NEAR("x==sqrt(1/3)", 3 * (*root)[0] * (*root)[0], 1.0, 1e-9);
    TEST_NEAR("y==sqrt(1/3)", 3 * (*root)[1] * (*root)[1], 1.0, 1e-9);
  }
  TEST("and no more imaginary roots", solver.real().size(), 4u);
  f1(0) = 2;
  f1(1) = 3;
  vnl_real_npolynomial poly5(f1, p1);  // 2 X^2 + 3 Y^2 - 1
  std::vector<vnl_real_npolynomial*> l3 = {&poly3, &poly5};
  vnl_rnpoly_solve solver3(l3);
  TEST("There should be no real roots", solver3.realroots().size(), 0u);
  TEST("and four imaginary roots", solver3.real().size(), 4u);
  TEST("and equally many imaginary parts", solver3.imag().size(), 4u);
  // X^2 + 2 Y^2 = 1 and 2 X^2 + 3 Y^2 = 1: X^2 = -1, Y^2 = 1.
  bool all_match = solver3.real().size() == 4;
  for (size_t k = 0; k < solver3.real().size(); ++k) {
    const std::complex<double> x((*solver3.real()[k])[0], (*solver3.imag()[k])[0]);
    const std::complex<double> y((*solver3.real()[k])[1], (*solver3.imag()[k])[1]);
    all_match = all_match && std::abs(x * x + 1.0) < 1e-9 && std::abs(y * y - 1.0) < 1e-9;
  }
  TEST("the complex roots have X^2 = -1 and Y^2 = 1", all_match, true);
}

/// The roots of the quartic 1, 0, c2, c3, c4 (x^4 + c2 x^2 + c3 x + c4), sorted.
std::vector<double> quartic_roots(double c2, double c3, double c4, double scale) {
  vnl_vector<double> coeffs(5);
  coeffs[0] = 1;
  coeffs[1] = 0;
  coeffs[2] = c2;
  coeffs[3] = c3;
  coeffs[4] = c4;
  double m = 1;
  for (int i = 0; i <= 4; ++i) coeffs[i] /= m, m *= scale;
  vnl_matrix<unsigned int> pol(5, 1, 0);
  for (unsigned i = 0; i < 5; ++i) pol(i, 0) = 4 - i;
  vnl_real_npolynomial monom1(coeffs, pol);
  vnl_rnpoly_solve solver({&monom1});
  TEST("Real part of roots has size 4", solver.real().size(), 4u);
  TEST("Imag part of roots has size 4", solver.imag().size(), 4u);
  std::vector<double> roots;
  for (const vnl_vector<double>* r : solver.realroots(1e-6)) roots.push_back((*r)[0] * scale);
  std::sort(roots.begin(), roots.end());
  return roots;
}

void fourth_degree() {
  const std::vector<double> roots = quartic_roots(-40614629.07703703, 0.0000678, 412195996534712.2688, 1.0);
  TEST("the quartic's four roots are real", roots.size(), 4u);
  // x^2 = (-c2 +- sqrt(c2^2 - 4 c4)) / 2 (c3 is negligible): x = +-4457.6 and +-4554.6, to the
  // two decimals upstream prints (its printed list has 4454.60 and 4557.60 for the positive
  // roots, which this nearly even quartic cannot have).
  const double expected[4] = {-4554.6, -4457.6, 4457.6, 4554.6};
  for (size_t k = 0; k < roots.size() && k < 4; ++k) TEST_NEAR("a root of the quartic", roots[k], expected[k], 0.01);
  const double c4 = 4121959965347122688.0;
  const std::vector<double> scaled = quartic_roots(-4061462907.703703, 0.0678, c4, std::sqrt(std::sqrt(c4)));
  TEST("the rescaled quartic's four roots are real", scaled.size(), 4u);
}

}  // namespace

static void test_rnpoly_roots() {
  unit_circles_intersect();
  ellipses_intersect();
  fourth_degree();
}

TESTMAIN(test_rnpoly_roots)
