// SPDX-License-Identifier: BSD-3-Clause
// The vnl_matrix / vnl_vector interface that upstream's vnl_matrix_fixed and vnl_vector_fixed
// also have, and the conversions between fixed and dense containers, each found missing when
// upstream's test_container_interface, test_matrix_fixed, test_vector, test_quaternion,
// test_diag_matrix, test_diag_matrix_fixed and test_matrix_fixed_ref were compiled against
// ports/.
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <utility>

#include "testlib/testlib_test.h"
#include "vnl/vnl_c_vector.h"
#include "vnl/vnl_diag_matrix_fixed.h"
#include "vnl/vnl_math.h"
#include "vnl/vnl_matrix.h"
#include "vnl/vnl_matrix_fixed.h"
#include "vnl/vnl_matrix_fixed_ref.h"
#include "vnl/vnl_quaternion.h"
#include "vnl/vnl_vector.h"
#include "vnl/vnl_vector_fixed.h"

namespace {

using int22 = vnl_matrix_fixed<int, 2, 2>;

int twice(int x) { return 2 * x; }
int row_sum(const vnl_vector_fixed<int, 2>& v) { return v[0] + v[1]; }

void test_matrix_fixed_shape_and_assignment() {
  int22 m(2, 2);  // upstream's shape-checked constructor
  TEST("vnl_matrix_fixed(2, 2) is 2x2 zeros", m.rows() == 2 && m.cols() == 2 && m.is_zero(), true);
  m = 5;
  TEST("vnl_matrix_fixed = scalar fills", m(0, 0) == 5 && m(1, 1) == 5 && m.max_value() == 5, true);
  const vnl_matrix<double> dense(3, 3, 2.0);
  const vnl_matrix_fixed<double, 3, 3> fixed = dense;  // implicit, as upstream
  TEST("vnl_matrix converts implicitly to vnl_matrix_fixed", fixed(2, 1), 2.0);
  TEST("fixed - dense gives a dense matrix", (fixed - dense).is_zero(), true);
  TEST("fixed == dense", fixed == dense, true);
  m.set(0, 1, 7).set(1, 0, -1);
  TEST("set(r, c, v) chains", m(0, 1) == 7 && m(1, 0) == -1, true);
  TEST("empty() of a 2x2", m.empty(), false);
}

void test_matrix_fixed_members() {
  const int values[4] = {1, 2, 3, 4};
  int22 m(values);
  TEST("begin/end walk the 4 elements", m.end() - m.begin(), 4);
  TEST("min_value / max_value", m.min_value() == 1 && m.max_value() == 4, true);
  TEST("arg_min / arg_max", m.arg_min() == 0 && m.arg_max() == 3, true);
  TEST("mean (integer, as upstream)", m.mean(), 2);
  const vnl_vector_fixed<int, 4> rows = m.flatten_row_major();
  const vnl_vector_fixed<int, 4> cols = m.flatten_column_major();
  TEST("flatten_row_major", rows[1] == 2 && rows[2] == 3, true);
  TEST("flatten_column_major", cols[1] == 3 && cols[2] == 2, true);
  int22 t(m);
  t.inplace_transpose();
  TEST("inplace_transpose", t == m.transpose(), true);
  int22 ud(m), lr(m);
  ud.flipud();
  lr.fliplr();
  TEST("flipud", ud(0, 0) == 3 && ud(1, 1) == 2, true);
  TEST("fliplr", lr(0, 0) == 2 && lr(1, 1) == 3, true);
  const unsigned order[2] = {1, 0};
  TEST("get_rows in the given order", ud.is_equal(m.get_rows(vnl_vector<unsigned>(order, 2)), 0.0), true);
  TEST("apply", m.apply(twice)(1, 1), 8);
  const vnl_vector_fixed<int, 2> sums = m.apply_rowwise(row_sum);
  TEST("apply_rowwise", sums[0] == 3 && sums[1] == 7, true);
  int22 a(m), b(t);
  a.swap(b);
  TEST("swap", a == t && b == m, true);
  std::swap(a, b);
  TEST("std::swap", a == m && b == t, true);
  int22 p(m);
  p *= t;  // right-multiply in place
  TEST("*= by a square fixed matrix", p == m * t, true);
  int22 s(m);
  s.scale_row(0, 10).scale_column(1, 2);
  TEST("scale_row / scale_column", s(0, 0) == 10 && s(0, 1) == 40 && s(1, 1) == 8, true);
  int22 c(m);
  c.set_column(0, 9).set_row(1, vnl_vector<int>(2, 6));
  TEST("set_column(value), set_row(vnl_vector)", c(0, 0) == 9 && c(1, 0) == 6 && c(1, 1) == 6, true);
  vnl_matrix<int> block(1, 2);
  m.extract(block, 1, 0);
  TEST("extract into an existing matrix", block(0, 0) == 3 && block(0, 1) == 4, true);
  const vnl_matrix_fixed<unsigned, 2, 2> u(vnl_matrix_fixed<unsigned, 2, 2>(3u));
  const vnl_matrix_fixed<int, 2, 2> negated = -u;  // the signed type, as upstream
  TEST("-unsigned fixed matrix is signed", negated(1, 0), -3);
}

void test_matrix_fixed_is_equal_and_nan() {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const vnl_matrix_fixed<float, 2, 2> a(nan), zero(0.0f);
  TEST("NaN matrix is_equal zero is false", a.is_equal(zero, 0.0), false);
  TEST("has_nans", a.has_nans() && !a.is_finite(), true);
  const vnl_vector<float> v(2, nan);
  TEST("NaN vector is_equal itself is false", v.is_equal(vnl_vector<float>(2, nan), 1.0), false);
}

void test_vector_fixed_members() {
  const vnl_vector_fixed<double, 2> a(0.9, 0.9), b(1.1, 1.1);
  TEST("is_equal with zero tolerance", a.is_equal(b, 0.0), false);
  TEST("is_equal with tolerance 0.3", a.is_equal(b, 0.3), true);
  const vnl_vector_fixed<unsigned, 3> u(1u, 2u, 3u);
  const vnl_vector_fixed<int, 3> negated = -u;
  TEST("-unsigned fixed vector is signed", negated[2], -3);
  vnl_vector_fixed<int, 3> f(1, 2, 3);
  f.flip();
  TEST("flip", f[0] == 3 && f[2] == 1, true);
  TEST("min_value / arg_max", f.min_value() == 1 && f.arg_max() == 0, true);
  const vnl_vector<int> dense(3, 1);
  const vnl_vector_fixed<int, 3> converted = dense;  // implicit, as upstream
  TEST("vnl_vector converts implicitly to vnl_vector_fixed", converted[1], 1);
  TEST("vnl_vector_ssd of fixed vectors", vnl_vector_ssd(f, converted), 5);
  vnl_vector<int> v(3, 0);
  v[0] = 4;
  v[2] = 6;
  TEST("vnl_vector front / back", v.front() == 4 && v.back() == 6, true);
}

void test_quaternion_from_fixed() {
  const vnl_vector_fixed<double, 4> xyzr(0.0, 0.0, 0.0, 1.0);
  const vnl_quaternion<double> q = xyzr;  // implicit, as upstream
  TEST("vnl_vector_fixed<double, 4> converts to vnl_quaternion", q.real(), 1.0);
  TEST("vnl_vector_ssd of quaternions", vnl_vector_ssd(q, q), 0.0);
}

void test_angles_and_std() {
  vnl_vector<float> x(3, 0.0f), y(3, 0.0f), z(3, 0.0f);
  x[0] = 1;
  y[1] = 1;
  z[0] = -0.5f;
  z[2] = 0.5f;
  TEST_NEAR("angle of orthogonal float vectors is pi/2 in double", angle(x, y), vnl_math::pi_over_2, 1e-15);
  TEST_NEAR("angle keeps the sign of the cosine (135 degrees)", angle(x, z), 0.75 * vnl_math::pi, 1e-6);
  TEST_NEAR("cos_angle", cos_angle(x, z), -std::sqrt(0.5f), 1e-6);
  const float three[3] = {1, 2, 3};
  TEST_NEAR("vnl_c_vector::std is the sample deviation (n - 1)", vnl_c_vector<float>::std(three, 3), 1.0, 1e-6);
  TEST("vnl_cross_2d takes the first two elements of longer vectors", vnl_cross_2d(x, y), 1.0f);
}

void test_diag_matrix_fixed_with_fixed() {
  vnl_diag_matrix_fixed<double, 2> d;
  d(0, 0) = 2;  // element assignment, as upstream
  d(1, 1) = 3;
  const vnl_matrix_fixed<double, 2, 2> ones(1.0);
  const vnl_matrix_fixed<double, 2, 2> sum = d + ones, diff = ones - d, rdiff = d - ones;
  TEST("diag + fixed", sum(0, 0) == 3 && sum(1, 1) == 4 && sum(0, 1) == 1, true);
  TEST("fixed - diag", diff(0, 0) == -1 && diff(1, 0) == 1, true);
  TEST("diag - fixed", rdiff(1, 1) == 2 && rdiff(0, 1) == -1, true);
  const vnl_vector_fixed<double, 2> v(1.0, 1.0);
  const vnl_vector_fixed<double, 2> vd = v * d;
  TEST("vector * diag", vd[0] == 2 && vd[1] == 3, true);
  std::ostringstream out;
  out << d;
  TEST("<< prints diag([ d0 d1 ])", out.str(), std::string("diag([ 2 3 ])"));
}

void test_matrix_fixed_ref_arithmetic() {
  vnl_matrix_fixed<double, 2, 2> a(1.0), b(2.0);
  const vnl_matrix_fixed_ref<double, 2, 2> ra(a);
  const vnl_matrix_fixed_ref_const<double, 2, 2> rb(b);
  TEST("a view's begin/end are the viewed block", ra.begin() == a.data_block() && rb.end() - rb.begin() == 4, true);
  TEST("view + view", (ra + rb)(1, 0), 3.0);
  TEST("view - view", (ra - rb)(0, 1), -1.0);
}

void test_vxl_fixed_api() {
  test_matrix_fixed_shape_and_assignment();
  test_matrix_fixed_members();
  test_matrix_fixed_is_equal_and_nan();
  test_vector_fixed_members();
  test_quaternion_from_fixed();
  test_angles_and_std();
  test_diag_matrix_fixed_with_fixed();
  test_matrix_fixed_ref_arithmetic();
}

}  // namespace

TESTMAIN(test_vxl_fixed_api)
