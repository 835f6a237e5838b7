// SPDX-License-Identifier: BSD-3-Clause
// The names, overloads and conversions VXL's own vnl tests use (a VXL user's program), each
// found missing or shaped differently when upstream's tests were compiled against ports/:
// included only through the headers those tests
// include, with upstream's behaviour.
#include <cmath>
#include <complex>
#include <limits>
#include <sstream>
#include <string>
#include <utility>

#include "testlib/testlib_test.h"
#include "vnl/vnl_complexify.h"
#include "vnl/vnl_decnum.h"
#include "vnl/vnl_decnum_traits.h"
#include "vnl/vnl_diag_matrix.h"
#include "vnl/vnl_diag_matrix_fixed.h"
#include "vnl/vnl_finite.h"
#include "vnl/vnl_imag.h"
#include "vnl/vnl_math.h"
#include "vnl/vnl_matrix.h"
#include "vnl/vnl_matrix_fixed.h"
#include "vnl/vnl_na.h"
#include "vnl/vnl_polynomial.h"
#include "vnl/vnl_rational.h"
#include "vnl/vnl_rational_traits.h"
#include "vnl/vnl_real.h"
#include "vnl/vnl_real_polynomial.h"
#include "vnl/vnl_rotation_matrix.h"
#include "vnl/vnl_sym_matrix.h"
#include "vnl/vnl_vector.h"
#include "vnl/vnl_vector_fixed.h"

