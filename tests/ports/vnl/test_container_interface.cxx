// SPDX-License-Identifier: BSD-3-Clause
// The container interface vnl_matrix and vnl_matrix_fixed share, as upstream's
// test_container_interface.cxx checks it: sizes, row and column selection, swap, emptiness,
// zero and equality tests, finiteness, and iteration.
#include <cmath>
#include <numeric>
#include <string>
#include <utility>

#include "testlib/testlib_test.h"
#include "vnl/vnl_matrix.h"
#include "vnl/vnl_matrix_fixed.h"
#include "vnl_test_types.h"

namespace {

template <class T>
struct CheckContainer {
  static void run(const std::string& type) {
    const std::string in = " (" + type + ")";
    vnl_matrix<T> m{{T(1), T(2)}, {T(3), T(4)}};
    TEST("size() of 2x2 container" + in, m.size(), 4u);
    TEST("rows() and cols() of 2x2 container" + in, m.rows() == 2 && m.cols() == 2 && m.columns() == 2, true);
    TEST("get_rows" + in, m.get_rows(vnl_vector<unsigned>{1u})(0, 1) == T(4), true);
    TEST("get_columns" + in, m.get_columns(vnl_vector<unsigned>{0u})(1, 0) == T(3), true);
    vnl_matrix<T> other(3, 1, T(7));
    m.swap(other);
    TEST("swap left-right" + in, m.rows() == 3 && other.rows() == 2 && other(1, 1) == T(4), true);
    std::swap(m, other);
    TEST("std::swap right-left" + in, m.rows() == 2 && m(0, 0) == T(1), true);
    TEST("empty() on 2x2 container" + in, m.empty(), false);
    TEST("empty() on a default container" + in, vnl_matrix<T>().empty(), true);
    const vnl_matrix<T> zero(2, 2, T(0));
    TEST("is_zero() on zero-filled container" + in, zero.is_zero(), true);
    TEST("is_zero(tol) on zero-filled container" + in, zero.is_zero(0.0), true);
    TEST("is_equal (true)" + in, m.is_equal(m, 0.0), true);
    TEST("is_equal (false)" + in, m.is_equal(zero, 0.5), false);
    TEST("is_finite() on finite-valued container" + in, m.is_finite(), true);
    TEST("iteration visits every element" + in, std::accumulate(m.begin(), m.end(), T(0)) == T(10), true);
    vnl_matrix_fixed<T, 2, 2> f(m);
    TEST("vnl_matrix_fixed: same sizes and values" + in, f.size() == 4 && f.rows() == 2 && f(1, 0) == T(3), true);
    const vnl_matrix_fixed<T, 2, 2> fixed_zero(T(0));
    TEST("vnl_matrix_fixed: is_zero" + in, fixed_zero.is_zero(), true);
  }
};

void test_container_interface() {
  for_each_test_scalar<CheckContainer>();
  vnl_matrix<double> nan_matrix(2, 2, 1.0);
  nan_matrix(1, 0) = std::nan("");
  TEST("is_finite() with a NaN", nan_matrix.is_finite(), false);
  TEST("has_nans() with a NaN", nan_matrix.has_nans(), true);
}

}  // namespace

TESTMAIN(test_container_interface)
