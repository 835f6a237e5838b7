// SPDX-License-Identifier: BSD-3-Clause
// vnl_matrix_fixed as upstream's test_matrix_fixed.cxx: construction, element access, the
// typedefs, arithmetic, products with fixed vectors and matrices, transpose, diagonal and
// the conversion to vnl_matrix.
#include <string>

#include "testlib/testlib_test.h"
#include "vnl/vnl_double_2x2.h"
#include "vnl/vnl_double_3x3.h"
#include "vnl/vnl_float_3x4.h"
#include "vnl/vnl_int_2x2.h"
#include "vnl/vnl_matrix_fixed.h"
#include "vnl_test_types.h"

namespace {

template <class T>
struct CheckMatrixFixed {
  static void run(const std::string& type) {
    const std::string in = " (" + type + ")";
    const T d[] = {T(1), T(2), T(3), T(4), T(5), T(6)};
    vnl_matrix_fixed<T, 2, 3> m(d);
    TEST("row-major construction" + in, m(1, 0) == T(4) && m[0][2] == T(3), true);
    TEST("size" + in, m.rows() == 2 && m.cols() == 3 && m.size() == 6, true);
    m.put(0, 0, T(-1));
    TEST("put and get" + in, m.get(0, 0) == T(-1), true);
    const vnl_matrix_fixed<T, 2, 3> twice = m * T(2);
    TEST("scalar product" + in, twice(1, 2) == T(12), true);
    TEST("sum and difference" + in, (twice - m)(1, 1) == T(5) && (twice + m)(0, 1) == T(6), true);
    vnl_matrix_fixed<T, 2, 3> h(twice);
    h /= T(2);
    TEST("/= by a scalar" + in, h == m, true);
    const vnl_matrix_fixed<T, 3, 2> t = m.transpose();
    TEST("transpose" + in, t(2, 1) == T(6), true);
    const vnl_matrix_fixed<T, 2, 2> p = m * t;
    TEST("fixed product m m^T" + in, p(1, 1) == T(77) && p(0, 1) == p(1, 0), true);
    const vnl_vector_fixed<T, 3> x(T(1), T(0), T(-1));
    TEST("matrix times vector" + in, (m * x)[1] == T(-2), true);
    vnl_matrix_fixed<T, 3, 3> i3;
    i3.set_identity();
    TEST("set_identity / is_identity" + in, i3.is_identity(), true);
    i3.set_diagonal(vnl_vector<T>(3, T(2)));
    TEST("set_diagonal" + in, i3.get_diagonal()[2] == T(2) && i3(0, 1) == T(0), true);
    TEST("operator_inf_norm" + in, m.operator_inf_norm() == T(15), true);
    TEST("as_matrix" + in, m.as_matrix()(1, 2) == T(6), true);
    vnl_matrix_fixed<T, 3, 3> u(T(0));
    u.update(m.as_matrix(), 1, 0);
    TEST("update" + in, u(2, 2) == T(6) && u(0, 0) == T(0), true);
    TEST("extract" + in, m.extract(2, 2, 0, 1)(1, 1) == T(6), true);
  }
};

void test_matrix_fixed() {
  for_each_test_scalar<CheckMatrixFixed>();
  TEST("vnl_double_3x3 is a 3x3 of double", vnl_double_3x3().size() == 9u, true);
  TEST("vnl_float_3x4 is 3 x 4", vnl_float_3x4::rows() == 3 && vnl_float_3x4::cols() == 4, true);
  vnl_int_2x2 k;
  k.set_identity();
  TEST("vnl_int_2x2 product", (k * k).is_identity(), true);
  vnl_double_2x2 z(0.5);
  TEST("vnl_double_2x2 fill constructor", z(1, 0), 0.5);
}

}  // namespace

TESTMAIN(test_matrix_fixed)