namespace {

// vnl_vector.h brings vnl_c_vector, as upstream's does (test_alignment uses it through it).
void test_c_vector_through_vector_h() {
  const float x[3] = {1, 2, 3}, y[3] = {4, 5, 6};
  float z[3];
  vnl_c_vector<float>::multiply(x, y, z, 3);
  TEST("vnl_c_vector<float>::multiply via vnl_vector.h", z[0] == 4 && z[1] == 10 && z[2] == 18, true);
}

void test_math_constants() {
  TEST_NEAR("vnl_math::euler", vnl_math::euler, 0.5772156649015329, 1e-16);
  TEST_NEAR("vnl_math::one_over_sqrt2pi", vnl_math::one_over_sqrt2pi, 1 / std::sqrt(2 * vnl_math::pi), 1e-16);
  TEST("vnl_math::eps", vnl_math::eps, std::numeric_limits<double>::epsilon());
  TEST_NEAR("vnl_math::sqrteps", vnl_math::sqrteps, std::sqrt(vnl_math::eps), 1e-20);
  TEST_NEAR("vnl_math::float_sqrteps", vnl_math::float_sqrteps, std::sqrt(vnl_math::float_eps), 1e-9);
}

void test_na_stream_float() {
  std::stringstream ss;
  ss << vnl_na_stream(-1.5f) << ' ' << vnl_na_stream(vnl_na(0.0f));
  TEST("float NA written", ss.str(), std::string("-1.5 NA"));
  float x = 0, y = 0;
  ss >> vnl_na_stream(x) >> vnl_na_stream(y);
  TEST("float NA read back", x == -1.5f && vnl_na_isna(y), true);
}

void test_fixed_views_and_streams() {
  vnl_vector_fixed<double, 4> v(1.0, 2.0, 3.0, 4.0);
  vnl_vector_ref<double> view = v.as_ref();
  view[2] = 7;
  TEST("vnl_vector_fixed::as_ref views the elements", v[2], 7.0);
  TEST("front and back", v.front() == 1 && v.back() == 4, true);
  std::ostringstream vs;
  vs << v;
  TEST("vnl_vector_fixed <<", vs.str(), std::string("1 2 7 4"));
  vnl_vector_fixed<double, 4> read;
  std::istringstream("5 6 7 8") >> read;
  TEST("vnl_vector_fixed >>", read[0] == 5 && read[3] == 8, true);
  // A fixed vector passes where a const vnl_vector& is expected (upstream's implicit view).
  const vnl_vector<double>& as_vector = v;
  TEST("vnl_vector_fixed as const vnl_vector&", as_vector.size() == 4 && as_vector[2] == 7, true);

  vnl_matrix_fixed<double, 2, 2> m;
  m(0, 0) = 1, m(0, 1) = 2, m(1, 0) = 3, m(1, 1) = 4;
  vnl_matrix_ref<double> mview = m.as_ref();
  mview(1, 0) = 5;
  TEST("vnl_matrix_fixed::as_ref views the elements", m(1, 0), 5.0);
  std::ostringstream ms;
  ms << m;
  std::istringstream in(ms.str());
  vnl_matrix_fixed<double, 2, 2> back;
  in >> back;
  TEST("vnl_matrix_fixed << then >>", back == m, true);
  // vnl_matrix minus vnl_matrix_fixed, through the implicit view.
  const vnl_matrix<double> dense(2, 2, 1.0);
  const vnl_matrix<double> difference = dense - m;
  TEST("vnl_matrix - vnl_matrix_fixed", difference(1, 0) == -4 && difference(1, 1) == -3, true);
  const vnl_matrix<double> product = m * dense;
  TEST("vnl_matrix_fixed * vnl_matrix", product(0, 0) == 3 && product(1, 1) == 9, true);
  vnl_matrix_fixed<double, 2, 2> assigned;
  assigned = dense * m;
  TEST("vnl_matrix_fixed = vnl_matrix", assigned(0, 0) == 6 && assigned(1, 1) == 6, true);
  TEST("vnl_matrix_fixed::array_inf_norm", m.array_inf_norm(), 5.0);
  TEST("vnl_matrix_fixed::absolute_value_sum", m.absolute_value_sum(), 12.0);
}

void test_unsigned_negation() {
  const unsigned values[4] = {1, 2, 3, 4};
  const vnl_matrix<unsigned> um(2, 2, 4, values);
  const vnl_matrix<int> minus = -um;
  TEST("-vnl_matrix<unsigned> is a vnl_matrix<int>", minus(0, 0) == -1 && minus(1, 1) == -4, true);
  const vnl_vector<unsigned> uv(3, 4, values);
  const vnl_vector<int> vminus = -uv;
  TEST("-vnl_vector<unsigned> is a vnl_vector<int>", vminus[0] == -1 && vminus[2] == -3, true);
}

void test_sym_matrix_swap() {
  vnl_sym_matrix<int> a(2, 1), b(3, 2);
  swap(a, b);
  TEST("swap(vnl_sym_matrix, vnl_sym_matrix) by ADL", a.rows() == 3 && a(2, 1) == 2 && b.rows() == 2, true);
}

void test_rotation_overloads() {
  const double axis[3] = {0, 0, vnl_math::pi_over_2};
  double R[3][3];
  TEST("vnl_rotation_matrix(double[3], double[3][3])", vnl_rotation_matrix(axis, R), true);
  TEST_NEAR("R(0, 1) of a quarter turn about z", R[0][1], -1.0, 1e-15);
  const vnl_vector<double> v(axis, 3);
  const vnl_matrix<double> M = vnl_rotation_matrix(v);
  TEST("vnl_rotation_matrix(vnl_vector<double>) is 3 x 3", M.rows() == 3 && M.cols() == 3, true);
  TEST_NEAR("the same rotation", M(1, 0), 1.0, 1e-15);
  vnl_matrix<double> out;
  TEST("vnl_rotation_matrix(vnl_vector, vnl_matrix&)", vnl_rotation_matrix(v, out) && out == M, true);
}

void test_polynomials() {
  const vnl_real_polynomial cubic(3u);
  TEST("vnl_real_polynomial(unsigned) has degree 3", cubic.degree(), 3);
  const vnl_real_polynomial f(2.0);
  const vnl_real_polynomial g = f - 0.5;  // the double converts as upstream's implicit constructor
  TEST("vnl_real_polynomial - double", g.evaluate(10.0), 1.5);
  vnl_polynomial<vnl_rational> p(1);
  p[1] = vnl_rational(1, 2);
  p[0] = vnl_rational(1, 3);
  TEST("vnl_polynomial<vnl_rational> evaluates exactly", p.evaluate(vnl_rational(2)), vnl_rational(4, 3));
  std::ostringstream printed;
  printed << p;
  TEST("vnl_polynomial<vnl_rational> prints its coefficients as rationals", printed.str(), std::string(" 1/2 X +1/3"));
  vnl_polynomial<vnl_decnum> q(1);
  q[1] = vnl_decnum(3);
  q[0] = vnl_decnum(-1);
  TEST("vnl_polynomial<vnl_decnum> is instantiated", q.evaluate(vnl_decnum(2)), vnl_decnum(5));
}

void test_finite_zero_divisor() {
  TEST("0 is a zero divisor of Z_2 (division by it is undefined)", vnl_finite_int<2>(0).is_zero_divisor(), true);
}

void test_math_rounding_and_classes() {
  TEST("rnd_halfinttoeven(2.5) == 2", vnl_math::rnd_halfinttoeven(2.5), 2);
  TEST("rnd_halfinttoeven(-1.5f) == -2", vnl_math::rnd_halfinttoeven(-1.5f), -2);
  TEST("rnd_halfinttoeven(3.5) == 4", vnl_math::rnd_halfinttoeven(3.5), 4);
  TEST("rnd_halfintup(-2.5) == -2", vnl_math::rnd_halfintup(-2.5), -2);
  TEST("rnd_halfintup(2.5f) == 3", vnl_math::rnd_halfintup(2.5f), 3);
  TEST("isnormal(1.0)", vnl_math::isnormal(1.0), true);
  TEST("isnormal(denormal float)", vnl_math::isnormal(std::numeric_limits<float>::denorm_min()), false);
  TEST("isnormal(int 0)", vnl_math::isnormal(0), false);
  TEST("vnl_huge_val(double) is infinite", std::isinf(vnl_huge_val(double())), true);
  TEST("vnl_huge_val(int) is INT_MAX", vnl_huge_val(int()), std::numeric_limits<int>::max());
  const double tiny = 2 * std::numeric_limits<double>::epsilon();
  const double wrapped = vnl_math::angle_0_to_2pi(-tiny);
  TEST("angle_0_to_2pi(-tiny) is just below 2 pi", wrapped < vnl_math::twopi && wrapped > 6.283, true);
  TEST("angle_minuspi_to_pi(-pi) stays -pi", vnl_math::angle_minuspi_to_pi(-vnl_math::pi), -vnl_math::pi);
  TEST("angle_minuspi_to_pi(-tiny) stays -tiny", vnl_math::angle_minuspi_to_pi(-tiny), -tiny);
}

void test_rational_as_upstream() {
  const vnl_rational seven_halves(7, 2);
  TEST("integer == rational", 5L == vnl_rational(5) && -7 == vnl_rational(-7), true);
  TEST("integer <= / >= rational", 3L <= seven_halves && 4 >= seven_halves && !(4 < seven_halves), true);
  TEST("free truncate / round / floor / ceil",
       truncate(seven_halves) == 3 && round(-seven_halves) == -4 && floor(-seven_halves) == -4 &&
           ceil(seven_halves) == 4,
       true);
  TEST("0.42857142857 converts to 3/7 (upstream's cut)", vnl_rational(0.42857142857), vnl_rational(3, 7));
  TEST("-1.23456 converts to -123456/100000", vnl_rational(-1.23456), vnl_rational(-123456, 100000));
  vnl_vector<vnl_rational> v(2);
  v[0] = vnl_rational(3, 5);
  v[1] = vnl_rational(4, 5);
  TEST("vnl_vector<vnl_rational>::two_norm (via double)", v.two_norm(), vnl_rational(1));
  vnl_matrix<vnl_rational> m(1, 2);
  m.set_row(0, v);
  TEST("vnl_matrix<vnl_rational> is instantiated", m(0, 1), vnl_rational(4, 5));
}

void test_complexify_diag_and_sym() {
  const vnl_diag_matrix<double> re(2, 1.5), im(2, -2.0);
  const vnl_diag_matrix<std::complex<double>> c = vnl_complexify(re, im);
  TEST("vnl_complexify(diag, diag)", c(1, 1), std::complex<double>(1.5, -2.0));
  TEST("vnl_real / vnl_imag of a complex diag", vnl_real(c)(0, 0) == 1.5 && vnl_imag(c)(1, 1) == -2.0, true);
  const vnl_diag_matrix_fixed<float, 2> fixed_re(3.0f);
  TEST("vnl_complexify(diag fixed)", vnl_complexify(fixed_re)(1, 1), std::complex<float>(3.0f, 0.0f));
  TEST("vnl_imag(diag fixed)", vnl_imag(vnl_complexify(fixed_re, fixed_re))(0, 0), 3.0f);
  const vnl_sym_matrix<double> sym_re(2, 4.0), sym_im(2, 5.0);
  const vnl_sym_matrix<std::complex<double>> sym = vnl_complexify(sym_re, sym_im);
  TEST("vnl_complexify(sym, sym)", sym(0, 1), std::complex<double>(4.0, 5.0));
  TEST("vnl_real(complex sym)", vnl_real(sym)(1, 0), 4.0);
  const vnl_vector_fixed<double, 2> vr(1.0, 2.0), vi(3.0, 4.0);
  TEST("vnl_complexify(fixed, fixed)", vnl_complexify(vr, vi)[1], std::complex<double>(2.0, 4.0));
}

void test_vxl_user_api() {
  test_c_vector_through_vector_h();
  test_math_constants();
  test_na_stream_float();
  test_fixed_views_and_streams();
  test_unsigned_negation();
  test_sym_matrix_swap();
  test_rotation_overloads();
  test_polynomials();
  test_finite_zero_divisor();
  test_math_rounding_and_classes();
  test_rational_as_upstream();
  test_complexify_diag_and_sym();
}

}  // namespace

TESTMAIN(test_vxl_user_api)
